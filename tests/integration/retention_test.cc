// Finished jobs live in the store: a bounded cache of them in memory, a cap on how many are
// kept (--max-retained-jobs) beside the retention time, results identical from the cache, from
// the store and after a restart.
#include <sqlite3.h>

#include <string>
#include <vector>

#include "absl/time/clock.h"
#include "server/proto_convert.h"
#include "tests/integration/test_server.h"

namespace swarmplan::testing {
namespace {

double MetricValue(TestServer& server, const std::string& name) {
  const std::string body = HttpGet(server.server().metrics_port(), "/metrics");
  const std::string prefix = "\n" + name + " ";
  const size_t at = body.find(prefix);
  if (at == std::string::npos) return -1;
  return std::stod(body.substr(at + prefix.size()));
}

std::vector<std::string> ListedIds(TestServer& server) {
  v1::ListJobsRequest request;
  request.set_page_size(100);
  v1::ListJobsResponse response;
  grpc::ClientContext context;
  grpc::Status status = server.jobs().ListJobs(&context, request, &response);
  EXPECT_TRUE(status.ok()) << status.error_message();
  std::vector<std::string> ids;
  for (const v1::Job& job : response.jobs()) ids.push_back(job.id());
  return ids;
}

grpc::StatusCode GetJobCode(TestServer& server, const std::string& id) {
  v1::GetJobRequest request;
  request.set_id(id);
  v1::Job job;
  grpc::ClientContext context;
  return server.jobs().GetJob(&context, request, &job).error_code();
}

// The finished event a WatchJob of a finished job gives.
v1::JobEvent WatchFinished(TestServer& server, const std::string& id) {
  v1::WatchJobRequest request;
  request.set_id(id);
  grpc::ClientContext context;
  auto reader = server.jobs().WatchJob(&context, request);
  grpc::Status status;
  std::vector<v1::JobEvent> events = TestServer::ReadAll(*reader, &status);
  EXPECT_TRUE(status.ok()) << status.error_message();
  return events.empty() ? v1::JobEvent() : events.back();
}

// `n` finished astar jobs on one map, oldest first, each with a different goal.
std::vector<v1::Job> RunJobs(TestServer& server, const std::string& map_id, int n) {
  std::vector<v1::Job> jobs;
  for (int i = 0; i < n; ++i) {
    jobs.push_back(server.WaitUntilFinal(
        server.SubmitOk(TestServer::Request(map_id, "astar", 1.5 + i % 5)).id()));
    EXPECT_EQ(jobs.back().state(), v1::JOB_STATE_SUCCEEDED);
  }
  return jobs;
}

TEST(RetentionTest, MaxRetainedJobsKeepsTheNewestFinishedJobsAlsoAfterARestart) {
  TempDir dir;
  server::ServerConfig config = TestServer::DefaultConfig();
  config.max_retained_jobs = 3;
  std::vector<v1::Job> jobs;
  {
    TestServer server(dir.path(), config);
    jobs = RunJobs(server, server.UploadGrid("grid", 6, 4), 5);
    EXPECT_EQ(ListedIds(server),
              (std::vector<std::string>{jobs[4].id(), jobs[3].id(), jobs[2].id()}));
    EXPECT_EQ(GetJobCode(server, jobs[0].id()), grpc::StatusCode::NOT_FOUND);
    EXPECT_EQ(GetJobCode(server, jobs[1].id()), grpc::StatusCode::NOT_FOUND);
    EXPECT_EQ(GetJobCode(server, jobs[2].id()), grpc::StatusCode::OK);
  }
  // A lower cap applies at the next start.
  config.max_retained_jobs = 2;
  TestServer server(dir.path(), config);
  EXPECT_EQ(ListedIds(server), (std::vector<std::string>{jobs[4].id(), jobs[3].id()}));
  EXPECT_EQ(GetJobCode(server, jobs[2].id()), grpc::StatusCode::NOT_FOUND);
  EXPECT_EQ(server.GetJob(jobs[4].id()).result().ShortDebugString(),
            jobs[4].result().ShortDebugString());
}

TEST(RetentionTest, TheCacheIsBoundedAndResultsComeBackIdenticallyFromTheStore) {
  TempDir dir;
  server::ServerConfig config = TestServer::WithMetrics();
  config.job_cache_entries = 2;
  std::vector<v1::Job> jobs;
  {
    TestServer server(dir.path(), config);
    jobs = RunJobs(server, server.UploadGrid("grid", 6, 4), 6);
    EXPECT_EQ(MetricValue(server, "swarmplan_job_cache_entries"), 2);
    // The oldest are read from the store; reading them moves them into the cache, which stays
    // bounded.
    for (const v1::Job& job : jobs) {
      SCOPED_TRACE(job.id());
      const v1::Job again = server.GetJob(job.id());
      EXPECT_TRUE(again.has_result());
      EXPECT_EQ(again.ShortDebugString(), job.ShortDebugString());
      const v1::JobEvent finished = WatchFinished(server, job.id());
      EXPECT_EQ(finished.finished().result().ShortDebugString(), job.result().ShortDebugString());
      EXPECT_LE(MetricValue(server, "swarmplan_job_cache_entries"), 2);
    }
    EXPECT_EQ(ListedIds(server).size(), jobs.size());
  }
  config.job_cache_entries = 0;
  TestServer server(dir.path(), config);
  EXPECT_EQ(ListedIds(server).size(), jobs.size());
  for (const v1::Job& job : jobs) {
    SCOPED_TRACE(job.id());
    EXPECT_EQ(server.GetJob(job.id()).ShortDebugString(), job.ShortDebugString());
    EXPECT_EQ(WatchFinished(server, job.id()).finished().result().ShortDebugString(),
              job.result().ShortDebugString());
  }
  EXPECT_EQ(MetricValue(server, "swarmplan_job_cache_entries"), 0);
}

TEST(RetentionTest, AClientRequestIdIsKnownAfterItsJobLeftTheCacheAndAfterARestart) {
  TempDir dir;
  server::ServerConfig config = TestServer::DefaultConfig();
  config.job_cache_entries = 0;
  std::string first_id;
  std::string map_id;
  {
    TestServer server(dir.path(), config);
    map_id = server.UploadGrid("grid", 6, 4);
    v1::PlanRequest request = TestServer::Request(map_id, "astar", 5.5);
    request.set_client_request_id("order-17");
    first_id = server.WaitUntilFinal(server.SubmitOk(request).id()).id();
    RunJobs(server, map_id, 2);
    EXPECT_EQ(server.SubmitOk(request).id(), first_id);
  }
  TestServer server(dir.path(), config);
  v1::PlanRequest request = TestServer::Request(map_id, "astar", 5.5);
  request.set_client_request_id("order-17");
  EXPECT_EQ(server.SubmitOk(request).id(), first_id);
  request.mutable_goal()->set_x(4.5);
  v1::SubmitPlanResponse response;
  grpc::ClientContext context;
  grpc::Status status = server.jobs().SubmitPlan(&context, request, &response);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::ALREADY_EXISTS);
  EXPECT_NE(status.error_message().find("client_request_id"), std::string::npos);
}

TEST(RetentionTest, PagesContinueAcrossJobsInTheStore) {
  TempDir dir;
  server::ServerConfig config = TestServer::DefaultConfig();
  config.job_cache_entries = 1;
  TestServer server(dir.path(), config);
  std::vector<v1::Job> jobs = RunJobs(server, server.UploadGrid("grid", 6, 4), 7);
  std::vector<std::string> listed;
  std::string token;
  int pages = 0;
  do {
    v1::ListJobsRequest request;
    request.set_page_size(3);
    request.set_page_token(token);
    request.add_states(v1::JOB_STATE_SUCCEEDED);
    v1::ListJobsResponse response;
    grpc::ClientContext context;
    ASSERT_TRUE(server.jobs().ListJobs(&context, request, &response).ok());
    for (const v1::Job& job : response.jobs()) {
      EXPECT_FALSE(job.has_result());  // lists leave results out
      listed.push_back(job.id());
    }
    token = response.next_page_token();
    ++pages;
  } while (!token.empty() && pages < 10);
  EXPECT_EQ(pages, 3);
  ASSERT_EQ(listed.size(), jobs.size());
  for (size_t i = 0; i < jobs.size(); ++i) EXPECT_EQ(listed[i], jobs[jobs.size() - 1 - i].id());
}

TEST(RetentionTest, JobsStoredBeforeTheClientRequestIdColumnAreServedAndDeduplicated) {
  if (TestingWithRedis()) GTEST_SKIP() << "an upgrade of the SQLite schema; Redis has no older one";
  TempDir dir;
  v1::Job old;
  old.set_id("job-0123456789abcdef");
  old.set_state(v1::JOB_STATE_SUCCEEDED);
  *old.mutable_request() = TestServer::Request("map-gone", "astar", 5.5);
  old.mutable_request()->set_client_request_id("order-old");
  old.set_seed(99);
  const absl::Time now = absl::Now();
  *old.mutable_created_at() = server::ToProto(now - absl::Seconds(2));
  *old.mutable_finished_at() = server::ToProto(now - absl::Seconds(1));
  old.mutable_result()->set_found(true);
  old.mutable_result()->set_fitness(5.0);
  {
    // The schema of the previous version: no client_request_id column.
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open((dir.path() + "/swarmplan.db").c_str(), &db), SQLITE_OK);
    ASSERT_EQ(sqlite3_exec(db,
                           "CREATE TABLE jobs (id TEXT PRIMARY KEY, state INTEGER NOT NULL, "
                           "record BLOB NOT NULL, created_us INTEGER NOT NULL, finished_us "
                           "INTEGER);",
                           nullptr, nullptr, nullptr),
              SQLITE_OK);
    sqlite3_stmt* insert = nullptr;
    ASSERT_EQ(
        sqlite3_prepare_v2(db, "INSERT INTO jobs VALUES (?, ?, ?, ?, ?)", -1, &insert, nullptr),
        SQLITE_OK);
    const std::string record = old.SerializeAsString();
    sqlite3_bind_text(insert, 1, old.id().c_str(), -1, SQLITE_TRANSIENT);
    sqlite3_bind_int64(insert, 2, old.state());
    sqlite3_bind_blob(insert, 3, record.data(), static_cast<int>(record.size()), SQLITE_TRANSIENT);
    sqlite3_bind_int64(insert, 4, absl::ToUnixMicros(now - absl::Seconds(2)));
    sqlite3_bind_int64(insert, 5, absl::ToUnixMicros(now - absl::Seconds(1)));
    ASSERT_EQ(sqlite3_step(insert), SQLITE_DONE);
    sqlite3_finalize(insert);
    sqlite3_close(db);
  }
  server::ServerConfig config = TestServer::DefaultConfig();
  config.job_cache_entries = 0;
  TestServer server(dir.path(), config);
  EXPECT_EQ(server.GetJob(old.id()).ShortDebugString(), old.ShortDebugString());
  EXPECT_EQ(ListedIds(server), std::vector<std::string>{old.id()});
  EXPECT_EQ(server.SubmitOk(old.request()).id(), old.id());
}

}  // namespace
}  // namespace swarmplan::testing
