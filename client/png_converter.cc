#include "client/png_converter.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <vector>

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"

namespace swarmplan::client {
namespace {

// Runs a program found on PATH without a shell; returns its exit status (127 when it cannot be
// started). Its stdout goes to *output when given, else (like stderr) to /dev/null.
int RunProgram(const std::vector<std::string>& argv, std::string* output) {
  int pipe_fds[2] = {-1, -1};
  if (output != nullptr && pipe(pipe_fds) != 0) return 127;
  const pid_t pid = fork();
  if (pid < 0) return 127;
  if (pid == 0) {
    const int null_fd = open("/dev/null", O_RDWR);
    dup2(null_fd, STDIN_FILENO);
    dup2(output != nullptr ? pipe_fds[1] : null_fd, STDOUT_FILENO);
    dup2(null_fd, STDERR_FILENO);
    std::vector<char*> args;
    for (const std::string& arg : argv) args.push_back(const_cast<char*>(arg.c_str()));
    args.push_back(nullptr);
    execvp(args[0], args.data());
    _exit(127);
  }
  if (output != nullptr) {
    close(pipe_fds[1]);
    char buffer[4096];
    ssize_t n;
    while ((n = read(pipe_fds[0], buffer, sizeof(buffer))) > 0) output->append(buffer, n);
    close(pipe_fds[0]);
  }
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return 127;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 127;
}

bool IsImageMagick(const std::string& program) {
  std::string version;
  return RunProgram({program, "-version"}, &version) == 0 &&
         absl::StrContains(version, "ImageMagick");
}

bool Exists(const std::string& program) {
  std::string ignored;
  return RunProgram({program, "--version"}, &ignored) != 127;
}

bool NonEmptyFile(const std::string& path) {
  std::error_code error;
  return std::filesystem::is_regular_file(path, error) &&
         std::filesystem::file_size(path, error) > 0;
}

}  // namespace

absl::StatusOr<std::string> ConvertSvgToPng(const std::string& svg_file,
                                            const std::string& png_file) {
  struct Converter {
    std::string name;
    bool (*available)(const std::string&);
    std::vector<std::string> argv;
  };
  const std::vector<Converter> converters = {
      {"rsvg-convert", Exists, {"rsvg-convert", "-o", png_file, svg_file}},
      {"inkscape",
       Exists,
       {"inkscape", svg_file, "--export-type=png", "--export-filename=" + png_file}},
      {"magick", IsImageMagick, {"magick", svg_file, png_file}},
      {"convert", IsImageMagick, {"convert", svg_file, png_file}},
  };
  for (const Converter& converter : converters) {
    if (!converter.available(converter.name)) continue;
    std::filesystem::remove(png_file);
    const int status = RunProgram(converter.argv, nullptr);
    if (status == 0 && NonEmptyFile(png_file)) return converter.name;
    return absl::InternalError(absl::StrCat(converter.name, " failed (exit status ", status,
                                            ") converting ", svg_file, " to ", png_file));
  }
  return absl::FailedPreconditionError(absl::StrCat(
      "no SVG-to-PNG converter found (rsvg-convert, inkscape or ImageMagick); the SVG is at ",
      svg_file, ". Install one, e.g.: apt-get install librsvg2-bin"));
}

}  // namespace swarmplan::client
