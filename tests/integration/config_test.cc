// The server's configuration: flags over environment variables over defaults.
#include "server/config.h"

#include <gtest/gtest.h>

namespace swarmplan::server {
namespace {

TEST(ConfigTest, DefaultsWhenNothingIsGiven) {
  absl::StatusOr<ServerConfig> config = ParseConfig({}, {});
  ASSERT_TRUE(config.ok()) << config.status();
  EXPECT_EQ(config->listen, "127.0.0.1:50051");
  EXPECT_EQ(config->metrics_port, 9464);
  EXPECT_EQ(config->workers, 0);
  EXPECT_TRUE(config->token_file.empty());
  EXPECT_EQ(config->max_retained_jobs, 100000);
  EXPECT_EQ(config->job_cache_entries, 1000);
}

TEST(ConfigTest, RetainedJobsAndTheJobCacheHaveFlagsAndVariables) {
  absl::StatusOr<ServerConfig> config =
      ParseConfig({"--max-retained-jobs=3"},
                  {"SWARMPLAN_JOB_CACHE_ENTRIES=0", "SWARMPLAN_MAX_RETAINED_JOBS=9"});
  ASSERT_TRUE(config.ok()) << config.status();
  EXPECT_EQ(config->max_retained_jobs, 3);
  EXPECT_EQ(config->job_cache_entries, 0);
}

TEST(ConfigTest, FlagsOverrideEnvironmentVariables) {
  absl::StatusOr<ServerConfig> config =
      ParseConfig({"--workers=3", "--max-job-time", "90s", "--data-dir=/tmp/x"},
                  {"SWARMPLAN_WORKERS=7", "SWARMPLAN_QUEUE_CAPACITY=9",
                   "SWARMPLAN_JOB_RETENTION=2h", "PATH=/usr/bin"});
  ASSERT_TRUE(config.ok()) << config.status();
  EXPECT_EQ(config->workers, 3);
  EXPECT_EQ(config->queue_capacity, 9);
  EXPECT_EQ(config->job_retention, absl::Hours(2));
  EXPECT_EQ(config->max_job_time, absl::Seconds(90));
  EXPECT_EQ(config->data_dir, "/tmp/x");
}

TEST(ConfigTest, DurationsAcceptPlainSeconds) {
  absl::StatusOr<ServerConfig> config = ParseConfig({"--shutdown-grace=2.5"}, {});
  ASSERT_TRUE(config.ok());
  EXPECT_EQ(config->shutdown_grace, absl::Milliseconds(2500));
}

TEST(ConfigTest, BadInputNamesTheFlagOrVariable) {
  struct Case {
    std::vector<std::string> args;
    std::vector<std::string> env;
    const char* message;
  };
  for (const Case& c : std::vector<Case>{
           {{"--workers=-1"}, {}, "--workers"},
           {{"--queue-capacity=0"}, {}, "--queue-capacity"},
           {{"--max-retained-jobs=0"}, {}, "--max-retained-jobs"},
           {{"--job-cache-entries=-1"}, {}, "--job-cache-entries"},
           {{"--max-job-time=soon"}, {}, "--max-job-time"},
           {{"--no-such-flag=1"}, {}, "--no-such-flag"},
           {{"--listen"}, {}, "--listen"},
           {{"stray"}, {}, "stray"},
           {{}, {"SWARMPLAN_MAX_ITERATIONS=lots"}, "SWARMPLAN_MAX_ITERATIONS"},
           {{"--tls-cert-file=a.pem"}, {}, "--tls-key-file"},
       }) {
    absl::StatusOr<ServerConfig> config = ParseConfig(c.args, c.env);
    ASSERT_FALSE(config.ok()) << c.message;
    EXPECT_EQ(config.status().code(), absl::StatusCode::kInvalidArgument);
    EXPECT_NE(config.status().message().find(c.message), std::string::npos)
        << config.status().message();
  }
}

TEST(ConfigTest, HelpListsEveryFlagWithItsVariable) {
  absl::StatusOr<ServerConfig> config = ParseConfig({"--help"}, {});
  ASSERT_TRUE(absl::IsNotFound(config.status()));
  const std::string help(config.status().message());
  for (const char* flag : {"--listen", "SWARMPLAN_LISTEN", "--metrics-port", "--data-dir",
                           "--token-file", "--tls-cert-file", "--max-watchers-per-job"}) {
    EXPECT_NE(help.find(flag), std::string::npos) << flag;
  }
}

}  // namespace
}  // namespace swarmplan::server
