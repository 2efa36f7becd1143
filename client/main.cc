// swarmplan: the command-line client of swarmplan-server.
#include <iostream>

#include "CLI/CLI.hpp"
#include "client/commands.h"
#include "client/exit_codes.h"

int main(int argc, char** argv) {
  using namespace swarmplan::client;
  CLI::App app("swarmplan: plan paths on a swarmplan server (maps, planners, jobs, rendering)",
               "swarmplan");
  app.fallthrough();  // global options may also follow the subcommand
  app.require_subcommand(1);
  app.set_version_flag("--version", "swarmplan 0.1.0");
  app.footer(ExitCodesHelp());

  GlobalOptions global;
  app.add_option("--server", global.server,
                 "Server address HOST:PORT, or replicas HOST:PORT,HOST:PORT,... (calls are "
                 "spread round-robin over every address they resolve to)")
      ->envname("SWARMPLAN_SERVER")
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast)
      ->capture_default_str();
  app.add_option("--timeout", global.timeout_seconds,
                 "Seconds to wait for the server on each call (streams: for connecting only)")
      ->check(CLI::PositiveNumber)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast)
      ->capture_default_str();
  app.add_flag("--json", global.json, "Machine-readable JSON on stdout");
  app.add_option("--token-file", global.token_file,
                 "File holding the bearer token the server requires")
      ->envname("SWARMPLAN_TOKEN_FILE");
  app.add_option("--tls-ca", global.tls_ca, "PEM root certificates: connect with TLS")
      ->envname("SWARMPLAN_TLS_CA");

  Action action;
  AddMapsCommand(app, global, &action);
  AddAlgorithmsCommand(app, global, &action);
  AddPlanCommand(app, global, &action);
  AddJobsCommand(app, global, &action);
  AddRenderCommand(app, global, &action);
  AddHealthCommand(app, global, &action);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int code = app.exit(error);
    return code == 0 ? kExitOk : kExitUsage;
  }
  if (!action) {
    std::cerr << app.help();
    return kExitUsage;
  }
  return action();
}
