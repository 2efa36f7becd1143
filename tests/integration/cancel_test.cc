// Stopping jobs over loopback: CancelJob, the Plan caller going away, detached jobs, the time
// budget, a full queue, the watcher limit. One worker, so "the worker is free again" is visible:
// the next job runs to the end.
#include "absl/time/clock.h"
#include "tests/integration/test_server.h"

namespace swarmplan::testing {
namespace {

class CancelTest : public ::testing::Test {
 protected:
  static server::ServerConfig Config() {
    server::ServerConfig config = TestServer::DefaultConfig();
    config.queue_capacity = 2;
    config.max_watchers_per_job = 2;
    return config;
  }

  // A quick job succeeds: the single worker is free.
  void ExpectWorkerFree() {
    const v1::Job job =
        server_.WaitUntilFinal(server_.SubmitOk(TestServer::SlowRequest(map_id_, 2, 0)).id());
    EXPECT_EQ(job.state(), v1::JOB_STATE_SUCCEEDED);
  }

  TempDir dir_;
  TestServer server_{dir_.path(), Config()};
  std::string map_id_ = server_.UploadGrid("grid", 6, 4);
};

TEST_F(CancelTest, CancelJobStopsARunningJobAtItsNextIteration) {
  const v1::Job job = server_.SubmitOk(TestServer::SlowRequest(map_id_, 1000000, 1));
  server_.WaitForState(job.id(), v1::JOB_STATE_RUNNING);
  v1::CancelJobRequest request;
  request.set_id(job.id());
  v1::Job response;
  grpc::ClientContext context;
  ASSERT_TRUE(server_.jobs().CancelJob(&context, request, &response).ok());
  const v1::Job done = server_.WaitUntilFinal(job.id());
  EXPECT_EQ(done.state(), v1::JOB_STATE_CANCELLED);
  EXPECT_EQ(done.result().stop_reason(), "cancelled");
  ExpectWorkerFree();
}

TEST_F(CancelTest, CancelJobOfAQueuedJobFinishesItAtOnce) {
  const v1::Job running = server_.SubmitOk(TestServer::SlowRequest(map_id_, 1000000, 1));
  server_.WaitForState(running.id(), v1::JOB_STATE_RUNNING);
  const v1::Job queued = server_.SubmitOk(TestServer::SlowRequest(map_id_, 2, 0));
  EXPECT_EQ(queued.state(), v1::JOB_STATE_QUEUED);
  EXPECT_EQ(queued.queue_position(), 0);
  for (const std::string& id : {queued.id(), running.id()}) {
    v1::CancelJobRequest request;
    request.set_id(id);
    v1::Job response;
    grpc::ClientContext context;
    ASSERT_TRUE(server_.jobs().CancelJob(&context, request, &response).ok());
  }
  EXPECT_EQ(server_.GetJob(queued.id()).state(), v1::JOB_STATE_CANCELLED);
  EXPECT_FALSE(server_.GetJob(queued.id()).has_result());
  EXPECT_EQ(server_.WaitUntilFinal(running.id()).state(), v1::JOB_STATE_CANCELLED);
  ExpectWorkerFree();
}

TEST_F(CancelTest, PlanCallerGoingAwayCancelsItsJob) {
  grpc::ClientContext context;
  auto reader = server_.jobs().Plan(&context, TestServer::SlowRequest(map_id_, 1000000, 1));
  v1::JobEvent event;
  ASSERT_TRUE(reader->Read(&event));
  ASSERT_TRUE(event.has_accepted());
  const std::string id = event.job_id();
  ASSERT_TRUE(reader->Read(&event));
  ASSERT_TRUE(event.has_started());
  context.TryCancel();
  EXPECT_EQ(reader->Finish().error_code(), grpc::StatusCode::CANCELLED);
  EXPECT_EQ(server_.WaitUntilFinal(id).state(), v1::JOB_STATE_CANCELLED);
  ExpectWorkerFree();
}

TEST_F(CancelTest, DetachedPlanKeepsRunningWhenItsCallerGoesAway) {
  v1::PlanRequest request = TestServer::SlowRequest(map_id_, 30, 5);
  request.set_detached(true);
  std::string id;
  {
    grpc::ClientContext context;
    auto reader = server_.jobs().Plan(&context, request);
    v1::JobEvent event;
    ASSERT_TRUE(reader->Read(&event));
    id = event.job_id();
    context.TryCancel();
    reader->Finish();
  }
  EXPECT_EQ(server_.WaitUntilFinal(id).state(), v1::JOB_STATE_SUCCEEDED);
}

TEST_F(CancelTest, AWatcherLeavingNeverCancelsTheJob) {
  const v1::Job job = server_.SubmitOk(TestServer::SlowRequest(map_id_, 30, 5));
  {
    v1::WatchJobRequest request;
    request.set_id(job.id());
    grpc::ClientContext context;
    auto reader = server_.jobs().WatchJob(&context, request);
    v1::JobEvent event;
    ASSERT_TRUE(reader->Read(&event));
    context.TryCancel();
    reader->Finish();
  }
  EXPECT_EQ(server_.WaitUntilFinal(job.id()).state(), v1::JOB_STATE_SUCCEEDED);
}

TEST_F(CancelTest, TimeBudgetEndsTheJobAsDeadlineExceeded) {
  v1::PlanRequest request = TestServer::SlowRequest(map_id_, 1000000, 1);
  request.mutable_limits()->mutable_time_budget()->set_nanos(100 * 1000 * 1000);
  grpc::ClientContext context;
  auto reader = server_.jobs().Plan(&context, request);
  grpc::Status status;
  const std::vector<v1::JobEvent> events = TestServer::ReadAll(*reader, &status);
  ASSERT_TRUE(status.ok()) << status.error_message();
  ASSERT_TRUE(events.back().has_finished());
  EXPECT_EQ(events.back().finished().state(), v1::JOB_STATE_DEADLINE_EXCEEDED);
  EXPECT_EQ(events.back().finished().result().stop_reason(), "deadline");
  ExpectWorkerFree();
}

TEST_F(CancelTest, FullQueueAnswersResourceExhaustedAtOnce) {
  const v1::Job running = server_.SubmitOk(TestServer::SlowRequest(map_id_, 1000000, 1));
  server_.WaitForState(running.id(), v1::JOB_STATE_RUNNING);
  std::vector<std::string> ids = {running.id()};
  for (int i = 0; i < 2; ++i)
    ids.push_back(server_.SubmitOk(TestServer::SlowRequest(map_id_, 1, 0)).id());
  v1::SubmitPlanResponse response;
  grpc::ClientContext context;
  grpc::Status status =
      server_.jobs().SubmitPlan(&context, TestServer::SlowRequest(map_id_, 1, 0), &response);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::RESOURCE_EXHAUSTED);
  EXPECT_NE(status.error_message().find("queue is full"), std::string::npos);
  // Plan says the same before any event.
  grpc::ClientContext plan_context;
  auto reader = server_.jobs().Plan(&plan_context, TestServer::SlowRequest(map_id_, 1, 0));
  grpc::Status plan_status;
  EXPECT_TRUE(TestServer::ReadAll(*reader, &plan_status).empty());
  EXPECT_EQ(plan_status.error_code(), grpc::StatusCode::RESOURCE_EXHAUSTED);

  v1::CancelJobRequest cancel;
  cancel.set_id(running.id());
  v1::Job out;
  grpc::ClientContext cancel_context;
  ASSERT_TRUE(server_.jobs().CancelJob(&cancel_context, cancel, &out).ok());
  EXPECT_EQ(server_.WaitUntilFinal(ids[1]).state(), v1::JOB_STATE_SUCCEEDED);
  EXPECT_EQ(server_.WaitUntilFinal(ids[2]).state(), v1::JOB_STATE_SUCCEEDED);
}

TEST_F(CancelTest, TooManyWatchersOnOneJobIsResourceExhausted) {
  const v1::Job job = server_.SubmitOk(TestServer::SlowRequest(map_id_, 1000000, 1));
  server_.WaitForState(job.id(), v1::JOB_STATE_RUNNING);
  v1::WatchJobRequest request;
  request.set_id(job.id());
  grpc::ClientContext c1, c2, c3;
  auto w1 = server_.jobs().WatchJob(&c1, request);
  auto w2 = server_.jobs().WatchJob(&c2, request);
  v1::JobEvent event;
  ASSERT_TRUE(w1->Read(&event));
  ASSERT_TRUE(w2->Read(&event));
  auto w3 = server_.jobs().WatchJob(&c3, request);
  grpc::Status status;
  EXPECT_TRUE(TestServer::ReadAll(*w3, &status).empty());
  EXPECT_EQ(status.error_code(), grpc::StatusCode::RESOURCE_EXHAUSTED);
  v1::CancelJobRequest cancel;
  cancel.set_id(job.id());
  v1::Job out;
  grpc::ClientContext cancel_context;
  ASSERT_TRUE(server_.jobs().CancelJob(&cancel_context, cancel, &out).ok());
  for (auto* reader : {w1.get(), w2.get()}) {
    const std::vector<v1::JobEvent> rest = TestServer::ReadAll(*reader, &status);
    EXPECT_TRUE(status.ok());
    ASSERT_FALSE(rest.empty());
    EXPECT_EQ(rest.back().finished().state(), v1::JOB_STATE_CANCELLED);
  }
}

}  // namespace
}  // namespace swarmplan::testing
