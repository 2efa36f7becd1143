// The Store contract, checked against both stores: the embedded SQLite one and the shared Redis
// one (a real redis-server on a free loopback port; skipped when it is not installed).
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <memory>
#include <string>

#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "google/protobuf/util/message_differencer.h"
#include "server/config.h"
#include "server/redis_client.h"
#include "server/redis_store.h"
#include "server/sqlite_store.h"
#include "server/store_url.h"
#include "tests/integration/redis_server_test.h"
#include "tests/integration/redis_test_server.h"
#include "tests/integration/test_server.h"

namespace swarmplan::testing {
namespace {

using server::JobCursor;
using server::StoredJob;
using server::StoredMap;

const absl::Time kT0 = absl::FromUnixSeconds(1'800'000'000);

StoredJob Job(const std::string& id, int state, absl::Time created, const std::string& crid = "",
              absl::Time finished = absl::InfiniteFuture()) {
  StoredJob job;
  job.id = id;
  job.state = state;
  job.record = "record of " + id + std::string("\0\xff", 2);
  job.created_at = created;
  job.finished_at = finished;
  job.client_request_id = crid;
  return job;
}

std::vector<std::string> Ids(const std::vector<StoredJob>& jobs) {
  std::vector<std::string> ids;
  for (const StoredJob& j : jobs) ids.push_back(j.id);
  return ids;
}

class StoreTest : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    if (GetParam() == "redis") {
      absl::StatusOr<std::unique_ptr<RedisTestServer>> redis = RedisTestServer::Start(dir_.path());
      if (absl::IsFailedPrecondition(redis.status())) GTEST_SKIP() << redis.status().message();
      ASSERT_TRUE(redis.ok()) << redis.status();
      redis_ = std::move(*redis);
    }
    Reopen();
  }

  void Reopen() {
    store_.reset();
    server::ServerConfig config;
    config.store = redis_ != nullptr ? redis_->url() : "sqlite:" + dir_.path();
    absl::StatusOr<std::unique_ptr<server::Store>> store = server::OpenStore(config);
    ASSERT_TRUE(store.ok()) << store.status();
    store_ = std::move(*store);
  }

  server::Store& store() { return *store_; }

  TempDir dir_;
  std::unique_ptr<RedisTestServer> redis_;
  std::unique_ptr<server::Store> store_;
};

std::vector<std::string> MapIds(const std::vector<StoredMap>& maps) {
  std::vector<std::string> ids;
  for (const StoredMap& m : maps) ids.push_back(m.id);
  return ids;
}

TEST_P(StoreTest, MapsArePutReadListedOldestFirstAndDeleted) {
  const std::string source("binary\0source", 13);
  ASSERT_TRUE(store().PutMap({"map-b", "second", "ascii", "h2", source, kT0, "info-b"}).ok());
  ASSERT_TRUE(store().PutMap({"map-a", "first", "ascii", "h1", "s1", kT0, "info-a"}).ok());
  ASSERT_TRUE(
      store().PutMap({"map-c", "third", "png", "h3", "s3", kT0 - absl::Seconds(1), ""}).ok());
  ASSERT_TRUE(
      store().PutMap({"map-d", "first", "ascii", "h1", "s1", kT0 + absl::Seconds(1), "i"}).ok());

  absl::StatusOr<StoredMap> b = store().GetMap("map-b");
  ASSERT_TRUE(b.ok()) << b.status();
  EXPECT_EQ(b->name, "second");
  EXPECT_EQ(b->source, source);
  EXPECT_EQ(b->created_at, kT0);
  EXPECT_EQ(b->info, "info-b");
  absl::StatusOr<StoredMap> b_info = store().GetMapInfo("map-b");
  ASSERT_TRUE(b_info.ok()) << b_info.status();
  EXPECT_EQ(b_info->content_hash, "h2");
  EXPECT_EQ(b_info->info, "info-b");
  EXPECT_TRUE(b_info->source.empty());
  EXPECT_TRUE(store().GetMapInfo("map-c")->info.empty());

  // Oldest first, then by id; pages continue after a cursor.
  EXPECT_EQ(MapIds(*store().ListMaps(nullptr, 10)),
            (std::vector<std::string>{"map-c", "map-a", "map-b", "map-d"}));
  const server::MapCursor after_a{absl::ToUnixMicros(kT0), "map-a"};
  EXPECT_EQ(MapIds(*store().ListMaps(&after_a, 1)), std::vector<std::string>{"map-b"});
  EXPECT_TRUE(store().ListMaps(nullptr, 10)->front().source.empty());
  EXPECT_EQ(*store().CountMaps(), 4);

  // Put again: the map is replaced.
  ASSERT_TRUE(store().PutMap({"map-a", "renamed", "ascii", "h1", "s1", kT0, "info-a"}).ok());
  EXPECT_EQ(store().GetMapInfo("map-a")->name, "renamed");
  EXPECT_EQ(*store().CountMaps(), 4);

  EXPECT_TRUE(store().DeleteMap("map-a").ok());
  EXPECT_TRUE(absl::IsNotFound(store().DeleteMap("map-a")));
  EXPECT_TRUE(absl::IsNotFound(store().GetMap("map-a").status()));
  EXPECT_TRUE(absl::IsNotFound(store().GetMapInfo("map-a").status()));
  EXPECT_EQ(MapIds(*store().ListMaps(nullptr, 10)),
            (std::vector<std::string>{"map-c", "map-b", "map-d"}));
  EXPECT_EQ(*store().CountMaps(), 3);
}

std::vector<int64_t> Versions(const std::vector<StoredMap>& maps) {
  std::vector<int64_t> versions;
  for (const StoredMap& m : maps) versions.push_back(m.version);
  return versions;
}

TEST_P(StoreTest, EachNameNumbersItsVersionsAndNeverReusesANumber) {
  auto put = [&](const std::string& id, const std::string& name, int64_t version = 0) {
    absl::StatusOr<int64_t> v =
        store().PutMap({id, name, "ascii", "h-" + id, "s", kT0, "i", version});
    EXPECT_TRUE(v.ok()) << v.status();
    return v.value_or(-1);
  };
  EXPECT_EQ(put("map-1", "dock"), 1);
  EXPECT_EQ(put("map-2", "dock"), 2);
  EXPECT_EQ(put("map-x", "yard"), 1);
  EXPECT_EQ(put("map-3", "dock"), 3);
  // Put again with version 0, the map keeps its version; a stated version is stored as given.
  EXPECT_EQ(put("map-2", "dock"), 2);
  EXPECT_EQ(store().GetMap("map-2")->version, 2);
  EXPECT_EQ(store().GetMapInfo("map-3")->version, 3);

  EXPECT_EQ(store().FindMapVersion("dock", 0)->id, "map-3");
  EXPECT_EQ(store().FindMapVersion("dock", 2)->id, "map-2");
  EXPECT_EQ(store().FindMapVersion("yard", 0)->id, "map-x");
  EXPECT_TRUE(store().FindMapVersion("dock", 2)->source.empty());
  EXPECT_TRUE(absl::IsNotFound(store().FindMapVersion("dock", 4).status()));
  EXPECT_TRUE(absl::IsNotFound(store().FindMapVersion("dockyard", 0).status()));
  EXPECT_EQ(Versions(*store().ListMapVersions("dock", 0, 10)), (std::vector<int64_t>{1, 2, 3}));
  EXPECT_EQ(MapIds(*store().ListMapVersions("dock", 1, 1)), std::vector<std::string>{"map-2"});

  // Deleting the latest makes the one before it the latest; its number is not given again.
  ASSERT_TRUE(store().DeleteMap("map-3").ok());
  EXPECT_EQ(store().FindMapVersion("dock", 0)->id, "map-2");
  EXPECT_TRUE(absl::IsNotFound(store().FindMapVersion("dock", 3).status()));
  EXPECT_EQ(put("map-4", "dock"), 4);
  EXPECT_EQ(Versions(*store().ListMapVersions("dock", 0, 10)), (std::vector<int64_t>{1, 2, 4}));
  Reopen();
  EXPECT_EQ(put("map-5", "dock"), 5);
  EXPECT_EQ(store().FindMapVersion("dock", 0)->id, "map-5");
}

TEST_P(StoreTest, AJobPutAgainReplacesItsRecordAndMovesBetweenStates) {
  ASSERT_TRUE(store().PutJob(Job("job-1", 1, kT0, "order-7")).ok());
  ASSERT_TRUE(store().PutJob(Job("job-1", 2, kT0, "order-7")).ok());
  StoredJob finished = Job("job-1", 3, kT0, "order-7", kT0 + absl::Seconds(5));
  finished.record = "final";
  ASSERT_TRUE(store().PutJob(finished).ok());

  absl::StatusOr<StoredJob> got = store().GetJob("job-1");
  ASSERT_TRUE(got.ok()) << got.status();
  EXPECT_EQ(got->state, 3);
  EXPECT_EQ(got->record, "final");
  EXPECT_EQ(got->finished_at, kT0 + absl::Seconds(5));
  EXPECT_EQ(got->client_request_id, "order-7");
  EXPECT_TRUE(got->client_request_id_known);

  EXPECT_TRUE(store().ListJobs(nullptr, {1}, 10)->empty());
  EXPECT_TRUE(store().ListJobs(nullptr, {2}, 10)->empty());
  EXPECT_EQ(Ids(*store().ListJobs(nullptr, {3}, 10)), std::vector<std::string>{"job-1"});
  EXPECT_TRUE(store().LoadJobsToRecover()->empty());
  EXPECT_EQ(*store().CountFinishedJobs(), 1);
  EXPECT_TRUE(absl::IsNotFound(store().GetJob("job-2").status()));
}

TEST_P(StoreTest, AClientRequestIdFindsItsNewestJob) {
  ASSERT_TRUE(store().PutJob(Job("job-old", 1, kT0, "order-1")).ok());
  ASSERT_TRUE(store().PutJob(Job("job-new", 1, kT0 + absl::Seconds(1), "order-1")).ok());
  ASSERT_TRUE(store().PutJob(Job("job-other", 1, kT0 + absl::Seconds(2), "order-2")).ok());
  absl::StatusOr<StoredJob> found = store().FindJobByClientRequestId("order-1");
  ASSERT_TRUE(found.ok()) << found.status();
  EXPECT_EQ(found->id, "job-new");
  EXPECT_TRUE(absl::IsNotFound(store().FindJobByClientRequestId("order-3").status()));
}

TEST_P(StoreTest, UnfinishedJobsAreRecoveredOldestFirst) {
  ASSERT_TRUE(store().PutJob(Job("job-b", 2, kT0 + absl::Seconds(2))).ok());
  ASSERT_TRUE(store().PutJob(Job("job-a", 1, kT0 + absl::Seconds(1))).ok());
  ASSERT_TRUE(store().PutJob(Job("job-done", 3, kT0, "", kT0 + absl::Seconds(3))).ok());
  absl::StatusOr<std::vector<StoredJob>> recover = store().LoadJobsToRecover();
  ASSERT_TRUE(recover.ok()) << recover.status();
  EXPECT_EQ(Ids(*recover), (std::vector<std::string>{"job-a", "job-b"}));
}

TEST_P(StoreTest, ListingIsNewestFirstThenByIdAndContinuesAfterACursor) {
  // Two jobs share a creation time: the id breaks the tie.
  ASSERT_TRUE(store().PutJob(Job("job-1", 1, kT0)).ok());
  ASSERT_TRUE(
      store().PutJob(Job("job-2", 3, kT0 + absl::Seconds(1), "", kT0 + absl::Seconds(9))).ok());
  ASSERT_TRUE(store().PutJob(Job("job-3", 2, kT0 + absl::Seconds(1))).ok());
  ASSERT_TRUE(store().PutJob(Job("job-4", 1, kT0 + absl::Seconds(2))).ok());

  EXPECT_EQ(Ids(*store().ListJobs(nullptr, {}, 10)),
            (std::vector<std::string>{"job-4", "job-3", "job-2", "job-1"}));
  EXPECT_EQ(Ids(*store().ListJobs(nullptr, {}, 2)), (std::vector<std::string>{"job-4", "job-3"}));
  const JobCursor after_job3{absl::ToUnixMicros(kT0 + absl::Seconds(1)), "job-3"};
  EXPECT_EQ(Ids(*store().ListJobs(&after_job3, {}, 10)),
            (std::vector<std::string>{"job-2", "job-1"}));
  EXPECT_EQ(Ids(*store().ListJobs(nullptr, {1, 2}, 10)),
            (std::vector<std::string>{"job-4", "job-3", "job-1"}));
  EXPECT_EQ(Ids(*store().ListJobs(&after_job3, {1, 2}, 1)), (std::vector<std::string>{"job-1"}));
  EXPECT_EQ(Ids(*store().ListJobs(nullptr, {1, 1}, 10)),
            (std::vector<std::string>{"job-4", "job-1"}));
}

TEST_P(StoreTest, FinishedJobsAreDeletedByAgeAndOldestFirst) {
  for (int i = 0; i < 5; ++i) {
    ASSERT_TRUE(store()
                    .PutJob(Job("job-" + std::to_string(i), 3, kT0, "order-" + std::to_string(i),
                                kT0 + absl::Seconds(10 - i)))
                    .ok());
  }
  ASSERT_TRUE(store().PutJob(Job("job-running", 2, kT0)).ok());
  EXPECT_EQ(*store().CountFinishedJobs(), 5);

  // Finished at 10, 9, 8, 7, 6 s: the two before 8 s are job-4 and job-3.
  absl::StatusOr<std::vector<std::string>> expired =
      store().DeleteJobsFinishedBefore(kT0 + absl::Seconds(8));
  ASSERT_TRUE(expired.ok()) << expired.status();
  EXPECT_EQ(*expired, (std::vector<std::string>{"job-4", "job-3"}));
  absl::StatusOr<std::vector<std::string>> oldest = store().DeleteOldestFinishedJobs(2);
  ASSERT_TRUE(oldest.ok()) << oldest.status();
  EXPECT_EQ(*oldest, (std::vector<std::string>{"job-2", "job-1"}));

  EXPECT_EQ(*store().CountFinishedJobs(), 1);
  EXPECT_EQ(Ids(*store().ListJobs(nullptr, {}, 10)),
            (std::vector<std::string>{"job-running", "job-0"}));
  EXPECT_TRUE(absl::IsNotFound(store().FindJobByClientRequestId("order-1").status()));
  EXPECT_TRUE(store().FindJobByClientRequestId("order-0").ok());
  EXPECT_TRUE(store().DeleteOldestFinishedJobs(0)->empty());
}

TEST_P(StoreTest, EverythingWrittenIsThereAfterTheStoreIsOpenedAgain) {
  ASSERT_TRUE(store().PutMap({"map-a", "a", "ascii", "h", "s", kT0, "i"}).ok());
  ASSERT_TRUE(store().PutJob(Job("job-1", 3, kT0, "order-1", kT0 + absl::Seconds(1))).ok());
  if (redis_ != nullptr) {
    // A crash of Redis itself: with appendfsync always every acknowledged write is in the AOF.
    redis_->Kill();
    ASSERT_TRUE(redis_->Restart().ok());
  }
  Reopen();
  EXPECT_TRUE(store().GetMap("map-a").ok());
  absl::StatusOr<StoredJob> job = store().FindJobByClientRequestId("order-1");
  ASSERT_TRUE(job.ok()) << job.status();
  EXPECT_EQ(job->record, Job("job-1", 3, kT0).record);
}

INSTANTIATE_TEST_SUITE_P(BothStores, StoreTest, ::testing::Values("sqlite", "redis"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return info.param;
                         });

TEST(StoreUrlTest, BadStoreUrlsAreRefusedNamingTheFlag) {
  for (const char* url : {"postgres://x", "sqlite:", "redis://", "redis://h:0", "redis://h:99999",
                          "redis://h:6379/x", "redis://user:pw@h:6379"}) {
    server::ServerConfig config;
    config.store = url;
    absl::StatusOr<std::unique_ptr<server::Store>> store = server::OpenStore(config);
    ASSERT_FALSE(store.ok()) << url;
    EXPECT_TRUE(absl::IsInvalidArgument(store.status())) << url << ": " << store.status();
    EXPECT_NE(store.status().message().find("--store"), std::string::npos) << store.status();
  }
  absl::StatusOr<server::RedisEndpoint> endpoint =
      server::ParseRedisUrl("redis://cache.local:6380/2", "--store");
  ASSERT_TRUE(endpoint.ok()) << endpoint.status();
  EXPECT_EQ(endpoint->host, "cache.local");
  EXPECT_EQ(endpoint->port, 6380);
  EXPECT_EQ(endpoint->db, 2);
}

TEST(StoreUrlTest, ARedisWithAPasswordTakesItFromTheFileOnly) {
  TempDir dir;
  absl::StatusOr<std::unique_ptr<RedisTestServer>> redis =
      RedisTestServer::Start(dir.path(), "s3cret-pass");
  if (absl::IsFailedPrecondition(redis.status())) GTEST_SKIP() << redis.status().message();
  ASSERT_TRUE(redis.ok()) << redis.status();

  server::ServerConfig config;
  config.store = (*redis)->url();
  EXPECT_FALSE(server::OpenStore(config).ok());  // NOAUTH

  config.store_password_file = dir.path() + "/absent";
  absl::StatusOr<std::unique_ptr<server::Store>> store = server::OpenStore(config);
  EXPECT_TRUE(absl::IsFailedPrecondition(store.status())) << store.status();

  const std::string wrong = dir.path() + "/wrong";
  FILE* f = fopen(wrong.c_str(), "w");
  fputs("not-it\n", f);
  fclose(f);
  config.store_password_file = wrong;
  store = server::OpenStore(config);
  EXPECT_TRUE(absl::IsPermissionDenied(store.status())) << store.status();

  const std::string right = dir.path() + "/password";
  f = fopen(right.c_str(), "w");
  fputs("s3cret-pass\n", f);
  fclose(f);
  config.store_password_file = right;
  store = server::OpenStore(config);
  ASSERT_TRUE(store.ok()) << store.status();
  EXPECT_TRUE((*store)->PutMap({"map-a", "a", "ascii", "h", "s", kT0, "i"}).ok());
  EXPECT_EQ(server::DescribeStore(config).find("s3cret"), std::string::npos);
}

// Servers on a real redis-server whose AOF is in dir_; config_ points at it.
class RedisStoreServerTest : public RedisServerTest {
 protected:
  void SetUp() override {
    RedisServerTest::SetUp();
    if (redis_ != nullptr) config_.store = redis_->url();
  }

  server::ServerConfig config_ = TestServer::DefaultConfig();
};

TEST_F(RedisStoreServerTest, AcknowledgedMapsAndFinishedJobsSurviveAKill9OfRedis) {
  std::string map_id;
  v1::Job finished;
  {
    TestServer server(dir_.path(), config_);
    map_id = server.UploadGrid("kept", 12, 6, 5);
    const v1::Job job = server.SubmitOk(TestServer::Request(map_id, "astar", 11.5));
    finished = server.WaitUntilFinal(job.id());
    ASSERT_EQ(finished.state(), v1::JOB_STATE_SUCCEEDED);
  }
  redis_->Kill();
  ASSERT_TRUE(redis_->Restart().ok());

  TestServer server(dir_.path(), config_);
  v1::GetMapRequest get;
  get.set_id(map_id);
  v1::GetMapResponse map;
  grpc::ClientContext context;
  ASSERT_TRUE(server.maps().GetMap(&context, get, &map).ok());
  EXPECT_EQ(map.map().name(), "kept");
  const v1::Job again = server.GetJob(finished.id());
  EXPECT_EQ(again.state(), v1::JOB_STATE_SUCCEEDED);
  EXPECT_TRUE(
      google::protobuf::util::MessageDifferencer::Equals(again.result(), finished.result()));
}

// One page of the versions of map `name`, through `server`'s ListMaps.
v1::ListMapsResponse VersionsOf(TestServer& server, const std::string& name) {
  v1::ListMapsRequest request;
  request.set_name(name);
  v1::ListMapsResponse versions;
  grpc::ClientContext context;
  const grpc::Status status = server.maps().ListMaps(&context, request, &versions);
  EXPECT_TRUE(status.ok()) << status.error_message();
  return versions;
}

TEST_F(RedisStoreServerTest, ReplicasNumberTheVersionsOfANameTogether) {
  TempDir dir_b;
  TestServer a(dir_.path(), config_);
  TestServer b(dir_b.path(), config_);
  const std::string first = a.UploadGrid("bay", 6, 4);
  const std::string second = b.UploadGrid("bay", 6, 4, /*wall_x=*/2);
  const std::string third = a.UploadGrid("bay", 6, 4, /*wall_x=*/3);
  // Replica b sees a's newest version as the latest, and numbers the next one after it.
  EXPECT_EQ(b.UploadGrid("bay", 6, 4, /*wall_x=*/3), third);
  const std::string fourth = b.UploadGrid("bay", 6, 4);
  const v1::ListMapsResponse versions = VersionsOf(a, "bay");
  ASSERT_EQ(versions.maps_size(), 4);
  const std::vector<std::string> ids = {first, second, third, fourth};
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(versions.maps(i).id(), ids[i]);
    EXPECT_EQ(versions.maps(i).version(), i + 1);
  }
}

TEST_F(RedisStoreServerTest, MapsStoredWithoutAVersionAreNumberedInUploadOrderAtStart) {
  v1::MapSource source;
  v1::OccupancyGridData* grid = source.mutable_structured()->mutable_occupancy_grid();
  grid->set_width(5);
  grid->set_height(3);
  grid->set_cells(std::string(15, '\0'));
  {
    // What a store kept before maps had versions: no version field, no per-name index.
    absl::StatusOr<std::unique_ptr<server::RedisClient>> redis =
        server::RedisClient::Connect(Endpoint());
    ASSERT_TRUE(redis.ok()) << redis.status();
    for (const auto& [id, created] : {std::pair{"map-late", "00001800000000000002"},
                                      std::pair{"map-early", "00001800000000000001"}}) {
      ASSERT_TRUE((*redis)
                      ->Command({"HSET", std::string("swarmplan:map:") + id, "name", "legacy",
                                 "format", "structured", "content_hash", id, "source",
                                 source.SerializeAsString(), "created_us", created})
                      .ok());
      ASSERT_TRUE(
          (*redis)->Command({"ZADD", "swarmplan:maps", "0", absl::StrCat(created, ":", id)}).ok());
    }
  }
  TestServer server(dir_.path(), config_);
  const v1::ListMapsResponse versions = VersionsOf(server, "legacy");
  ASSERT_EQ(versions.maps_size(), 2);
  EXPECT_EQ(versions.maps(0).id(), "map-early");
  EXPECT_EQ(versions.maps(0).version(), 1);
  EXPECT_EQ(versions.maps(0).width(), 5);
  EXPECT_EQ(versions.maps(1).id(), "map-late");
  EXPECT_EQ(versions.maps(1).version(), 2);
  EXPECT_EQ(server.UploadGrid("legacy", 7, 3), server.UploadGrid("legacy", 7, 3));
  v1::GetMapRequest latest;
  latest.set_name("legacy");
  v1::GetMapResponse response;
  grpc::ClientContext get_context;
  ASSERT_TRUE(server.maps().GetMap(&get_context, latest, &response).ok());
  EXPECT_EQ(response.map().version(), 3);
}

TEST_F(RedisStoreServerTest, AMapUploadedOnOneReplicaIsPlannedOnFromAnotherAndDeletedForBoth) {
  TempDir dir_b;
  TestServer a(dir_.path(), config_);
  TestServer b(dir_b.path(), config_);

  const std::string map_id = a.UploadGrid("shared", 12, 6, 5);
  const v1::Job job = b.SubmitOk(TestServer::Request(map_id, "astar", 11.5));
  const v1::Job finished = b.WaitUntilFinal(job.id());
  EXPECT_EQ(finished.state(), v1::JOB_STATE_SUCCEEDED);
  EXPECT_GT(finished.result().raw_path_size(), 2);  // around the wall
  EXPECT_EQ(a.GetJob(job.id()).state(), v1::JOB_STATE_SUCCEEDED);

  {
    v1::DeleteMapRequest request;
    request.set_id(map_id);
    v1::DeleteMapResponse response;
    grpc::ClientContext context;
    ASSERT_TRUE(a.maps().DeleteMap(&context, request, &response).ok());
  }
  v1::GetMapRequest get;
  get.set_id(map_id);
  v1::GetMapResponse got;
  grpc::ClientContext context;
  EXPECT_EQ(b.maps().GetMap(&context, get, &got).error_code(), grpc::StatusCode::NOT_FOUND);
  v1::SubmitPlanResponse refused;
  grpc::ClientContext submit_context;
  EXPECT_EQ(b.jobs()
                .SubmitPlan(&submit_context, TestServer::Request(map_id, "astar", 11.5), &refused)
                .error_code(),
            grpc::StatusCode::NOT_FOUND);
}

TEST_F(RedisStoreServerTest, WhileRedisIsDownCallsAnswerUnavailableAndTheServerRecoversAfter) {
  TestServer server(dir_.path(), config_);
  const std::string kept = server.UploadGrid("kept", 12, 6, 5);

  redis_->Kill();
  v1::UploadMapRequest upload;
  upload.set_name("during-outage");
  upload.mutable_source()->mutable_files()->set_format("ascii");
  v1::MapFile* file = upload.mutable_source()->mutable_files()->add_files();
  file->set_name("m.txt");
  file->set_content("....\n.#..\n");
  {
    v1::UploadMapResponse response;
    grpc::ClientContext context;
    const grpc::Status status = server.maps().UploadMap(&context, upload, &response);
    EXPECT_EQ(status.error_code(), grpc::StatusCode::UNAVAILABLE) << status.error_message();
    EXPECT_NE(status.error_message().find("redis"), std::string::npos) << status.error_message();
  }
  {
    v1::SubmitPlanResponse response;
    grpc::ClientContext context;
    EXPECT_EQ(server.jobs()
                  .SubmitPlan(&context, TestServer::Request(kept, "astar", 11.5), &response)
                  .error_code(),
              grpc::StatusCode::UNAVAILABLE);
  }

  ASSERT_TRUE(redis_->Restart().ok());
  {
    v1::UploadMapResponse response;
    grpc::ClientContext context;
    const grpc::Status status = server.maps().UploadMap(&context, upload, &response);
    EXPECT_TRUE(status.ok()) << status.error_message();
  }
  const v1::Job job = server.SubmitOk(TestServer::Request(kept, "astar", 11.5));
  EXPECT_EQ(server.WaitUntilFinal(job.id()).state(), v1::JOB_STATE_SUCCEEDED);
}

TEST(SqliteStoreTest, MapsStoredWithoutADescriptionOrVersionAreDescribedAndNumberedAtStart) {
  TempDir dir;
  v1::MapSource source;
  v1::OccupancyGridData* grid = source.mutable_structured()->mutable_occupancy_grid();
  grid->set_width(12);
  grid->set_height(6);
  grid->set_resolution(1.0);
  grid->set_cells(std::string(72, '\0'));
  {
    // The maps table of the previous version: no info column.
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open((dir.path() + "/swarmplan.db").c_str(), &db), SQLITE_OK);
    ASSERT_EQ(sqlite3_exec(db,
                           "CREATE TABLE maps (id TEXT PRIMARY KEY, name TEXT NOT NULL, format "
                           "TEXT NOT NULL, content_hash TEXT NOT NULL, source BLOB NOT NULL, "
                           "created_us INTEGER NOT NULL);",
                           nullptr, nullptr, nullptr),
              SQLITE_OK);
    // Two uploads under one name, the newer one first in the table.
    for (const char* row : {"('map-new', 'old', 'structured', 'hash2', ?, 1800000000000001)",
                            "('map-old', 'old', 'structured', 'hash', ?, 1800000000000000)"}) {
      sqlite3_stmt* insert = nullptr;
      ASSERT_EQ(sqlite3_prepare_v2(db, (std::string("INSERT INTO maps VALUES ") + row).c_str(), -1,
                                   &insert, nullptr),
                SQLITE_OK);
      const std::string bytes = source.SerializeAsString();
      sqlite3_bind_blob(insert, 1, bytes.data(), static_cast<int>(bytes.size()), SQLITE_TRANSIENT);
      ASSERT_EQ(sqlite3_step(insert), SQLITE_DONE);
      sqlite3_finalize(insert);
    }
    sqlite3_close(db);
  }
  TestServer server(dir.path());
  v1::ListMapsRequest list;
  v1::ListMapsResponse maps;
  grpc::ClientContext context;
  ASSERT_TRUE(server.maps().ListMaps(&context, list, &maps).ok());
  ASSERT_EQ(maps.maps_size(), 2);
  EXPECT_EQ(maps.maps(0).id(), "map-old");
  EXPECT_EQ(maps.maps(0).kind(), v1::MAP_KIND_OCCUPANCY_GRID);
  EXPECT_EQ(maps.maps(0).width(), 12);
  EXPECT_EQ(maps.maps(0).height(), 6);
  // Numbered in upload order.
  EXPECT_EQ(maps.maps(0).version(), 1);
  EXPECT_EQ(maps.maps(1).id(), "map-new");
  EXPECT_EQ(maps.maps(1).version(), 2);
  const v1::Job job = server.SubmitOk(TestServer::Request("map-old", "astar", 11.5));
  EXPECT_EQ(server.WaitUntilFinal(job.id()).state(), v1::JOB_STATE_SUCCEEDED);
}

}  // namespace
}  // namespace swarmplan::testing
