// swarmplan algorithms [ID]
#include <iostream>
#include <memory>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "client/commands.h"
#include "client/exit_codes.h"
#include "client/output.h"
#include "swarmplan/v1/algorithms.grpc.pb.h"

namespace swarmplan::client {
namespace {

std::string MapKinds(const v1::Algorithm& algorithm) {
  std::vector<std::string> kinds;
  for (int kind : algorithm.map_kinds()) kinds.push_back(MapKindName(v1::MapKind(kind)));
  return absl::StrJoin(kinds, ",");
}

std::string Range(const v1::ParameterSpec& spec) {
  if (!spec.choices().empty()) return absl::StrJoin(spec.choices(), "|");
  if (!spec.has_min() && !spec.has_max()) return "";
  return absl::StrCat("[", spec.has_min() ? FormatNumber(spec.min()) : "", ", ",
                      spec.has_max() ? FormatNumber(spec.max()) : "", "]");
}

void PrintAlgorithm(const v1::Algorithm& algorithm) {
  PrintKeyValues(std::cout,
                 {{"id", algorithm.id()},
                  {"seed paper", algorithm.seed_paper().empty() ? "-" : algorithm.seed_paper()},
                  {"encoding", algorithm.encoding()},
                  {"map kinds", MapKinds(algorithm)}});
  std::cout << "\n" << algorithm.description() << "\n\n";
  if (algorithm.parameters().empty()) {
    std::cout << "no parameters\n";
    return;
  }
  Table table({"PARAMETER", "TYPE", "DEFAULT", "RANGE", "UNIT", "DESCRIPTION"});
  for (const v1::ParameterSpec& spec : algorithm.parameters()) {
    table.AddRow({spec.name(), ParameterTypeName(spec.type()),
                  FormatParamValue(spec.default_value()) + (spec.default_is_ours() ? " *" : ""),
                  Range(spec), spec.unit(), spec.description()});
  }
  table.Print(std::cout);
  std::cout << "\n* default chosen by swarmplan, not given by the seed paper\n"
            << "Set parameters with: swarmplan plan ... --algorithm " << algorithm.id()
            << " --param NAME=VALUE\n";
}

int Run(const GlobalOptions& global, const std::string& id) {
  absl::StatusOr<Connection> connection = Connection::Open(global);
  if (!connection.ok()) return ReportLocalError(global, connection.status());
  auto stub = v1::AlgorithmService::NewStub(connection->channel());
  if (!id.empty()) {
    v1::GetAlgorithmRequest request;
    request.set_id(id);
    v1::Algorithm algorithm;
    grpc::Status status = stub->GetAlgorithm(connection->UnaryContext().get(), request, &algorithm);
    if (!status.ok()) return ReportRpcError(global, "algorithms", status);
    if (global.json) {
      PrintJson(algorithm);
    } else {
      PrintAlgorithm(algorithm);
    }
    return kExitOk;
  }
  v1::ListAlgorithmsResponse response;
  grpc::Status status = stub->ListAlgorithms(connection->UnaryContext().get(),
                                             v1::ListAlgorithmsRequest(), &response);
  if (!status.ok()) return ReportRpcError(global, "algorithms", status);
  if (global.json) {
    PrintJson(response);
    return kExitOk;
  }
  Table table({"ID", "ENCODING", "MAP KINDS", "PARAMS", "SEED PAPER"});
  for (const v1::Algorithm& algorithm : response.algorithms()) {
    std::string paper = algorithm.seed_paper().empty() ? "-" : algorithm.seed_paper();
    if (paper.size() > 60) paper = paper.substr(0, 57) + "...";
    table.AddRow({algorithm.id(), algorithm.encoding(), MapKinds(algorithm),
                  absl::StrCat(algorithm.parameters_size()), paper});
  }
  table.Print(std::cout);
  std::cout << "\nParameters of one planner: swarmplan algorithms ID\n";
  return kExitOk;
}

}  // namespace

void AddAlgorithmsCommand(CLI::App& app, const GlobalOptions& global, Action* action) {
  auto id = std::make_shared<std::string>();
  CLI::App* command =
      app.add_subcommand("algorithms", "List the planners, or show one planner's parameter schema");
  command->add_option("id", *id, "A planner id, e.g. astar");
  OnChosen(command, action, [&global, id] { return Run(global, *id); });
}

}  // namespace swarmplan::client
