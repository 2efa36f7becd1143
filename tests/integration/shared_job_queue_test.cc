// The shared queue on a real redis-server: jobs taken once, leases that run out and are taken
// over as the next attempt, writes that only the holder of the current attempt can make, the
// cluster-wide capacity, cancellation before and while a job runs.
#include "server/shared_job_queue.h"

#include <set>
#include <string>
#include <thread>
#include <vector>

#include "absl/time/clock.h"
#include "server/redis_store.h"
#include "tests/integration/redis_server_test.h"

namespace swarmplan::testing {
namespace {

using server::JobLease;
using server::SharedJobQueue;
using server::StoredJob;

constexpr int kQueued = 1;
constexpr int kRunning = 2;
constexpr int kSucceeded = 3;
constexpr int kCancelled = 5;

StoredJob Job(const std::string& id, int state, const std::string& record) {
  StoredJob job;
  job.id = id;
  job.state = state;
  job.record = record;
  job.created_at = absl::FromUnixMicros(1'700'000'000'000'000);
  if (state == kSucceeded || state == kCancelled) job.finished_at = absl::Now();
  return job;
}

class SharedJobQueueTest : public RedisServerTest {
 protected:
  void SetUp() override {
    RedisServerTest::SetUp();
    if (IsSkipped() || HasFatalFailure()) return;
    absl::StatusOr<std::unique_ptr<server::RedisStore>> store =
        server::RedisStore::Open(Endpoint());
    ASSERT_TRUE(store.ok()) << store.status();
    store_ = std::move(*store);
  }

  // A replica's view of the queue.
  std::unique_ptr<SharedJobQueue> Replica(const std::string& name,
                                          absl::Duration lease = absl::Seconds(10),
                                          int64_t capacity = 64) {
    absl::StatusOr<std::unique_ptr<SharedJobQueue>> queue =
        SharedJobQueue::Open(store_->client(), "swarmplan:", {name, lease, capacity});
    EXPECT_TRUE(queue.ok()) << queue.status();
    return queue.ok() ? std::move(*queue) : nullptr;
  }

  std::optional<JobLease> TakeNow(SharedJobQueue& queue) {
    absl::StatusOr<std::optional<JobLease>> lease = queue.Take(absl::Milliseconds(1));
    EXPECT_TRUE(lease.ok()) << lease.status();
    return lease.ok() ? *lease : std::nullopt;
  }

  StoredJob Stored(const std::string& id) {
    absl::StatusOr<StoredJob> job = store_->GetJob(id);
    EXPECT_TRUE(job.ok()) << job.status();
    return job.ok() ? *job : StoredJob{};
  }

  int64_t Waiting(SharedJobQueue& queue) {
    absl::StatusOr<int64_t> n = queue.Waiting();
    EXPECT_TRUE(n.ok()) << n.status();
    return n.ok() ? *n : -1;
  }

  std::unique_ptr<server::RedisStore> store_;
};

TEST_F(SharedJobQueueTest, APushedJobIsRecordedAndTakenOnceInOrder) {
  std::unique_ptr<SharedJobQueue> a = Replica("a");
  std::unique_ptr<SharedJobQueue> b = Replica("b");
  EXPECT_EQ(*a->Push(Job("job-1", kQueued, "r1")), 0);
  EXPECT_EQ(*b->Push(Job("job-2", kQueued, "r2")), 1);
  EXPECT_EQ(Stored("job-1").record, "r1");
  EXPECT_EQ(Stored("job-2").state, kQueued);
  EXPECT_EQ(Waiting(*a), 2);

  std::optional<JobLease> first = TakeNow(*b);
  ASSERT_TRUE(first.has_value());
  EXPECT_EQ(first->job_id, "job-1");
  EXPECT_EQ(first->attempt, 1);
  EXPECT_FALSE(first->reclaimed);
  std::optional<JobLease> second = TakeNow(*a);
  ASSERT_TRUE(second.has_value());
  EXPECT_EQ(second->job_id, "job-2");
  EXPECT_FALSE(TakeNow(*a).has_value());
  EXPECT_FALSE(TakeNow(*b).has_value());
  EXPECT_EQ(Waiting(*a), 0);
}

TEST_F(SharedJobQueueTest, ManyReplicasTakeEveryJobExactlyOnce) {
  std::vector<std::unique_ptr<SharedJobQueue>> replicas;
  for (const char* name : {"a", "b", "c"}) replicas.push_back(Replica(name));
  constexpr int kJobs = 60;
  for (int i = 0; i < kJobs; ++i) {
    ASSERT_TRUE(replicas[0]->Push(Job("job-" + std::to_string(i), kQueued, "r")).ok());
  }
  std::vector<std::vector<std::string>> taken(replicas.size());
  std::vector<std::thread> threads;
  for (size_t r = 0; r < replicas.size(); ++r) {
    threads.emplace_back([&, r] {
      while (true) {
        absl::StatusOr<std::optional<JobLease>> lease = replicas[r]->Take(absl::Milliseconds(50));
        if (!lease.ok() || !lease->has_value()) return;
        taken[r].push_back((*lease)->job_id);
      }
    });
  }
  for (std::thread& t : threads) t.join();
  std::multiset<std::string> all;
  for (const auto& ids : taken) all.insert(ids.begin(), ids.end());
  EXPECT_EQ(all.size(), static_cast<size_t>(kJobs));
  EXPECT_EQ(std::set<std::string>(all.begin(), all.end()).size(), static_cast<size_t>(kJobs));
}

TEST_F(SharedJobQueueTest, CapacityCountsWaitingJobsOfEveryReplica) {
  std::unique_ptr<SharedJobQueue> a = Replica("a", absl::Seconds(10), 2);
  std::unique_ptr<SharedJobQueue> b = Replica("b", absl::Seconds(10), 2);
  ASSERT_TRUE(a->Push(Job("job-1", kQueued, "r")).ok());
  ASSERT_TRUE(b->Push(Job("job-2", kQueued, "r")).ok());
  absl::StatusOr<int64_t> full = a->Push(Job("job-3", kQueued, "r"));
  EXPECT_TRUE(absl::IsResourceExhausted(full.status())) << full.status();
  EXPECT_NE(full.status().message().find("--queue-capacity"), std::string::npos);
  EXPECT_TRUE(absl::IsNotFound(store_->GetJob("job-3").status())) << "a refused job is recorded";
  EXPECT_TRUE(b->Push(Job("job-4", kQueued, "r"), /*ignore_capacity=*/true).ok());

  // A taken job no longer waits: its place is free.
  ASSERT_TRUE(TakeNow(*a).has_value());
  ASSERT_TRUE(TakeNow(*b).has_value());
  EXPECT_EQ(Waiting(*a), 1);
  EXPECT_TRUE(a->Push(Job("job-5", kQueued, "r")).ok());
}

TEST_F(SharedJobQueueTest, AJobWhoseLeaseRunsOutIsTakenOverAsTheNextAttempt) {
  const absl::Duration lease = absl::Milliseconds(300);
  std::unique_ptr<SharedJobQueue> a = Replica("a", lease);
  std::unique_ptr<SharedJobQueue> b = Replica("b", lease);
  ASSERT_TRUE(a->Push(Job("job-1", kQueued, "queued")).ok());
  std::optional<JobLease> first = TakeNow(*a);
  ASSERT_TRUE(first.has_value());
  EXPECT_TRUE(*a->Record(*first, Job("job-1", kRunning, "running on a")));

  // While a renews, b cannot take the job.
  for (int i = 0; i < 6; ++i) {
    absl::SleepFor(lease / 3);
    ASSERT_TRUE(*a->Renew(*first));
    EXPECT_FALSE(TakeNow(*b).has_value());
  }
  // a stops renewing (as if it died): after the lease, b takes the job as attempt 2.
  absl::SleepFor(lease + absl::Milliseconds(100));
  std::optional<JobLease> second = TakeNow(*b);
  ASSERT_TRUE(second.has_value());
  EXPECT_EQ(second->job_id, "job-1");
  EXPECT_EQ(second->attempt, 2);
  EXPECT_TRUE(second->reclaimed);

  // a's attempt is over: it can neither renew nor write, even its result.
  EXPECT_FALSE(*a->Renew(*first));
  EXPECT_FALSE(*a->Record(*first, Job("job-1", kSucceeded, "result of a")));
  EXPECT_EQ(Stored("job-1").record, "running on a");

  EXPECT_TRUE(*b->Record(*second, Job("job-1", kRunning, "running on b")));
  EXPECT_TRUE(*b->Record(*second, Job("job-1", kSucceeded, "result of b")));
  EXPECT_EQ(Stored("job-1").record, "result of b");
  EXPECT_EQ(Stored("job-1").state, kSucceeded);
  // Finished: out of the queue for good, and its lease gone with it.
  absl::SleepFor(lease + absl::Milliseconds(100));
  EXPECT_FALSE(TakeNow(*a).has_value());
  EXPECT_FALSE(*b->Record(*second, Job("job-1", kSucceeded, "written twice")));
  EXPECT_EQ(Stored("job-1").record, "result of b");
  EXPECT_EQ(Waiting(*a), 0);
}

TEST_F(SharedJobQueueTest, AReleasedJobGoesBackToTheEndOfTheQueue) {
  std::unique_ptr<SharedJobQueue> a = Replica("a");
  std::unique_ptr<SharedJobQueue> b = Replica("b");
  ASSERT_TRUE(a->Push(Job("job-1", kQueued, "r")).ok());
  ASSERT_TRUE(a->Push(Job("job-2", kQueued, "r")).ok());
  std::optional<JobLease> held = TakeNow(*a);
  ASSERT_TRUE(held.has_value());
  ASSERT_EQ(held->job_id, "job-1");
  EXPECT_TRUE(*a->Release(*held, Job("job-1", kQueued, "queued again")));
  EXPECT_FALSE(*a->Renew(*held));
  EXPECT_EQ(Stored("job-1").record, "queued again");

  std::optional<JobLease> next = TakeNow(*b);
  ASSERT_TRUE(next.has_value());
  EXPECT_EQ(next->job_id, "job-2");
  std::optional<JobLease> again = TakeNow(*b);
  ASSERT_TRUE(again.has_value());
  EXPECT_EQ(again->job_id, "job-1");
  EXPECT_EQ(again->attempt, 2);
  EXPECT_FALSE(again->reclaimed);
}

TEST_F(SharedJobQueueTest, CancellingAWaitingJobTakesItOutAndRecordsIt) {
  std::unique_ptr<SharedJobQueue> a = Replica("a");
  std::unique_ptr<SharedJobQueue> b = Replica("b");
  ASSERT_TRUE(a->Push(Job("job-1", kQueued, "r")).ok());
  ASSERT_TRUE(a->Push(Job("job-2", kQueued, "r")).ok());
  EXPECT_TRUE(*b->RemoveWaiting(Job("job-1", kCancelled, "cancelled")));
  EXPECT_EQ(Stored("job-1").state, kCancelled);
  EXPECT_FALSE(*b->RemoveWaiting(Job("job-1", kCancelled, "twice")));
  EXPECT_EQ(Stored("job-1").record, "cancelled");
  EXPECT_EQ(Waiting(*a), 1);

  // A running job is not removed: its replica is asked to stop it instead.
  std::optional<JobLease> running = TakeNow(*a);
  ASSERT_TRUE(running.has_value());
  ASSERT_EQ(running->job_id, "job-2");
  EXPECT_FALSE(*b->RemoveWaiting(Job("job-2", kCancelled, "cancelled")));
  EXPECT_EQ(Stored("job-2").state, kQueued);
  EXPECT_EQ(*a->CancelRequested({"job-2", "job-1"}), (std::vector<bool>{false, false}));
  ASSERT_TRUE(b->RequestCancel("job-2").ok());
  EXPECT_EQ(*a->CancelRequested({"job-2", "job-1"}), (std::vector<bool>{true, false}));
  EXPECT_TRUE(*a->Record(*running, Job("job-2", kCancelled, "stopped")));
  EXPECT_EQ(*a->CancelRequested({"job-2"}), (std::vector<bool>{false}));
  EXPECT_FALSE(TakeNow(*b).has_value());
}

TEST_F(SharedJobQueueTest, AnEntryOfAJobThatFinishedMeanwhileIsDropped) {
  const absl::Duration lease = absl::Milliseconds(200);
  std::unique_ptr<SharedJobQueue> a = Replica("a", lease);
  std::unique_ptr<SharedJobQueue> b = Replica("b", lease);
  ASSERT_TRUE(a->Push(Job("job-1", kQueued, "r")).ok());
  std::optional<JobLease> held = TakeNow(*a);
  ASSERT_TRUE(held.has_value());
  // The job's record is final (written outside the queue, as a store migration could), while
  // its entry still waits to be taken over.
  ASSERT_TRUE(store_->PutJob(Job("job-1", kSucceeded, "done")).ok());
  absl::SleepFor(lease + absl::Milliseconds(100));
  EXPECT_FALSE(TakeNow(*b).has_value());
  EXPECT_EQ(Waiting(*b), 0);
  EXPECT_EQ(Stored("job-1").record, "done");
}

TEST_F(SharedJobQueueTest, TheQueueSurvivesARestartOfRedis) {
  std::unique_ptr<SharedJobQueue> a = Replica("a");
  ASSERT_TRUE(a->Push(Job("job-1", kQueued, "r")).ok());
  ASSERT_TRUE(a->Push(Job("job-2", kQueued, "r")).ok());
  std::optional<JobLease> held = TakeNow(*a);
  ASSERT_TRUE(held.has_value());
  redis_->Kill();
  ASSERT_TRUE(redis_->Restart().ok());
  EXPECT_TRUE(*a->Renew(*held));
  std::optional<JobLease> next = TakeNow(*a);
  ASSERT_TRUE(next.has_value());
  EXPECT_EQ(next->job_id, "job-2");
  EXPECT_TRUE(*a->Record(*held, Job("job-1", kSucceeded, "done")));
}

}  // namespace
}  // namespace swarmplan::testing
