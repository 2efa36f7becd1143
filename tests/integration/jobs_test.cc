// JobService over loopback: Plan streams, SubmitPlan, GetJob, ListJobs, WatchJob, idempotency.
#include "tests/integration/test_server.h"

namespace swarmplan::testing {
namespace {

class JobsTest : public ::testing::Test {
 protected:
  TempDir dir_;
  TestServer server_{dir_.path()};
  std::string map_id_ = server_.UploadGrid("grid", 6, 4, 3);
};

TEST_F(JobsTest, PlanStreamsAcceptedStartedEveryProgressThenFinishedInOrder) {
  grpc::ClientContext context;
  auto reader = server_.jobs().Plan(&context, TestServer::SlowRequest(map_id_, 5, 0));
  grpc::Status status;
  const std::vector<v1::JobEvent> events = TestServer::ReadAll(*reader, &status);
  ASSERT_TRUE(status.ok()) << status.error_message();
  ASSERT_GE(events.size(), 4u);
  EXPECT_TRUE(events.front().has_accepted());
  EXPECT_EQ(events.front().accepted().seed(), 7u);
  EXPECT_TRUE(events[1].has_started());
  EXPECT_TRUE(events.back().has_finished());
  int64_t last_sequence = 0;
  int last_iteration = -1;
  for (size_t i = 0; i < events.size(); ++i) {
    EXPECT_EQ(events[i].job_id(), events.front().job_id());
    EXPECT_GT(events[i].sequence(), last_sequence);
    last_sequence = events[i].sequence();
    if (i >= 2 && i + 1 < events.size()) {
      ASSERT_TRUE(events[i].has_progress());
      EXPECT_GT(events[i].progress().iteration(), last_iteration);
      last_iteration = events[i].progress().iteration();
    }
  }
  EXPECT_EQ(last_iteration, 4);  // the last iteration is always reported
  const v1::JobEvent::Finished& finished = events.back().finished();
  EXPECT_EQ(finished.state(), v1::JOB_STATE_SUCCEEDED);
  EXPECT_EQ(finished.result().iterations(), 5);
  EXPECT_EQ(finished.result().convergence_size(), 5);
  EXPECT_EQ(finished.result().seed(), 7u);
  EXPECT_EQ(finished.result().resolved_parameters().at("iterations").int_value(), 5);
}

TEST_F(JobsTest, PlanWithAStarFindsACollisionFreePathAroundTheWall) {
  grpc::ClientContext context;
  auto reader = server_.jobs().Plan(&context, TestServer::Request(map_id_, "astar", 5.5));
  grpc::Status status;
  const std::vector<v1::JobEvent> events = TestServer::ReadAll(*reader, &status);
  ASSERT_TRUE(status.ok()) << status.error_message();
  ASSERT_TRUE(events.back().has_finished());
  const v1::PlanResult& result = events.back().finished().result();
  EXPECT_EQ(events.back().finished().state(), v1::JOB_STATE_SUCCEEDED)
      << events.back().ShortDebugString();
  ASSERT_GE(result.raw_path_size(), 2);
  EXPECT_DOUBLE_EQ(result.raw_path(0).x(), 0.5);
  EXPECT_DOUBLE_EQ(result.raw_path(result.raw_path_size() - 1).x(), 5.5);
  EXPECT_TRUE(result.raw_metrics().collision_free());
  // The wall at x = 3 blocks rows 0..2: the path climbs to row 3 and back.
  EXPECT_GT(result.raw_metrics().length(), 5.0 + 2 * 2.0 - 1e-9);
}

TEST_F(JobsTest, ProgressEveryNIterationsThinsTheStream) {
  v1::PlanRequest request = TestServer::SlowRequest(map_id_, 10, 2);
  request.mutable_progress()->set_every_iterations(5);
  grpc::ClientContext context;
  auto reader = server_.jobs().Plan(&context, request);
  grpc::Status status;
  std::vector<int> iterations;
  for (const v1::JobEvent& e : TestServer::ReadAll(*reader, &status)) {
    if (e.has_progress()) iterations.push_back(e.progress().iteration());
  }
  ASSERT_TRUE(status.ok());
  // Only iterations 0, 5 and the last (9) are published; a slow reader may see fewer of them
  // (coalesced), but always the last.
  ASSERT_FALSE(iterations.empty());
  EXPECT_EQ(iterations.back(), 9);
  for (int i : iterations) EXPECT_TRUE(i == 0 || i == 5 || i == 9) << i;
}

TEST_F(JobsTest, SubmitPlanReturnsAtOnceAndGetJobHasTheResult) {
  const v1::Job queued = server_.SubmitOk(TestServer::SlowRequest(map_id_, 3, 1));
  EXPECT_FALSE(queued.id().empty());
  EXPECT_TRUE(queued.state() == v1::JOB_STATE_QUEUED || queued.state() == v1::JOB_STATE_RUNNING);
  EXPECT_EQ(queued.seed(), 7u);
  EXPECT_EQ(queued.request().map_id(), map_id_);
  const v1::Job done = server_.WaitUntilFinal(queued.id());
  EXPECT_EQ(done.state(), v1::JOB_STATE_SUCCEEDED);
  EXPECT_EQ(done.result().raw_path_size(), 2);
  EXPECT_GT(done.finished_at().seconds(), 0);
  EXPECT_GE(done.finished_at().seconds(), done.started_at().seconds());
}

TEST_F(JobsTest, SubmitPlanPicksAndReportsASeedWhenTheRequestHasNone) {
  v1::PlanRequest request = TestServer::SlowRequest(map_id_, 1, 0);
  request.set_seed(0);
  const v1::Job job = server_.WaitUntilFinal(server_.SubmitOk(request).id());
  EXPECT_NE(job.seed(), 0u);
  EXPECT_EQ(job.result().seed(), job.seed());
}

TEST_F(JobsTest, ClientRequestIdMakesSubmitIdempotent) {
  v1::PlanRequest request = TestServer::SlowRequest(map_id_, 1, 0);
  request.set_client_request_id("req-42");
  (*request.mutable_labels())["robot"] = "agv-7";
  v1::SubmitPlanResponse first, second;
  grpc::ClientContext c1, c2;
  ASSERT_TRUE(server_.jobs().SubmitPlan(&c1, request, &first).ok());
  ASSERT_TRUE(server_.jobs().SubmitPlan(&c2, request, &second).ok());
  EXPECT_FALSE(first.deduplicated());
  EXPECT_TRUE(second.deduplicated());
  EXPECT_EQ(second.job().id(), first.job().id());
  EXPECT_EQ(second.job().request().labels().at("robot"), "agv-7");
}

TEST_F(JobsTest, AClientRequestIdReusedForADifferentRequestIsAlreadyExists) {
  v1::PlanRequest request = TestServer::SlowRequest(map_id_, 1, 0);
  request.set_client_request_id("req-7");
  const v1::Job first = server_.SubmitOk(request);
  v1::PlanRequest other = request;
  other.mutable_goal()->set_x(4.5);
  v1::SubmitPlanResponse response;
  grpc::ClientContext c1;
  grpc::Status status = server_.jobs().SubmitPlan(&c1, other, &response);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::ALREADY_EXISTS);
  EXPECT_NE(status.error_message().find("client_request_id"), std::string::npos);
  EXPECT_NE(status.error_message().find(first.id()), std::string::npos);
  // Plan refuses it the same way; the same request through Plan streams the first job.
  grpc::ClientContext c2;
  auto reader = server_.jobs().Plan(&c2, other);
  EXPECT_TRUE(TestServer::ReadAll(*reader, &status).empty());
  EXPECT_EQ(status.error_code(), grpc::StatusCode::ALREADY_EXISTS);
  grpc::ClientContext c3;
  auto same = server_.jobs().Plan(&c3, request);
  const std::vector<v1::JobEvent> events = TestServer::ReadAll(*same, &status);
  ASSERT_TRUE(status.ok()) << status.error_message();
  ASSERT_FALSE(events.empty());
  EXPECT_EQ(events.front().job_id(), first.id());
}

TEST_F(JobsTest, ListJobsFiltersByStateAndPagesNewestFirst) {
  std::vector<std::string> ids;
  for (int i = 0; i < 3; ++i) {
    ids.push_back(
        server_.WaitUntilFinal(server_.SubmitOk(TestServer::SlowRequest(map_id_, 1, 0)).id()).id());
  }
  const v1::Job cancelled_job = server_.SubmitOk(TestServer::SlowRequest(map_id_, 100000, 1));
  {
    v1::CancelJobRequest cancel;
    cancel.set_id(cancelled_job.id());
    v1::Job out;
    grpc::ClientContext context;
    ASSERT_TRUE(server_.jobs().CancelJob(&context, cancel, &out).ok());
  }
  server_.WaitForState(cancelled_job.id(), v1::JOB_STATE_CANCELLED);

  std::vector<std::string> listed;
  std::string token;
  do {
    v1::ListJobsRequest request;
    request.add_states(v1::JOB_STATE_SUCCEEDED);
    request.set_page_size(2);
    request.set_page_token(token);
    v1::ListJobsResponse response;
    grpc::ClientContext context;
    ASSERT_TRUE(server_.jobs().ListJobs(&context, request, &response).ok());
    for (const v1::Job& j : response.jobs()) {
      EXPECT_EQ(j.state(), v1::JOB_STATE_SUCCEEDED);
      EXPECT_FALSE(j.has_result());  // ListJobs omits results
      listed.push_back(j.id());
    }
    token = response.next_page_token();
  } while (!token.empty());
  EXPECT_EQ(listed, (std::vector<std::string>{ids[2], ids[1], ids[0]}));

  v1::ListJobsRequest all;
  v1::ListJobsResponse response;
  grpc::ClientContext context;
  ASSERT_TRUE(server_.jobs().ListJobs(&context, all, &response).ok());
  ASSERT_EQ(response.jobs_size(), 4);
  EXPECT_EQ(response.jobs(0).id(), cancelled_job.id());
}

TEST(JobsPagesTest, APageStopsBeforeItWouldExceedTheByteBudgetAndTheTokenContinues) {
  TempDir dir;
  server::ServerConfig config = TestServer::DefaultConfig();
  config.max_page_bytes = 2048;
  TestServer server(dir.path(), config);
  const std::string map_id = server.UploadGrid("grid", 6, 4);
  std::vector<std::string> ids;
  for (int i = 0; i < 6; ++i) {
    v1::PlanRequest request = TestServer::SlowRequest(map_id, 1, 0);
    for (const char* key : {"a", "b", "c"})
      (*request.mutable_labels())[key] = std::string(256, 'v');
    ids.insert(ids.begin(), server.WaitUntilFinal(server.SubmitOk(request).id()).id());
  }
  std::vector<std::string> listed;
  std::string token;
  int pages = 0;
  do {
    v1::ListJobsRequest request;
    request.set_page_token(token);
    v1::ListJobsResponse response;
    grpc::ClientContext context;
    ASSERT_TRUE(server.jobs().ListJobs(&context, request, &response).ok());
    EXPECT_LE(response.ByteSizeLong(), 2048u + response.next_page_token().size() + 8);
    ASSERT_GT(response.jobs_size(), 0);
    for (const v1::Job& j : response.jobs()) listed.push_back(j.id());
    token = response.next_page_token();
    ++pages;
  } while (!token.empty() && pages < 20);
  EXPECT_EQ(listed, ids);
  EXPECT_GE(pages, 3);
}

TEST_F(JobsTest, LateWatcherOfAFinishedJobGetsTheFinishedEventOnly) {
  const v1::Job job =
      server_.WaitUntilFinal(server_.SubmitOk(TestServer::SlowRequest(map_id_, 2, 0)).id());
  v1::WatchJobRequest request;
  request.set_id(job.id());
  grpc::ClientContext context;
  auto reader = server_.jobs().WatchJob(&context, request);
  grpc::Status status;
  const std::vector<v1::JobEvent> events = TestServer::ReadAll(*reader, &status);
  ASSERT_TRUE(status.ok()) << status.error_message();
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].finished().state(), v1::JOB_STATE_SUCCEEDED);
  EXPECT_EQ(events[0].finished().result().iterations(), 2);
}

TEST_F(JobsTest, LateWatcherOfARunningJobGetsStartedThenLiveEventsToTheEnd) {
  const v1::Job job = server_.SubmitOk(TestServer::SlowRequest(map_id_, 100, 10));
  server_.WaitForState(job.id(), v1::JOB_STATE_RUNNING);
  v1::WatchJobRequest request;
  request.set_id(job.id());
  grpc::ClientContext context;
  auto reader = server_.jobs().WatchJob(&context, request);
  grpc::Status status;
  const std::vector<v1::JobEvent> events = TestServer::ReadAll(*reader, &status);
  ASSERT_TRUE(status.ok()) << status.error_message();
  ASSERT_GE(events.size(), 2u);
  EXPECT_TRUE(events.front().has_started());
  EXPECT_TRUE(events.back().has_finished());
  EXPECT_EQ(events.back().finished().state(), v1::JOB_STATE_SUCCEEDED);
  for (size_t i = 1; i + 1 < events.size(); ++i) EXPECT_TRUE(events[i].has_progress());
}

TEST_F(JobsTest, WatchAndGetOfAnUnknownJobAreNotFound) {
  v1::WatchJobRequest watch;
  watch.set_id("job-nope");
  grpc::ClientContext c1, c2;
  auto reader = server_.jobs().WatchJob(&c1, watch);
  grpc::Status status;
  EXPECT_TRUE(TestServer::ReadAll(*reader, &status).empty());
  EXPECT_EQ(status.error_code(), grpc::StatusCode::NOT_FOUND);
  v1::GetJobRequest get;
  get.set_id("job-nope");
  v1::Job job;
  EXPECT_EQ(server_.jobs().GetJob(&c2, get, &job).error_code(), grpc::StatusCode::NOT_FOUND);
}

}  // namespace
}  // namespace swarmplan::testing
