// swarmplan maps upload|list|get|delete
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "client/commands.h"
#include "client/exit_codes.h"
#include "client/map_files.h"
#include "client/map_reference.h"
#include "client/output.h"
#include "core/map/io/map_io.h"
#include "swarmplan/v1/maps.grpc.pb.h"

namespace swarmplan::client {
namespace {

struct UploadOptions {
  std::string file;
  std::string format;
  std::string name;
  double terrain_height_scale = 0.0;
  double terrain_ceiling = 0.0;
  bool has_ceiling = false;
};

std::string MapSize(const v1::MapInfo& map) {
  if (map.kind() == v1::MAP_KIND_SHAPE_WORLD) {
    return absl::StrCat(FormatNumber(map.max().x() - map.min().x()), "x",
                        FormatNumber(map.max().y() - map.min().y()));
  }
  return absl::StrCat(map.width(), "x", map.height());
}

KeyValues MapDetails(const v1::MapInfo& map) {
  KeyValues rows = {
      {"id", map.id()},
      {"name", map.name()},
      {"version", absl::StrCat(map.version())},
      {"kind", MapKindName(map.kind())},
      {"format", map.format()},
      {"size", MapSize(map)},
  };
  if (map.resolution() > 0) rows.push_back({"resolution", FormatNumber(map.resolution())});
  const bool terrain = map.kind() == v1::MAP_KIND_TERRAIN;
  rows.push_back({"bounds", absl::StrCat(FormatPoint(map.min(), terrain), " .. ",
                                         FormatPoint(map.max(), terrain))});
  rows.push_back({"obstacles", absl::StrCat(map.obstacle_count())});
  rows.push_back({"created", FormatTimestamp(map.created_at())});
  rows.push_back({"content hash", map.content_hash()});
  return rows;
}

int RunUpload(const GlobalOptions& global, const UploadOptions& options) {
  absl::StatusOr<v1::MapFiles> files = ReadMapFiles(options.file, options.format);
  if (!files.ok()) return ReportLocalError(global, files.status());
  if (options.terrain_height_scale > 0) {
    files->set_terrain_height_scale(options.terrain_height_scale);
  }
  if (options.has_ceiling) files->set_terrain_ceiling(options.terrain_ceiling);

  absl::StatusOr<Connection> connection = Connection::Open(global);
  if (!connection.ok()) return ReportLocalError(global, connection.status());
  v1::UploadMapRequest request;
  request.set_name(options.name.empty() ? std::filesystem::path(options.file).stem().string()
                                        : options.name);
  *request.mutable_source()->mutable_files() = *std::move(files);
  v1::UploadMapResponse response;
  auto stub = v1::MapService::NewStub(connection->channel());
  grpc::Status status = stub->UploadMap(connection->UnaryContext().get(), request, &response);
  if (!status.ok()) return ReportRpcError(global, "maps upload", status);
  if (global.json) {
    PrintJson(response);
    return kExitOk;
  }
  std::cout << (response.created() ? "uploaded map " : "map already stored: ")
            << response.map().id() << " (" << response.map().name() << "@"
            << response.map().version() << ")\n";
  PrintKeyValues(std::cout, MapDetails(response.map()));
  return kExitOk;
}

struct ListOptions {
  int page_size = 100;
  std::string name;
};

int RunList(const GlobalOptions& global, const ListOptions& options) {
  absl::StatusOr<Connection> connection = Connection::Open(global);
  if (!connection.ok()) return ReportLocalError(global, connection.status());
  auto stub = v1::MapService::NewStub(connection->channel());
  v1::ListMapsResponse all;
  v1::ListMapsRequest request;
  request.set_page_size(options.page_size);
  request.set_name(options.name);
  do {
    v1::ListMapsResponse page;
    grpc::Status status = stub->ListMaps(connection->UnaryContext().get(), request, &page);
    if (!status.ok()) return ReportRpcError(global, "maps list", status);
    for (auto& map : *page.mutable_maps()) *all.add_maps() = std::move(map);
    request.set_page_token(page.next_page_token());
  } while (!request.page_token().empty());
  if (global.json) {
    PrintJson(all);
    return kExitOk;
  }
  if (all.maps().empty()) {
    if (!options.name.empty()) {
      std::cout << "no map named '" << options.name << "'\n";
    } else {
      std::cout << "no maps stored; upload one with: swarmplan maps upload FILE\n";
    }
    return kExitOk;
  }
  Table table(
      {"ID", "NAME", "VERSION", "KIND", "SIZE", "RESOLUTION", "OBSTACLES", "FORMAT", "CREATED"});
  for (const v1::MapInfo& map : all.maps()) {
    table.AddRow({map.id(), map.name(), absl::StrCat(map.version()), MapKindName(map.kind()),
                  MapSize(map), map.resolution() > 0 ? FormatNumber(map.resolution()) : "-",
                  absl::StrCat(map.obstacle_count()), map.format(),
                  FormatTimestamp(map.created_at())});
  }
  table.Print(std::cout);
  return kExitOk;
}

int RunGet(const GlobalOptions& global, const std::string& map, const std::string& save_dir) {
  absl::StatusOr<v1::GetMapRequest> reference = ParseMapReference("map", map);
  if (!reference.ok()) return ReportLocalError(global, reference.status());
  absl::StatusOr<Connection> connection = Connection::Open(global);
  if (!connection.ok()) return ReportLocalError(global, connection.status());
  auto stub = v1::MapService::NewStub(connection->channel());
  v1::GetMapRequest request = *std::move(reference);
  request.set_include_source(!save_dir.empty());
  v1::GetMapResponse response;
  grpc::Status status = stub->GetMap(connection->UnaryContext().get(), request, &response);
  if (!status.ok()) return ReportRpcError(global, "maps get", status);
  std::vector<std::string> saved;
  if (!save_dir.empty()) {
    absl::StatusOr<std::vector<std::string>> written = SaveMapSource(response.source(), save_dir);
    if (!written.ok()) return ReportLocalError(global, written.status());
    saved = *std::move(written);
  }
  if (global.json) {
    response.clear_source();  // the files are on disk; keep stdout small
    PrintJson(response);
    return kExitOk;
  }
  PrintKeyValues(std::cout, MapDetails(response.map()));
  if (!saved.empty()) std::cout << "saved: " << absl::StrJoin(saved, ", ") << "\n";
  return kExitOk;
}

int RunDelete(const GlobalOptions& global, const std::string& map) {
  absl::StatusOr<v1::GetMapRequest> reference = ParseMapReference("map", map);
  if (!reference.ok()) return ReportLocalError(global, reference.status());
  absl::StatusOr<Connection> connection = Connection::Open(global);
  if (!connection.ok()) return ReportLocalError(global, connection.status());
  std::string id;
  if (grpc::Status status = ResolveMapId(*connection, *reference, &id); !status.ok()) {
    return ReportRpcError(global, "maps delete", status);
  }
  auto stub = v1::MapService::NewStub(connection->channel());
  v1::DeleteMapRequest request;
  request.set_id(id);
  v1::DeleteMapResponse response;
  grpc::Status status = stub->DeleteMap(connection->UnaryContext().get(), request, &response);
  if (!status.ok()) return ReportRpcError(global, "maps delete", status);
  if (global.json) {
    std::cout << "{\"deleted\": \"" << id << "\"}\n";
  } else {
    std::cout << "deleted map " << id << "\n";
  }
  return kExitOk;
}

}  // namespace

void AddMapsCommand(CLI::App& app, const GlobalOptions& global, Action* action) {
  CLI::App* maps = app.add_subcommand("maps", "Upload, list, show and delete stored maps");
  maps->require_subcommand(1);

  auto upload = std::make_shared<UploadOptions>();
  CLI::App* upload_command = maps->add_subcommand(
      "upload", "Upload a map file (ros-yaml-pgm uploads the YAML and the image it names)");
  upload_command->add_option("file", upload->file, "The map file")->required();
  upload_command
      ->add_option("--format", upload->format,
                   absl::StrCat("One of: ", absl::StrJoin(MapFormats(), ", "),
                                "; guessed from the extension when omitted"))
      ->check(CLI::IsMember(MapFormats()));
  upload_command->add_option("--name", upload->name, "Map name (default: the file's stem)");
  upload_command->add_option("--terrain-height-scale", upload->terrain_height_scale,
                             "terrain-pgm: height units per grey level");
  upload_command
      ->add_option("--terrain-ceiling", upload->terrain_ceiling,
                   "Terrain formats: the flight ceiling (default: derived from the heights)")
      ->each([upload](const std::string&) { upload->has_ceiling = true; });
  OnChosen(upload_command, action, [&global, upload] { return RunUpload(global, *upload); });

  auto list_options = std::make_shared<ListOptions>();
  CLI::App* list = maps->add_subcommand("list", "List stored map versions, oldest first");
  list->add_option("--page-size", list_options->page_size, "Maps fetched per request")
      ->capture_default_str();
  list->add_option("--name", list_options->name, "Only the versions of the map with this name");
  OnChosen(list, action, [&global, list_options] { return RunList(global, *list_options); });

  constexpr char kMapHelp[] = "Map id, or NAME@VERSION (VERSION a number or 'latest')";
  auto get_map = std::make_shared<std::string>();
  auto save_dir = std::make_shared<std::string>();
  CLI::App* get = maps->add_subcommand("get", "Show one map version");
  get->add_option("map", *get_map, kMapHelp)->required();
  get->add_option("--save", *save_dir, "Also download the map's files into this folder");
  OnChosen(get, action,
           [&global, get_map, save_dir] { return RunGet(global, *get_map, *save_dir); });

  auto delete_id = std::make_shared<std::string>();
  CLI::App* remove = maps->add_subcommand("delete", "Delete a map version");
  remove->add_option("map", *delete_id, kMapHelp)->required();
  OnChosen(remove, action, [&global, delete_id] { return RunDelete(global, *delete_id); });
}

}  // namespace swarmplan::client
