// Replicas on one Redis: any replica serves any map and job, and the shared queue runs each job
// once, wherever it was submitted; events and cancellations cross replicas; the job of a killed
// replica finishes on another with the identical path.
#include <thread>

#include "absl/time/clock.h"
#include "tests/integration/redis_server_test.h"
#include "tests/integration/server_process.h"

namespace swarmplan::testing {
namespace {

class ReplicasTest : public RedisServerTest {
 protected:
  void SetUp() override {
    RedisServerTest::SetUp();
    if (redis_ == nullptr) return;
    for (int i = 0; i < kReplicas; ++i) AddReplica();
  }
  void TearDown() override { replicas_.clear(); }

  // A replica of one worker on the test's Redis.
  TestServer& AddReplica() {
    server::ServerConfig config = TestServer::DefaultConfig();
    config.store = redis_->url();
    config.job_lease = absl::Seconds(2);
    dirs_.push_back(std::make_unique<TempDir>());
    replicas_.push_back(std::make_unique<TestServer>(dirs_.back()->path(), config));
    return *replicas_.back();
  }
  TestServer& replica(int i) { return *replicas_[i]; }

  static constexpr int kReplicas = 3;
  std::vector<std::unique_ptr<TempDir>> dirs_;
  std::vector<std::unique_ptr<TestServer>> replicas_;
};

// Tests that need the replicas started in a given order.
class ReplicasInOrderTest : public ReplicasTest {
 protected:
  void SetUp() override { RedisServerTest::SetUp(); }
};

TEST_F(ReplicasTest, AMapUploadedOnOneReplicaIsPlannedOnFromAnother) {
  const std::string map_id = replica(0).UploadGrid("shared", 8, 5, 4);
  const v1::Job submitted = replica(2).SubmitOk(TestServer::Request(map_id, "astar", 7.5));
  const v1::Job done = replica(2).WaitUntilFinal(submitted.id());
  ASSERT_EQ(done.state(), v1::JOB_STATE_SUCCEEDED) << done.failure_reason();
  EXPECT_GT(done.result().raw_path_size(), 2);  // around the wall
  // Every replica answers with the same record.
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(replica(i).WaitUntilFinal(submitted.id()).ShortDebugString(),
              done.ShortDebugString());
  }
}

TEST_F(ReplicasTest, AJobSubmittedOnOneIsWatchedOnAnotherAndCancelledFromTheThird) {
  const std::string map_id = replica(0).UploadGrid("grid", 6, 4);
  const v1::Job submitted = replica(0).SubmitOk(TestServer::SlowRequest(map_id, 3000, 10));
  replica(1).WaitForState(submitted.id(), v1::JOB_STATE_RUNNING);

  v1::WatchJobRequest watch;
  watch.set_id(submitted.id());
  grpc::ClientContext watch_context;
  auto watcher = replica(1).jobs().WatchJob(&watch_context, watch);
  v1::JobEvent first;
  ASSERT_TRUE(watcher->Read(&first));  // the latest state first
  std::vector<v1::JobEvent> events = {first};
  std::thread reader([&] {
    v1::JobEvent event;
    while (watcher->Read(&event)) events.push_back(event);
  });
  // Progress from the replica running it reaches the watcher.
  const absl::Time give_up = absl::Now() + absl::Seconds(20);
  while (replica(1).GetJob(submitted.id()).progress().iteration() < 5 && absl::Now() < give_up) {
    absl::SleepFor(absl::Milliseconds(10));
  }

  v1::CancelJobRequest cancel;
  cancel.set_id(submitted.id());
  v1::Job cancelled;
  grpc::ClientContext cancel_context;
  const absl::Time asked = absl::Now();
  ASSERT_TRUE(replica(2).jobs().CancelJob(&cancel_context, cancel, &cancelled).ok());
  reader.join();
  const absl::Duration to_end = absl::Now() - asked;
  EXPECT_TRUE(watcher->Finish().ok());

  ASSERT_FALSE(events.empty());
  ASSERT_TRUE(events.back().has_finished()) << events.back().ShortDebugString();
  EXPECT_EQ(events.back().finished().state(), v1::JOB_STATE_CANCELLED);
  bool saw_progress = false;
  for (const v1::JobEvent& e : events) saw_progress = saw_progress || e.has_progress();
  EXPECT_TRUE(saw_progress);
  // Stopped long before its 30 s of iterations.
  EXPECT_LT(to_end, absl::Seconds(10));
  for (int i = 0; i < 3; ++i) {
    const v1::Job job = replica(i).WaitUntilFinal(submitted.id());
    EXPECT_EQ(job.state(), v1::JOB_STATE_CANCELLED);
    EXPECT_LT(job.result().iterations(), 3000);
  }
}

TEST_F(ReplicasTest, AWaitingJobCancelledOnAnotherReplicaNeverRuns) {
  const std::string map_id = replica(0).UploadGrid("grid", 6, 4);
  // Three long jobs keep the three workers busy; the fourth waits in the shared queue.
  std::vector<std::string> busy;
  for (int i = 0; i < 3; ++i) {
    busy.push_back(replica(0).SubmitOk(TestServer::SlowRequest(map_id, 3000, 10)).id());
  }
  for (const std::string& id : busy) replica(0).WaitForState(id, v1::JOB_STATE_RUNNING);
  const v1::Job waiting = replica(1).SubmitOk(TestServer::SlowRequest(map_id, 1, 0));
  EXPECT_EQ(waiting.state(), v1::JOB_STATE_QUEUED);

  v1::CancelJobRequest cancel;
  cancel.set_id(waiting.id());
  v1::Job cancelled;
  grpc::ClientContext context;
  ASSERT_TRUE(replica(2).jobs().CancelJob(&context, cancel, &cancelled).ok());
  EXPECT_EQ(cancelled.state(), v1::JOB_STATE_CANCELLED);
  const v1::Job on_submitter = replica(1).WaitUntilFinal(waiting.id());
  EXPECT_EQ(on_submitter.state(), v1::JOB_STATE_CANCELLED);
  EXPECT_FALSE(on_submitter.has_started_at());

  for (const std::string& id : busy) {
    v1::CancelJobRequest stop;
    stop.set_id(id);
    grpc::ClientContext stop_context;
    ASSERT_TRUE(replica(1).jobs().CancelJob(&stop_context, stop, &cancelled).ok());
  }
  for (const std::string& id : busy) {
    EXPECT_EQ(replica(2).WaitUntilFinal(id).state(), v1::JOB_STATE_CANCELLED);
  }
}

TEST_F(ReplicasTest, JobsSubmittedOnOneReplicaAllFinishOnce) {
  const std::string map_id = replica(0).UploadGrid("grid", 6, 4);
  std::vector<std::string> ids;
  for (int i = 0; i < 6; ++i) {
    // Two rounds of three: the queue holds at most 4 waiting jobs.
    if (i == 3) absl::SleepFor(absl::Milliseconds(300));
    ids.push_back(replica(0).SubmitOk(TestServer::SlowRequest(map_id, 20, 10)).id());
  }
  for (const std::string& id : ids) {
    const v1::Job job = replica(1).WaitUntilFinal(id);
    EXPECT_EQ(job.state(), v1::JOB_STATE_SUCCEEDED);
    EXPECT_EQ(job.result().iterations(), 20);
  }
}

TEST_F(ReplicasTest, AClientRequestIdNamesOneJobOnEveryReplica) {
  const std::string map_id = replica(0).UploadGrid("grid", 6, 4);
  v1::PlanRequest request = TestServer::SlowRequest(map_id, 5, 1);
  request.set_client_request_id("order-17");
  const v1::Job first = replica(0).SubmitOk(request);
  EXPECT_EQ(replica(1).SubmitOk(request).id(), first.id());
  EXPECT_EQ(replica(2).SubmitOk(request).id(), first.id());
  request.set_seed(request.seed() + 1);  // another request under the same id
  v1::SubmitPlanResponse response;
  grpc::ClientContext context;
  EXPECT_EQ(replica(2).jobs().SubmitPlan(&context, request, &response).error_code(),
            grpc::StatusCode::ALREADY_EXISTS);
}

TEST_F(ReplicasInOrderTest, APlanCallerLeavingCancelsItsJobOnTheReplicaRunningIt) {
  TestServer& caller = AddReplica();
  const std::string map_id = caller.UploadGrid("grid", 6, 4);
  // The caller's only worker is busy, so the job of its Plan call runs on the replica after it.
  const std::string busy = caller.SubmitOk(TestServer::SlowRequest(map_id, 3000, 10)).id();
  caller.WaitForState(busy, v1::JOB_STATE_RUNNING);
  TestServer& runner = AddReplica();

  std::string id;
  {
    grpc::ClientContext context;
    auto plan = caller.jobs().Plan(&context, TestServer::SlowRequest(map_id, 3000, 10));
    v1::JobEvent event;
    ASSERT_TRUE(plan->Read(&event));
    id = event.job_id();
    while (plan->Read(&event) && !event.has_started()) {
    }
    runner.WaitForState(id, v1::JOB_STATE_RUNNING);
    context.TryCancel();
  }
  const v1::Job ended = runner.WaitUntilFinal(id);
  EXPECT_EQ(ended.state(), v1::JOB_STATE_CANCELLED);
  EXPECT_LT(ended.result().iterations(), 3000);
  EXPECT_EQ(caller.GetJob(busy).state(), v1::JOB_STATE_RUNNING);  // only the Plan call's job

  v1::CancelJobRequest cancel;
  cancel.set_id(busy);
  v1::Job cancelled;
  grpc::ClientContext context;
  ASSERT_TRUE(runner.jobs().CancelJob(&context, cancel, &cancelled).ok());
  EXPECT_EQ(caller.WaitUntilFinal(busy).state(), v1::JOB_STATE_CANCELLED);
}

v1::Job GetJob(v1::JobService::Stub& jobs, const std::string& id) {
  v1::GetJobRequest request;
  request.set_id(id);
  v1::Job job;
  grpc::ClientContext context;
  EXPECT_TRUE(jobs.GetJob(&context, request, &job).ok());
  return job;
}

v1::Job WaitUntil(v1::JobService::Stub& jobs, const std::string& id, bool (*done)(v1::JobState)) {
  const absl::Time give_up = absl::Now() + absl::Seconds(90);
  v1::Job job = GetJob(jobs, id);
  while (!done(job.state()) && absl::Now() < give_up) {
    absl::SleepFor(absl::Milliseconds(20));
    job = GetJob(jobs, id);
  }
  return job;
}

std::string Submit(v1::JobService::Stub& jobs, const v1::PlanRequest& request) {
  v1::SubmitPlanResponse response;
  grpc::ClientContext context;
  const grpc::Status status = jobs.SubmitPlan(&context, request, &response);
  EXPECT_TRUE(status.ok()) << status.error_message();
  return response.job().id();
}

using ReplicaFailoverTest = RedisServerTest;

TEST_F(ReplicaFailoverTest, TheJobOfAKilledReplicaFinishesOnAnotherWithTheIdenticalPath) {
  const std::vector<std::string> args = {"--store=" + redis_->url(), "--job-lease=1s",
                                         "--workers=1"};
  absl::StatusOr<std::unique_ptr<ServerProcess>> doomed = ServerProcess::Start(args);
  ASSERT_TRUE(doomed.ok()) << doomed.status();

  v1::UploadMapRequest upload;
  upload.set_name("hall");
  upload.mutable_source()->mutable_files()->set_format("ascii");
  v1::MapFile* file = upload.mutable_source()->mutable_files()->add_files();
  file->set_name("hall.txt");
  std::string rows;
  for (int y = 0; y < 24; ++y) {
    std::string row(48, '.');
    if (y > 2 && y < 21) row.replace(10 + (y % 3) * 12, 4, "####");
    rows += row + "\n";
  }
  file->set_content(rows);
  v1::UploadMapResponse uploaded;
  {
    grpc::ClientContext context;
    ASSERT_TRUE((*doomed)->maps().UploadMap(&context, upload, &uploaded).ok());
  }
  // A swarm that runs for a second or more, so that it is still running when its replica dies.
  v1::PlanRequest request;
  request.set_map_id(uploaded.map().id());
  request.set_algorithm("pso");
  request.mutable_start()->set_x(1.5);
  request.mutable_start()->set_y(1.5);
  request.mutable_goal()->set_x(46.5);
  request.mutable_goal()->set_y(22.5);
  request.set_seed(77);
  (*request.mutable_parameters())["population"].set_int_value(1000);
  (*request.mutable_parameters())["iterations"].set_int_value(600);
  request.set_detached(true);
  const std::string id = Submit((*doomed)->jobs(), request);
  const v1::Job running =
      WaitUntil((*doomed)->jobs(), id, [](v1::JobState s) { return s != v1::JOB_STATE_QUEUED; });
  ASSERT_EQ(running.state(), v1::JOB_STATE_RUNNING) << running.ShortDebugString();
  const absl::Time killed = absl::Now();
  (*doomed)->Kill();

  absl::StatusOr<std::unique_ptr<ServerProcess>> survivor = ServerProcess::Start(args);
  ASSERT_TRUE(survivor.ok()) << survivor.status();
  const v1::Job rerun = WaitUntil((*survivor)->jobs(), id, IsFinalState);
  ASSERT_EQ(rerun.state(), v1::JOB_STATE_SUCCEEDED) << rerun.ShortDebugString();
  EXPECT_GT(rerun.started_at().seconds() * 1000000000LL + rerun.started_at().nanos(),
            absl::ToUnixNanos(killed));
  EXPECT_EQ(rerun.result().iterations(), 600);

  // The same request again, run from its start on the survivor: the same path, bit for bit.
  request.set_detached(false);
  const v1::Job reference =
      WaitUntil((*survivor)->jobs(), Submit((*survivor)->jobs(), request), IsFinalState);
  ASSERT_EQ(reference.state(), v1::JOB_STATE_SUCCEEDED);
  ASSERT_EQ(rerun.result().raw_path_size(), reference.result().raw_path_size());
  for (int i = 0; i < rerun.result().raw_path_size(); ++i) {
    EXPECT_EQ(rerun.result().raw_path(i).x(), reference.result().raw_path(i).x());
    EXPECT_EQ(rerun.result().raw_path(i).y(), reference.result().raw_path(i).y());
  }
  EXPECT_EQ(rerun.result().fitness(), reference.result().fitness());

  // Nothing is left queued or held: the killed replica's entry was taken over and acknowledged.
  absl::StatusOr<std::unique_ptr<server::RedisClient>> client =
      server::RedisClient::Connect(Endpoint());
  ASSERT_TRUE(client.ok()) << client.status();
  absl::StatusOr<server::RedisReply> queued = (*client)->Command({"XLEN", "swarmplan:queue"});
  ASSERT_TRUE(queued.ok()) << queued.status();
  EXPECT_EQ(queued->integer, 0);
  v1::ListJobsRequest unfinished;
  unfinished.add_states(v1::JOB_STATE_QUEUED);
  unfinished.add_states(v1::JOB_STATE_RUNNING);
  v1::ListJobsResponse listed;
  grpc::ClientContext context;
  ASSERT_TRUE((*survivor)->jobs().ListJobs(&context, unfinished, &listed).ok());
  EXPECT_EQ(listed.jobs_size(), 0);
}

}  // namespace
}  // namespace swarmplan::testing
