// Durability over restarts: maps and finished jobs survive; jobs queued or running at shutdown
// run again with their recorded seed; acknowledged maps survive kill -9 of the server binary.
#include <thread>

#include "absl/time/clock.h"
#include "tests/integration/server_process.h"
#include "tests/integration/test_server.h"

namespace swarmplan::testing {
namespace {

std::vector<v1::MapInfo> ListAllMaps(TestServer& server) {
  v1::ListMapsResponse response;
  grpc::ClientContext context;
  EXPECT_TRUE(server.maps().ListMaps(&context, {}, &response).ok());
  return {response.maps().begin(), response.maps().end()};
}

TEST(RestartTest, MapsAndJobsSurviveARestartAndUnfinishedJobsRunAgainWithTheirSeed) {
  TempDir dir;
  server::ServerConfig config = TestServer::DefaultConfig();
  config.shutdown_grace = absl::Milliseconds(50);
  std::vector<v1::MapInfo> maps_before;
  std::string finished_id, running_id, queued_id, plan_id;
  v1::Job finished_before;
  {
    TestServer server(dir.path(), config);
    const std::string map_id = server.UploadGrid("grid", 6, 4, 3);
    server.UploadGrid("other", 3, 3);
    maps_before = ListAllMaps(server);
    finished_before =
        server.WaitUntilFinal(server.SubmitOk(TestServer::Request(map_id, "astar", 5.5)).id());
    finished_id = finished_before.id();
    v1::PlanRequest running = TestServer::SlowRequest(map_id, 200, 10);
    running.set_seed(1234);
    running_id = server.SubmitOk(running).id();
    server.WaitForState(running_id, v1::JOB_STATE_RUNNING);
    v1::PlanRequest queued = TestServer::SlowRequest(map_id, 3, 0);
    queued.set_seed(0);  // the server picks one and must keep it
    const v1::Job queued_job = server.SubmitOk(queued);
    queued_id = queued_job.id();
    EXPECT_NE(queued_job.seed(), 0u);
    // A queued job whose Plan stream the shutdown cuts stays queued too.
    grpc::ClientContext plan_context;
    auto plan = server.jobs().Plan(&plan_context, TestServer::SlowRequest(map_id, 2, 0));
    v1::JobEvent accepted;
    ASSERT_TRUE(plan->Read(&accepted));
    plan_id = accepted.job_id();
    server.server().Shutdown();  // the running job does not finish within the grace period
    grpc::Status plan_status;
    const std::vector<v1::JobEvent> rest = TestServer::ReadAll(*plan, &plan_status);
    ASSERT_FALSE(rest.empty());
    EXPECT_TRUE(rest.back().has_requeued());
    EXPECT_EQ(plan_status.error_code(), grpc::StatusCode::UNAVAILABLE);
  }
  TestServer server(dir.path(), config);
  std::vector<v1::MapInfo> maps_after = ListAllMaps(server);
  ASSERT_EQ(maps_after.size(), maps_before.size());
  for (size_t i = 0; i < maps_after.size(); ++i) {
    EXPECT_EQ(maps_after[i].ShortDebugString(), maps_before[i].ShortDebugString());
  }
  const v1::Job finished_after = server.GetJob(finished_id);
  EXPECT_EQ(finished_after.state(), v1::JOB_STATE_SUCCEEDED);
  EXPECT_EQ(finished_after.result().ShortDebugString(),
            finished_before.result().ShortDebugString());

  const v1::Job rerun = server.WaitUntilFinal(running_id);
  EXPECT_EQ(rerun.state(), v1::JOB_STATE_SUCCEEDED);
  EXPECT_EQ(rerun.seed(), 1234u);
  EXPECT_EQ(rerun.result().seed(), 1234u);
  EXPECT_EQ(rerun.result().iterations(), 200);
  const v1::Job queued_rerun = server.WaitUntilFinal(queued_id);
  EXPECT_EQ(queued_rerun.state(), v1::JOB_STATE_SUCCEEDED);
  EXPECT_EQ(queued_rerun.result().seed(), queued_rerun.seed());
  EXPECT_EQ(server.WaitUntilFinal(plan_id).state(), v1::JOB_STATE_SUCCEEDED);
}

grpc::Status DeleteMap(TestServer& server, const std::string& id) {
  v1::DeleteMapRequest request;
  request.set_id(id);
  v1::DeleteMapResponse response;
  grpc::ClientContext context;
  return server.maps().DeleteMap(&context, request, &response);
}

TEST(RestartTest, AMapWithQueuedOrRunningJobsCannotBeDeletedBeforeOrAfterARestart) {
  TempDir dir;
  server::ServerConfig config = TestServer::DefaultConfig();
  config.shutdown_grace = absl::Milliseconds(50);
  std::string map_id, running_id, queued_id;
  {
    TestServer server(dir.path(), config);
    map_id = server.UploadGrid("grid", 6, 4);
    running_id = server.SubmitOk(TestServer::SlowRequest(map_id, 100, 10)).id();
    server.WaitForState(running_id, v1::JOB_STATE_RUNNING);
    queued_id = server.SubmitOk(TestServer::SlowRequest(map_id, 2, 0)).id();
    const grpc::Status refused = DeleteMap(server, map_id);
    EXPECT_EQ(refused.error_code(), grpc::StatusCode::FAILED_PRECONDITION);
    EXPECT_NE(refused.error_message().find(running_id), std::string::npos)
        << refused.error_message();
    EXPECT_NE(refused.error_message().find(queued_id), std::string::npos)
        << refused.error_message();
    server.server().Shutdown();  // both jobs are stored as queued
  }
  TestServer server(dir.path(), config);
  EXPECT_EQ(DeleteMap(server, map_id).error_code(), grpc::StatusCode::FAILED_PRECONDITION);
  EXPECT_EQ(server.WaitUntilFinal(running_id).state(), v1::JOB_STATE_SUCCEEDED);
  EXPECT_EQ(server.WaitUntilFinal(queued_id).state(), v1::JOB_STATE_SUCCEEDED);
  // Finished jobs do not hold their map.
  EXPECT_TRUE(DeleteMap(server, map_id).ok());
  EXPECT_EQ(server.GetJob(running_id).state(), v1::JOB_STATE_SUCCEEDED);
}

TEST(RestartTest, AShutdownEndsTheStreamsOfUnfinishedJobsWithARequeuedEvent) {
  TempDir dir;
  server::ServerConfig config = TestServer::DefaultConfig();
  config.shutdown_grace = absl::Milliseconds(50);
  std::string running_id, queued_id;
  {
    TestServer server(dir.path(), config);
    const std::string map_id = server.UploadGrid("grid", 6, 4);
    grpc::ClientContext running_context, queued_context;
    auto running = server.jobs().Plan(&running_context, TestServer::SlowRequest(map_id, 200, 10));
    v1::JobEvent event;
    ASSERT_TRUE(running->Read(&event));  // accepted
    running_id = event.job_id();
    ASSERT_TRUE(running->Read(&event));
    ASSERT_TRUE(event.has_started());
    auto queued = server.jobs().Plan(&queued_context, TestServer::SlowRequest(map_id, 2, 0));
    ASSERT_TRUE(queued->Read(&event));
    ASSERT_TRUE(event.has_accepted());
    queued_id = event.job_id();
    // The running job outlasts the grace period.
    std::thread stop([&server] { server.server().Shutdown(); });
    for (auto* stream : {running.get(), queued.get()}) {
      grpc::Status status;
      const std::vector<v1::JobEvent> events = TestServer::ReadAll(*stream, &status);
      ASSERT_FALSE(events.empty());
      EXPECT_TRUE(events.back().has_requeued()) << events.back().ShortDebugString();
      EXPECT_NE(events.back().requeued().reason().find("queued again"), std::string::npos);
      EXPECT_EQ(status.error_code(), grpc::StatusCode::UNAVAILABLE) << status.error_message();
      for (const v1::JobEvent& e : events) EXPECT_FALSE(e.has_finished());
    }
    stop.join();
  }
  TestServer server(dir.path(), config);
  EXPECT_EQ(server.WaitUntilFinal(running_id).state(), v1::JOB_STATE_SUCCEEDED);
  EXPECT_EQ(server.WaitUntilFinal(queued_id).state(), v1::JOB_STATE_SUCCEEDED);
}

TEST(RestartTest, FinishedJobsOlderThanTheRetentionPeriodAreDropped) {
  TempDir dir;
  server::ServerConfig config = TestServer::DefaultConfig();
  std::string id;
  {
    TestServer server(dir.path(), config);
    const std::string map_id = server.UploadGrid("grid", 6, 4);
    id = server.WaitUntilFinal(server.SubmitOk(TestServer::SlowRequest(map_id, 1, 0)).id()).id();
  }
  absl::SleepFor(absl::Milliseconds(20));
  config.job_retention = absl::Milliseconds(10);
  TestServer server(dir.path(), config);
  v1::GetJobRequest request;
  request.set_id(id);
  v1::Job job;
  grpc::ClientContext context;
  EXPECT_EQ(server.jobs().GetJob(&context, request, &job).error_code(),
            grpc::StatusCode::NOT_FOUND);
  EXPECT_EQ(ListAllMaps(server).size(), 1u);  // maps have no retention
}

TEST(RestartTest, AcknowledgedMapsAndJobsSurviveKill9OfTheServerBinary) {
  TempDir dir;
  absl::StatusOr<std::unique_ptr<ServerProcess>> process =
      ServerProcess::Start({"--store=" + StoreUrlFor(dir.path())});
  ASSERT_TRUE(process.ok()) << process.status();
  v1::MapService::Stub* maps = &(*process)->maps();
  v1::JobService::Stub* jobs = &(*process)->jobs();
  v1::UploadMapRequest upload;
  upload.set_name("kept");
  upload.mutable_source()->mutable_files()->set_format("ascii");
  v1::MapFile* file = upload.mutable_source()->mutable_files()->add_files();
  file->set_name("kept.txt");
  file->set_content("......\n..##..\n......\n");
  v1::UploadMapResponse uploaded;
  {
    grpc::ClientContext context;
    ASSERT_TRUE(maps->UploadMap(&context, upload, &uploaded).ok());
  }
  v1::PlanRequest request = TestServer::Request(uploaded.map().id(), "astar", 5.5);
  std::string job_id;
  {
    grpc::ClientContext context;
    auto reader = jobs->Plan(&context, request);
    grpc::Status status;
    const std::vector<v1::JobEvent> events = TestServer::ReadAll(*reader, &status);
    ASSERT_TRUE(status.ok()) << status.error_message();
    job_id = events.front().job_id();
  }
  (*process)->Kill();

  TestServer server(dir.path());
  v1::GetMapRequest get;
  get.set_id(uploaded.map().id());
  v1::GetMapResponse got;
  grpc::ClientContext context;
  ASSERT_TRUE(server.maps().GetMap(&context, get, &got).ok());
  EXPECT_EQ(got.map().content_hash(), uploaded.map().content_hash());
  EXPECT_EQ(server.GetJob(job_id).state(), v1::JOB_STATE_SUCCEEDED);
}

}  // namespace
}  // namespace swarmplan::testing
