#pragma once

#include <functional>

#include "CLI/CLI.hpp"
#include "client/connection.h"

// The command groups of `swarmplan`, one file each. Every Add* function adds its subcommands to
// the app; when one of them is chosen on the command line, its callback stores what to run in
// *action, and main runs it after parsing (so parse errors and --help come first).
namespace swarmplan::client {

using Action = std::function<int()>;

void AddMapsCommand(CLI::App& app, const GlobalOptions& global, Action* action);
void AddAlgorithmsCommand(CLI::App& app, const GlobalOptions& global, Action* action);
void AddPlanCommand(CLI::App& app, const GlobalOptions& global, Action* action);
void AddJobsCommand(CLI::App& app, const GlobalOptions& global, Action* action);
void AddRenderCommand(CLI::App& app, const GlobalOptions& global, Action* action);
void AddHealthCommand(CLI::App& app, const GlobalOptions& global, Action* action);

// Makes `command` store `run` in *action when it is chosen.
inline void OnChosen(CLI::App* command, Action* action, Action run) {
  command->callback([action, run = std::move(run)] { *action = run; });
}

}  // namespace swarmplan::client
