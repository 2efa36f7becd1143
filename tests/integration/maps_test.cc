// MapService over loopback: upload (structured and files), idempotent re-upload, versions, get,
// list with pagination, delete.
#include "tests/integration/test_server.h"

namespace swarmplan::testing {
namespace {

class MapsTest : public ::testing::Test {
 protected:
  TempDir dir_;
  TestServer server_{dir_.path()};
};

v1::UploadMapRequest AsciiUpload(const std::string& name, const std::string& art) {
  v1::UploadMapRequest request;
  request.set_name(name);
  v1::MapFiles* files = request.mutable_source()->mutable_files();
  files->set_format("ascii");
  v1::MapFile* file = files->add_files();
  file->set_name(name + ".txt");
  file->set_content(art);
  return request;
}

TEST_F(MapsTest, UploadFromFileBytesParsesAndDescribesTheMap) {
  v1::UploadMapResponse response;
  grpc::ClientContext context;
  ASSERT_TRUE(server_.maps()
                  .UploadMap(&context, AsciiUpload("corridor", "....\n.##.\n....\n"), &response)
                  .ok());
  EXPECT_TRUE(response.created());
  const v1::MapInfo& info = response.map();
  EXPECT_FALSE(info.id().empty());
  EXPECT_EQ(info.name(), "corridor");
  EXPECT_EQ(info.kind(), v1::MAP_KIND_OCCUPANCY_GRID);
  EXPECT_EQ(info.width(), 4);
  EXPECT_EQ(info.height(), 3);
  EXPECT_EQ(info.obstacle_count(), 2);
  EXPECT_EQ(info.format(), "ascii");
  EXPECT_EQ(info.content_hash().size(), 64u);
  EXPECT_GT(info.created_at().seconds(), 0);
}

TEST_F(MapsTest, ReuploadingIdenticalContentUnderTheSameNameIsIdempotent) {
  v1::UploadMapResponse first, second, renamed;
  grpc::ClientContext c1, c2, c3;
  ASSERT_TRUE(server_.maps().UploadMap(&c1, AsciiUpload("a", "..\n..\n"), &first).ok());
  ASSERT_TRUE(server_.maps().UploadMap(&c2, AsciiUpload("a", "..\n..\n"), &second).ok());
  ASSERT_TRUE(server_.maps().UploadMap(&c3, AsciiUpload("b", "..\n..\n"), &renamed).ok());
  EXPECT_FALSE(second.created());
  EXPECT_EQ(second.map().id(), first.map().id());
  EXPECT_TRUE(renamed.created());
  EXPECT_NE(renamed.map().id(), first.map().id());
}

v1::MapInfo GetVersion(TestServer& server, const std::string& name, int64_t version,
                       grpc::StatusCode expected = grpc::StatusCode::OK) {
  v1::GetMapRequest request;
  request.set_name(name);
  request.set_version(version);
  v1::GetMapResponse response;
  grpc::ClientContext context;
  const grpc::Status status = server.maps().GetMap(&context, request, &response);
  EXPECT_EQ(status.error_code(), expected) << status.error_message();
  return response.map();
}

std::vector<int64_t> ListedVersions(TestServer& server, const std::string& name, int page_size) {
  std::vector<int64_t> versions;
  v1::ListMapsRequest request;
  request.set_name(name);
  request.set_page_size(page_size);
  do {
    v1::ListMapsResponse page;
    grpc::ClientContext context;
    const grpc::Status status = server.maps().ListMaps(&context, request, &page);
    EXPECT_TRUE(status.ok()) << status.error_message();
    if (!status.ok()) break;
    for (const v1::MapInfo& map : page.maps()) {
      EXPECT_EQ(map.name(), name);
      versions.push_back(map.version());
    }
    request.set_page_token(page.next_page_token());
  } while (!request.page_token().empty());
  return versions;
}

TEST_F(MapsTest, NewContentUnderANameIsItsNextVersionAndJobsKeepTheVersionTheyPlannedOn) {
  const std::string first = server_.UploadGrid("floor", 8, 4);
  const v1::Job on_first = server_.SubmitOk(TestServer::Request(first, "astar", 7.5));
  ASSERT_EQ(server_.WaitUntilFinal(on_first.id()).state(), v1::JOB_STATE_SUCCEEDED);

  // A wall across the floor: the second version, with its own id.
  const std::string second = server_.UploadGrid("floor", 8, 4, /*wall_x=*/4);
  EXPECT_NE(second, first);
  const v1::Job on_second = server_.SubmitOk(TestServer::Request(second, "astar", 7.5));
  const v1::Job second_done = server_.WaitUntilFinal(on_second.id());
  ASSERT_EQ(second_done.state(), v1::JOB_STATE_SUCCEEDED);
  EXPECT_EQ(second_done.map_name(), "floor");
  EXPECT_EQ(second_done.map_version(), 2);

  // The first job still reads version 1 and its straight path, after the newer upload.
  const v1::Job first_done = server_.GetJob(on_first.id());
  EXPECT_EQ(first_done.request().map_id(), first);
  EXPECT_EQ(first_done.map_name(), "floor");
  EXPECT_EQ(first_done.map_version(), 1);
  EXPECT_NEAR(first_done.result().raw_metrics().length(), 7.0, 1e-9);
  EXPECT_GT(second_done.result().raw_metrics().length(), 7.5);

  EXPECT_EQ(GetVersion(server_, "floor", 0).id(), second);
  EXPECT_EQ(GetVersion(server_, "floor", 1).id(), first);
  EXPECT_EQ(GetVersion(server_, "floor", 1).version(), 1);
  GetVersion(server_, "floor", 3, grpc::StatusCode::NOT_FOUND);
  GetVersion(server_, "ceiling", 0, grpc::StatusCode::NOT_FOUND);
  GetVersion(server_, "floor", -1, grpc::StatusCode::INVALID_ARGUMENT);

  // The latest version's content again is idempotent; an older version's content becomes the
  // next version (a rollback).
  EXPECT_EQ(server_.UploadGrid("floor", 8, 4, /*wall_x=*/4), second);
  const std::string rolled_back = server_.UploadGrid("floor", 8, 4);
  EXPECT_NE(rolled_back, first);
  EXPECT_EQ(GetVersion(server_, "floor", 0).version(), 3);
  EXPECT_EQ(ListedVersions(server_, "floor", 1), (std::vector<int64_t>{1, 2, 3}));

  // Deleting the latest makes the one before it the latest; numbers are not reused.
  v1::DeleteMapRequest remove;
  remove.set_id(rolled_back);
  v1::DeleteMapResponse removed;
  grpc::ClientContext delete_context;
  ASSERT_TRUE(server_.maps().DeleteMap(&delete_context, remove, &removed).ok());
  EXPECT_EQ(GetVersion(server_, "floor", 0).id(), second);
  server_.UploadGrid("floor", 8, 4);
  EXPECT_EQ(ListedVersions(server_, "floor", 2), (std::vector<int64_t>{1, 2, 4}));
}

TEST_F(MapsTest, GetMapTakesAnIdOrANameAndListingTokensKeepTheirFilter) {
  const std::string id = server_.UploadGrid("dock", 4, 4);
  server_.UploadGrid("dock", 4, 4, /*wall_x=*/1);
  auto get = [&](const std::string& map_id, const std::string& name, int64_t version) {
    v1::GetMapRequest request;
    request.set_id(map_id);
    request.set_name(name);
    request.set_version(version);
    v1::GetMapResponse response;
    grpc::ClientContext context;
    return server_.maps().GetMap(&context, request, &response);
  };
  const grpc::Status both = get(id, "dock", 0);
  EXPECT_EQ(both.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_NE(both.error_message().find("name"), std::string::npos) << both.error_message();
  const grpc::Status neither = get("", "", 0);
  EXPECT_EQ(neither.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_NE(neither.error_message().find("id"), std::string::npos) << neither.error_message();
  const grpc::Status version_alone = get(id, "", 2);
  EXPECT_EQ(version_alone.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_NE(version_alone.error_message().find("version"), std::string::npos);

  v1::ListMapsRequest by_name;
  by_name.set_name("dock");
  by_name.set_page_size(1);
  v1::ListMapsResponse page;
  grpc::ClientContext c1;
  ASSERT_TRUE(server_.maps().ListMaps(&c1, by_name, &page).ok());
  ASSERT_FALSE(page.next_page_token().empty());
  v1::ListMapsRequest all;
  all.set_page_token(page.next_page_token());
  v1::ListMapsResponse refused;
  grpc::ClientContext c2;
  const grpc::Status other_filter = server_.maps().ListMaps(&c2, all, &refused);
  EXPECT_EQ(other_filter.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_NE(other_filter.error_message().find("page_token"), std::string::npos);
}

TEST_F(MapsTest, GetMapReturnsTheDescriptionAndOnRequestTheSource) {
  const std::string id = server_.UploadGrid("grid", 8, 4, 3);
  v1::GetMapRequest request;
  request.set_id(id);
  v1::GetMapResponse plain, full;
  grpc::ClientContext c1, c2;
  ASSERT_TRUE(server_.maps().GetMap(&c1, request, &plain).ok());
  EXPECT_EQ(plain.map().id(), id);
  EXPECT_EQ(plain.map().obstacle_count(), 3);
  EXPECT_FALSE(plain.has_source());
  request.set_include_source(true);
  ASSERT_TRUE(server_.maps().GetMap(&c2, request, &full).ok());
  ASSERT_TRUE(full.source().has_structured());
  EXPECT_EQ(full.source().structured().occupancy_grid().cells().size(), 32u);
}

TEST_F(MapsTest, ListMapsPagesThroughEveryMapOldestFirst) {
  std::vector<std::string> ids;
  for (int i = 0; i < 5; ++i) ids.push_back(server_.UploadGrid("m" + std::to_string(i), 3, 3));
  std::vector<std::string> listed;
  std::string token;
  int pages = 0;
  do {
    v1::ListMapsRequest request;
    request.set_page_size(2);
    request.set_page_token(token);
    v1::ListMapsResponse response;
    grpc::ClientContext context;
    ASSERT_TRUE(server_.maps().ListMaps(&context, request, &response).ok());
    EXPECT_LE(response.maps_size(), 2);
    for (const v1::MapInfo& m : response.maps()) listed.push_back(m.id());
    token = response.next_page_token();
    ++pages;
  } while (!token.empty() && pages < 10);
  EXPECT_EQ(listed, ids);
  EXPECT_EQ(pages, 3);
}

TEST_F(MapsTest, ListMapsContinuesAfterThePagesLastMapWasDeleted) {
  std::vector<std::string> ids;
  for (int i = 0; i < 5; ++i) ids.push_back(server_.UploadGrid("m" + std::to_string(i), 3, 3));
  v1::ListMapsRequest request;
  request.set_page_size(2);
  v1::ListMapsResponse first;
  {
    grpc::ClientContext context;
    ASSERT_TRUE(server_.maps().ListMaps(&context, request, &first).ok());
  }
  ASSERT_EQ(first.maps_size(), 2);
  ASSERT_FALSE(first.next_page_token().empty());
  for (const std::string& id : {ids[1], ids[2]}) {  // the page's last map and the next one
    v1::DeleteMapRequest del;
    del.set_id(id);
    v1::DeleteMapResponse deleted;
    grpc::ClientContext context;
    ASSERT_TRUE(server_.maps().DeleteMap(&context, del, &deleted).ok());
  }
  request.set_page_token(first.next_page_token());
  request.set_page_size(10);
  v1::ListMapsResponse rest;
  grpc::ClientContext context;
  ASSERT_TRUE(server_.maps().ListMaps(&context, request, &rest).ok());
  ASSERT_EQ(rest.maps_size(), 2);
  EXPECT_EQ(rest.maps(0).id(), ids[3]);
  EXPECT_EQ(rest.maps(1).id(), ids[4]);
  EXPECT_TRUE(rest.next_page_token().empty());
}

TEST(MapsPagesTest, APageStopsBeforeItWouldExceedTheByteBudgetAndTheTokenContinues) {
  TempDir dir;
  server::ServerConfig config = TestServer::DefaultConfig();
  config.max_page_bytes = 2048;
  TestServer server(dir.path(), config);
  std::vector<std::string> ids;
  for (int i = 0; i < 12; ++i) {
    ids.push_back(server.UploadGrid(std::string(200, static_cast<char>('a' + i)), 3, 3));
  }
  std::vector<std::string> listed;
  std::string token;
  int pages = 0;
  do {
    v1::ListMapsRequest request;  // page_size 0: up to 100 maps, but not 2048 bytes
    request.set_page_token(token);
    v1::ListMapsResponse response;
    grpc::ClientContext context;
    ASSERT_TRUE(server.maps().ListMaps(&context, request, &response).ok());
    EXPECT_LE(response.ByteSizeLong(), 2048u + response.next_page_token().size() + 8);
    ASSERT_GT(response.maps_size(), 0);
    for (const v1::MapInfo& m : response.maps()) listed.push_back(m.id());
    token = response.next_page_token();
    ++pages;
  } while (!token.empty() && pages < 20);
  EXPECT_EQ(listed, ids);
  EXPECT_GE(pages, 3);
}

TEST_F(MapsTest, DeleteMapRemovesItAndASecondDeleteIsNotFound) {
  const std::string id = server_.UploadGrid("gone", 3, 3);
  v1::DeleteMapRequest request;
  request.set_id(id);
  v1::DeleteMapResponse response;
  grpc::ClientContext c1, c2, c3;
  ASSERT_TRUE(server_.maps().DeleteMap(&c1, request, &response).ok());
  EXPECT_EQ(server_.maps().DeleteMap(&c2, request, &response).error_code(),
            grpc::StatusCode::NOT_FOUND);
  v1::GetMapRequest get;
  get.set_id(id);
  v1::GetMapResponse got;
  grpc::Status status = server_.maps().GetMap(&c3, get, &got);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::NOT_FOUND);
  EXPECT_NE(status.error_message().find(id), std::string::npos);
}

TEST_F(MapsTest, StructuredShapeWorldAndTerrainUpload) {
  v1::UploadMapRequest world;
  world.set_name("world");
  v1::ShapeWorldData* w = world.mutable_source()->mutable_structured()->mutable_shape_world();
  w->mutable_max()->set_x(10);
  w->mutable_max()->set_y(10);
  v1::Circle* c = w->add_circles();
  c->mutable_center()->set_x(5);
  c->mutable_center()->set_y(5);
  c->set_radius(1);
  v1::UploadMapResponse response;
  grpc::ClientContext c1;
  ASSERT_TRUE(server_.maps().UploadMap(&c1, world, &response).ok());
  EXPECT_EQ(response.map().kind(), v1::MAP_KIND_SHAPE_WORLD);
  EXPECT_EQ(response.map().obstacle_count(), 1);

  v1::UploadMapRequest terrain;
  terrain.set_name("hills");
  v1::TerrainData* t = terrain.mutable_source()->mutable_structured()->mutable_terrain();
  t->set_width(3);
  t->set_depth(2);
  for (double h : {1.0, 2.0, 3.0, 2.0, 1.0, 0.0}) t->add_heights(h);
  grpc::ClientContext c2;
  ASSERT_TRUE(server_.maps().UploadMap(&c2, terrain, &response).ok());
  EXPECT_EQ(response.map().kind(), v1::MAP_KIND_TERRAIN);
  EXPECT_EQ(response.map().width(), 3);
  EXPECT_EQ(response.map().height(), 2);
  // The extent in world coordinates: the first and the last cell centre (unit cells, corner at
  // the origin), from the lowest ground to the ceiling.
  EXPECT_EQ(response.map().min().x(), 0.5);
  EXPECT_EQ(response.map().min().y(), 0.5);
  EXPECT_EQ(response.map().min().z(), 0.0);
  EXPECT_EQ(response.map().max().x(), 2.5);
  EXPECT_EQ(response.map().max().y(), 1.5);
  EXPECT_EQ(response.map().max().z(), 6.0);
}

}  // namespace
}  // namespace swarmplan::testing
