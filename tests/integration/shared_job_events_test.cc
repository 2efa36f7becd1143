// Job events shared through Redis: appended by the replica running a job, read by followers
// after a cursor, capped, expiring, and a blocked reader woken by an append.
#include "server/shared_job_events.h"

#include <string>
#include <thread>
#include <vector>

#include "absl/time/clock.h"
#include "tests/integration/redis_server_test.h"

namespace swarmplan::testing {
namespace {

using server::SharedJobEvents;

v1::JobEvent Progress(const std::string& job_id, int iteration) {
  v1::JobEvent event;
  event.set_job_id(job_id);
  event.mutable_progress()->set_iteration(iteration);
  return event;
}

v1::JobEvent Finished(const std::string& job_id) {
  v1::JobEvent event;
  event.set_job_id(job_id);
  event.mutable_finished()->set_state(v1::JOB_STATE_SUCCEEDED);
  return event;
}

class SharedJobEventsTest : public RedisServerTest {
 protected:
  void SetUp() override {
    RedisServerTest::SetUp();
    if (IsSkipped() || HasFatalFailure()) return;
    absl::StatusOr<std::unique_ptr<server::RedisClient>> client =
        server::RedisClient::Connect(Endpoint());
    ASSERT_TRUE(client.ok()) << client.status();
    client_ = std::move(*client);
  }

  std::unique_ptr<server::RedisClient> client_;
};

TEST_F(SharedJobEventsTest, FollowersReadEveryEventAfterTheirCursorPerJob) {
  SharedJobEvents runner(*client_, "swarmplan:");
  SharedJobEvents follower(*client_, "swarmplan:");
  for (int i = 1; i <= 3; ++i) ASSERT_TRUE(runner.Append(Progress("job-a", i)).ok());
  ASSERT_TRUE(runner.Append(Finished("job-b")).ok());

  absl::StatusOr<std::vector<SharedJobEvents::Followed>> read =
      follower.Read({{"job-a", "0"}, {"job-b", "0"}, {"job-none", "0"}}, absl::ZeroDuration());
  ASSERT_TRUE(read.ok()) << read.status();
  ASSERT_EQ(read->size(), 4u);
  EXPECT_EQ((*read)[0].job_id, "job-a");
  EXPECT_EQ((*read)[0].event.progress().iteration(), 1);
  EXPECT_EQ((*read)[2].event.progress().iteration(), 3);
  EXPECT_EQ((*read)[3].job_id, "job-b");
  EXPECT_TRUE((*read)[3].event.has_finished());

  // After the cursor of the second event: only the third.
  read = follower.Read({{"job-a", (*read)[1].entry}}, absl::ZeroDuration());
  ASSERT_TRUE(read.ok()) << read.status();
  ASSERT_EQ(read->size(), 1u);
  EXPECT_EQ((*read)[0].event.progress().iteration(), 3);
  read = follower.Read({{"job-a", (*read)[0].entry}}, absl::ZeroDuration());
  ASSERT_TRUE(read.ok()) << read.status();
  EXPECT_TRUE(read->empty());
}

TEST_F(SharedJobEventsTest, ABlockedReaderWakesWhenAnotherReplicaAppends) {
  SharedJobEvents runner(*client_, "swarmplan:");
  SharedJobEvents follower(*client_, "swarmplan:");
  ASSERT_TRUE(runner.Append(Progress("job-a", 1)).ok());
  absl::StatusOr<std::vector<SharedJobEvents::Followed>> first =
      follower.Read({{"job-a", "0"}}, absl::ZeroDuration());
  ASSERT_TRUE(first.ok() && first->size() == 1u);

  std::thread append([&] {
    absl::SleepFor(absl::Milliseconds(200));
    ASSERT_TRUE(runner.Append(Finished("job-a")).ok());
  });
  absl::StatusOr<std::vector<SharedJobEvents::Followed>> next =
      follower.Read({{"job-a", first->front().entry}}, absl::Seconds(4));
  append.join();
  ASSERT_TRUE(next.ok()) << next.status();
  ASSERT_EQ(next->size(), 1u);
  EXPECT_TRUE(next->front().event.has_finished());

  // Nothing new: an empty answer after the wait.
  absl::StatusOr<std::vector<SharedJobEvents::Followed>> none =
      follower.Read({{"job-a", next->front().entry}}, absl::Milliseconds(50));
  ASSERT_TRUE(none.ok()) << none.status();
  EXPECT_TRUE(none->empty());
}

TEST_F(SharedJobEventsTest, AStreamKeepsAboutItsNewestEventsAndExpires) {
  SharedJobEvents runner(*client_, "swarmplan:", /*max_events=*/10, absl::Seconds(60));
  for (int i = 1; i <= 1000; ++i) ASSERT_TRUE(runner.Append(Progress("job-a", i)).ok());
  ASSERT_TRUE(runner.Append(Finished("job-a")).ok());
  absl::StatusOr<server::RedisReply> length = client_->Command({"XLEN", "swarmplan:events:job-a"});
  ASSERT_TRUE(length.ok()) << length.status();
  EXPECT_GE(length->integer, 10);
  EXPECT_LT(length->integer, 200) << "trimming is approximate, in whole nodes";
  absl::StatusOr<server::RedisReply> ttl = client_->Command({"PTTL", "swarmplan:events:job-a"});
  ASSERT_TRUE(ttl.ok()) << ttl.status();
  EXPECT_GT(ttl->integer, 0);
  EXPECT_LE(ttl->integer, 60000);

  absl::StatusOr<std::vector<SharedJobEvents::Followed>> read =
      SharedJobEvents(*client_, "swarmplan:").Read({{"job-a", "0"}}, absl::ZeroDuration(), 1000);
  ASSERT_TRUE(read.ok()) << read.status();
  ASSERT_FALSE(read->empty());
  EXPECT_TRUE(read->back().event.has_finished()) << "the newest event is always kept";
}

TEST_F(SharedJobEventsTest, AnEntryThatDoesNotParseStillMovesTheCursor) {
  absl::StatusOr<server::RedisReply> bad =
      client_->Command({"XADD", "swarmplan:events:job-a", "*", "e", "\xff\xff not a message"});
  ASSERT_TRUE(bad.ok()) << bad.status();
  ASSERT_TRUE(SharedJobEvents(*client_, "swarmplan:").Append(Finished("job-a")).ok());
  absl::StatusOr<std::vector<SharedJobEvents::Followed>> read =
      SharedJobEvents(*client_, "swarmplan:").Read({{"job-a", "0"}}, absl::ZeroDuration());
  ASSERT_TRUE(read.ok()) << read.status();
  ASSERT_EQ(read->size(), 2u);
  EXPECT_EQ((*read)[0].event.event_case(), v1::JobEvent::EVENT_NOT_SET);
  EXPECT_EQ((*read)[0].entry, bad->str);
  EXPECT_TRUE((*read)[1].event.has_finished());
  EXPECT_FALSE(SharedJobEvents(*client_, "swarmplan:").Append(v1::JobEvent()).ok())
      << "an event without a job id";
}

}  // namespace
}  // namespace swarmplan::testing
