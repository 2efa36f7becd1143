// swarmplan render: SVG (and PNG where a converter exists) of a map with paths and convergence.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>

#include "absl/strings/ascii.h"
#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "client/commands.h"
#include "client/exit_codes.h"
#include "client/map_files.h"
#include "client/map_reference.h"
#include "client/map_render.h"
#include "client/output.h"
#include "client/path_files.h"
#include "client/png_converter.h"
#include "core/map/io/map_io.h"
#include "nlohmann/json.hpp"
#include "swarmplan/v1/jobs.grpc.pb.h"
#include "swarmplan/v1/maps.grpc.pb.h"

namespace swarmplan::client {
namespace {

struct RenderCommandOptions {
  std::string map_id;
  std::string map_file;
  std::string map_format;
  std::vector<std::string> jobs;
  std::vector<std::string> path_files;
  std::string output = "render.svg";
  std::string convergence = "inset";
  bool png = false;
  bool raw = false;
  double width = 900;
  std::string y_axis = "auto";
  std::string title;
};

// Text-file grids put their first line at y = 0: draw them y-down so they look like the file.
bool YUp(const std::string& y_axis, const std::string& format) {
  if (y_axis == "up") return true;
  if (y_axis == "down") return false;
  return !(format == "ascii" || format == "movingai");
}

absl::Status WriteText(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  out.close();
  if (!out) return absl::PermissionDeniedError(absl::StrCat(path, ": cannot write"));
  return absl::OkStatus();
}

std::string WithSuffix(const std::string& file, const std::string& suffix_and_extension) {
  std::filesystem::path path(file);
  return (path.parent_path() / (path.stem().string() + suffix_and_extension)).string();
}

int Run(const GlobalOptions& global, const RenderCommandOptions& options) {
  if (options.map_id.empty() && options.map_file.empty() && options.jobs.empty()) {
    return ReportError(global, kExitUsage,
                       "render: name the map with --map ID or --map-file FILE, or give --job ID");
  }
  // Outputs: out.svg (+ out.png), or out.png from out.svg.
  const bool png_output = absl::EndsWithIgnoreCase(options.output, ".png");
  const std::string svg_file = png_output ? WithSuffix(options.output, ".svg") : options.output;
  const std::string png_file =
      png_output ? options.output : (options.png ? WithSuffix(options.output, ".png") : "");

  std::vector<RenderedPath> paths;
  std::vector<ConvergenceCurve> curves;
  for (const std::string& file : options.path_files) {
    absl::StatusOr<PathFile> path = ReadPathFile(file);
    if (!path.ok()) return ReportLocalError(global, path.status());
    RenderedPath rendered{path->label, {}};
    for (const v1::Point& p : path->points) rendered.points.emplace_back(p.x(), p.y(), p.z());
    paths.push_back(std::move(rendered));
  }

  std::optional<Connection> connection;
  auto connect = [&]() -> int {
    if (connection) return kExitOk;
    absl::StatusOr<Connection> opened = Connection::Open(global);
    if (!opened.ok()) return ReportLocalError(global, opened.status());
    connection = *std::move(opened);
    return kExitOk;
  };
  std::string map_id;
  if (!options.map_id.empty()) {
    absl::StatusOr<v1::GetMapRequest> reference = ParseMapReference("--map", options.map_id);
    if (!reference.ok()) return ReportLocalError(global, reference.status());
    if (int code = connect(); code != kExitOk) return code;
    grpc::Status status = ResolveMapId(*connection, *reference, &map_id);
    if (!status.ok()) {
      return ReportRpcError(global, absl::StrCat("render: map ", options.map_id), status);
    }
  }
  for (const std::string& id : options.jobs) {
    if (int code = connect(); code != kExitOk) return code;
    auto stub = v1::JobService::NewStub(connection->channel());
    v1::GetJobRequest request;
    request.set_id(id);
    v1::Job job;
    grpc::Status status = stub->GetJob(connection->UnaryContext().get(), request, &job);
    if (!status.ok()) return ReportRpcError(global, absl::StrCat("render: job ", id), status);
    if (map_id.empty()) map_id = job.request().map_id();
    if (job.request().map_id() != map_id && options.map_file.empty()) {
      std::cerr << "swarmplan: warning: job " << id << " planned on map " << job.request().map_id()
                << ", drawn on map " << map_id << "\n";
    }
    const v1::PlanResult& result = job.result();
    const auto& points =
        options.raw || result.smoothed_path().empty() ? result.raw_path() : result.smoothed_path();
    const std::string label = absl::StrCat(
        id, " ", result.algorithm().empty() ? job.request().algorithm() : result.algorithm());
    if (points.empty()) {
      std::cerr << "swarmplan: warning: job " << id << " (" << JobStateName(job.state())
                << ") has no path to draw\n";
    } else {
      RenderedPath rendered{label, {}};
      for (const v1::Point& p : points) rendered.points.emplace_back(p.x(), p.y(), p.z());
      paths.push_back(std::move(rendered));
    }
    for (int i = 0; i < result.alternatives_size(); ++i) {
      RenderedPath rendered{absl::StrCat(label, " alternative ", i + 1), {}};
      for (const v1::Point& p : result.alternatives(i).path()) {
        rendered.points.emplace_back(p.x(), p.y(), p.z());
      }
      paths.push_back(std::move(rendered));
    }
    ConvergenceCurve curve{label, {}};
    for (const v1::IterationStats& stats : result.convergence()) {
      curve.best.push_back(
          {static_cast<double>(stats.iteration()), stats.best_fitness(), stats.feasible()});
    }
    if (!curve.best.empty()) curves.push_back(std::move(curve));
  }

  // The map: from the local file, else its content from the server.
  absl::StatusOr<Map> map = absl::UnknownError("no map");
  std::string format;
  std::string map_name;
  if (!options.map_file.empty()) {
    format = options.map_format.empty() ? GuessMapFormat(options.map_file) : options.map_format;
    map = LoadMapFile(options.map_file, format);
    if (!map.ok()) return ReportLocalError(global, map.status());
    map_name = std::filesystem::path(options.map_file).filename().string();
  } else {
    if (int code = connect(); code != kExitOk) return code;
    auto stub = v1::MapService::NewStub(connection->channel());
    v1::GetMapRequest request;
    request.set_id(map_id);
    request.set_include_source(true);
    v1::GetMapResponse response;
    grpc::Status status = stub->GetMap(connection->UnaryContext().get(), request, &response);
    if (!status.ok()) return ReportRpcError(global, absl::StrCat("render: map ", map_id), status);
    map = MapFromSource(response.source());
    if (!map.ok()) {
      return ReportError(global, kExitOther,
                         absl::StrCat("render: map ", map_id, ": ", map.status().message()));
    }
    format = response.map().format();
    map_name = absl::StrCat(response.map().name(), " (", map_id, ")");
  }

  RenderOptions render;
  render.max_width_px = options.width;
  render.max_height_px = options.width * 0.8;
  render.y_up = YUp(options.y_axis, format);
  render.title = options.title.empty() ? absl::StrCat("swarmplan: ", map_name) : options.title;
  render.convergence_inset = options.convergence == "inset";
  if (absl::Status written = WriteText(svg_file, RenderMapSvg(*map, paths, curves, render));
      !written.ok()) {
    return ReportLocalError(global, written);
  }
  nlohmann::json report = {{"svg", svg_file}, {"paths", paths.size()}};
  if (!global.json) std::cout << "wrote " << svg_file << "\n";
  if (options.convergence == "file" && !curves.empty()) {
    const std::string curve_file = WithSuffix(svg_file, "-convergence.svg");
    if (absl::Status written =
            WriteText(curve_file, RenderConvergenceSvg(curves, render.title + ": convergence"));
        !written.ok()) {
      return ReportLocalError(global, written);
    }
    report["convergence_svg"] = curve_file;
    if (!global.json) std::cout << "wrote " << curve_file << "\n";
  }
  int exit_code = kExitOk;
  if (!png_file.empty()) {
    absl::StatusOr<std::string> converter = ConvertSvgToPng(svg_file, png_file);
    if (converter.ok()) {
      report["png"] = png_file;
      report["png_converter"] = *converter;
      if (!global.json) std::cout << "wrote " << png_file << " (with " << *converter << ")\n";
    } else {
      report["png"] = nullptr;
      report["png_message"] = std::string(converter.status().message());
      std::cerr << "swarmplan: PNG not written: " << converter.status().message() << "\n";
      // Asked for a .png output only: that is a failure. --png next to the SVG is best effort.
      if (png_output) exit_code = kExitOther;
    }
  }
  if (global.json) std::cout << report.dump(2) << "\n";
  return exit_code;
}

}  // namespace

void AddRenderCommand(CLI::App& app, const GlobalOptions& global, Action* action) {
  auto options = std::make_shared<RenderCommandOptions>();
  CLI::App* command = app.add_subcommand(
      "render",
      "Draw a map with paths (from jobs or path files) and the convergence curves as SVG,\n"
      "and PNG when rsvg-convert, inkscape or ImageMagick is installed");
  command->add_option("--map", options->map_id,
                      "Map id or NAME@VERSION (default: the map of the first --job); its content "
                      "comes from the server");
  command->add_option("--map-file", options->map_file, "Draw this local map file instead");
  command->add_option("--map-format", options->map_format, "Format of --map-file")
      ->check(CLI::IsMember(MapFormats()));
  command->add_option("-j,--job", options->jobs, "Draw this job's path (repeatable)")
      ->allow_extra_args(false);
  command
      ->add_option("--path", options->path_files,
                   "Draw a path file: .json, .csv or .geojson (repeatable)")
      ->allow_extra_args(false);
  command->add_option("-o,--output", options->output, "SVG (or .png) file to write")
      ->capture_default_str();
  command
      ->add_option("--convergence", options->convergence,
                   "Convergence curves: inset (below the map), file (a second SVG "
                   "NAME-convergence.svg) or none")
      ->check(CLI::IsMember({"inset", "file", "none"}))
      ->capture_default_str();
  command->add_flag("--png", options->png, "Also write a PNG next to the SVG, if possible");
  command->add_flag("--raw", options->raw, "Draw the raw paths instead of the smoothed ones");
  command->add_option("--width", options->width, "Largest map width in pixels")
      ->check(CLI::Range(100.0, 10000.0))
      ->capture_default_str();
  command
      ->add_option("--y-axis", options->y_axis,
                   "Map y on the page: up, down, or auto (down for ascii and movingai maps, "
                   "whose first line is y = 0)")
      ->check(CLI::IsMember({"auto", "up", "down"}))
      ->capture_default_str();
  command->add_option("--title", options->title, "Title above the map");
  OnChosen(command, action, [&global, options] { return Run(global, *options); });
}

}  // namespace swarmplan::client
