// The bad-input table: each wrong field, malformed file per format, oversized map, unknown
// algorithm, parameters out of range, start/goal blocked or outside -> the right code and a
// message naming what is wrong; afterwards the server is healthy and nothing stored is lost.
#include <functional>

#include "tests/integration/test_server.h"

namespace swarmplan::testing {
namespace {

server::ServerConfig SmallLimits() {
  server::ServerConfig config = TestServer::DefaultConfig();
  config.max_map_cells = 10000;
  config.max_iterations = 5000;
  config.max_population = 50;
  config.max_job_time = absl::Seconds(60);
  return config;
}

struct PlanCase {
  const char* name;
  std::function<void(v1::PlanRequest&)> mutate;
  grpc::StatusCode code;
  const char* message;  // a substring the message must contain
};

struct UploadCase {
  const char* name;
  std::function<void(v1::UploadMapRequest&)> mutate;
  grpc::StatusCode code;
  const char* message;
};

void SetFile(v1::UploadMapRequest& r, const std::string& format, const std::string& name,
             const std::string& content) {
  r.mutable_source()->clear_structured();
  v1::MapFiles* files = r.mutable_source()->mutable_files();
  files->set_format(format);
  files->clear_files();
  v1::MapFile* f = files->add_files();
  f->set_name(name);
  f->set_content(content);
}

class BadInputTest : public ::testing::Test {
 protected:
  void SetUp() override {
    grid_id_ = server_.UploadGrid("grid", 6, 4, 3);
    v1::UploadMapRequest world;
    world.set_name("world");
    v1::ShapeWorldData* w = world.mutable_source()->mutable_structured()->mutable_shape_world();
    w->mutable_max()->set_x(10);
    w->mutable_max()->set_y(10);
    v1::UploadMapResponse response;
    grpc::ClientContext context;
    ASSERT_TRUE(server_.maps().UploadMap(&context, world, &response).ok());
    world_id_ = response.map().id();
  }

  // Every map still there, the server still answers and plans.
  void ExpectHealthyAndNothingLost() {
    v1::ListMapsResponse maps;
    grpc::ClientContext context;
    ASSERT_TRUE(server_.maps().ListMaps(&context, {}, &maps).ok());
    ASSERT_EQ(maps.maps_size(), 2);
    EXPECT_EQ(maps.maps(0).id(), grid_id_);
    EXPECT_EQ(maps.maps(1).id(), world_id_);
    const v1::Job job =
        server_.WaitUntilFinal(server_.SubmitOk(TestServer::Request(grid_id_, "astar", 5.5)).id());
    EXPECT_EQ(job.state(), v1::JOB_STATE_SUCCEEDED);
  }

  TempDir dir_;
  TestServer server_{dir_.path(), SmallLimits()};
  std::string grid_id_;
  std::string world_id_;
};

TEST_F(BadInputTest, EveryBadPlanRequestGetsTheRightCodeAndNamesTheField) {
  using C = grpc::StatusCode;
  const std::string world = world_id_;
  auto param = [](const char* name, int64_t v) {
    return [name, v](v1::PlanRequest& r) { (*r.mutable_parameters())[name].set_int_value(v); };
  };
  const std::vector<PlanCase> cases = {
      {"no map", [](auto& r) { r.clear_map_id(); }, C::INVALID_ARGUMENT, "map_id"},
      {"unknown map", [](auto& r) { r.set_map_id("map-nope"); }, C::NOT_FOUND, "map-nope"},
      {"no algorithm", [](auto& r) { r.clear_algorithm(); }, C::INVALID_ARGUMENT, "algorithm"},
      {"unknown algorithm", [](auto& r) { r.set_algorithm("warp-drive"); }, C::NOT_FOUND,
       "warp-drive"},
      {"unknown parameter", param("nonsense", 1), C::INVALID_ARGUMENT, "nonsense"},
      {"parameter out of range", param("iterations", 0), C::INVALID_ARGUMENT, "iterations"},
      {"parameter of the wrong type",
       [](auto& r) { (*r.mutable_parameters())["iterations"].set_string_value("many"); },
       C::INVALID_ARGUMENT, "iterations"},
      {"parameter without a value",
       [](auto& r) { (*r.mutable_parameters())["iterations"].Clear(); }, C::INVALID_ARGUMENT,
       "iterations"},
      {"population above the server limit", param("population", 51), C::INVALID_ARGUMENT,
       "population"},
      {"ants above the server's population limit",
       [](auto& r) {
         r.set_algorithm("aco-grid");
         r.clear_parameters();
         (*r.mutable_parameters())["ants"].set_int_value(51);
       },
       C::INVALID_ARGUMENT, "ants"},
      {"negative clearance", [](auto& r) { r.set_clearance(-1); }, C::INVALID_ARGUMENT,
       "clearance"},
      {"negative preferred clearance",
       [](auto& r) { r.mutable_preferences()->set_preferred_clearance(-1); }, C::INVALID_ARGUMENT,
       "preferences.preferred_clearance"},
      {"too many alternatives", [](auto& r) { r.set_alternatives(9); }, C::INVALID_ARGUMENT,
       "alternatives"},
      {"turning radius not finite",
       [](auto& r) { r.mutable_preferences()->set_turning_radius(std::nan("")); },
       C::INVALID_ARGUMENT, "preferences.turning_radius"},
      {"negative max_iterations", [](auto& r) { r.mutable_limits()->set_max_iterations(-1); },
       C::INVALID_ARGUMENT, "limits.max_iterations"},
      {"max_iterations above the server limit",
       [](auto& r) { r.mutable_limits()->set_max_iterations(5001); }, C::INVALID_ARGUMENT,
       "limits.max_iterations"},
      {"negative time budget",
       [](auto& r) { r.mutable_limits()->mutable_time_budget()->set_seconds(-1); },
       C::INVALID_ARGUMENT, "limits.time_budget"},
      {"time budget above the server limit",
       [](auto& r) { r.mutable_limits()->mutable_time_budget()->set_seconds(61); },
       C::INVALID_ARGUMENT, "limits.time_budget"},
      {"time budget nanos above a second",
       [](auto& r) { r.mutable_limits()->mutable_time_budget()->set_nanos(2000000000); },
       C::INVALID_ARGUMENT, "limits.time_budget"},
      {"time budget with seconds and nanos of opposite signs",
       [](auto& r) {
         r.mutable_limits()->mutable_time_budget()->set_seconds(1);
         r.mutable_limits()->mutable_time_budget()->set_nanos(-1);
       },
       C::INVALID_ARGUMENT, "limits.time_budget"},
      {"progress interval nanos below minus a second",
       [](auto& r) { r.mutable_progress()->mutable_min_interval()->set_nanos(-1000000000); },
       C::INVALID_ARGUMENT, "progress.min_interval"},
      {"negative progress interval",
       [](auto& r) { r.mutable_progress()->mutable_min_interval()->set_nanos(-5); },
       C::INVALID_ARGUMENT, "progress.min_interval"},
      {"negative progress rate", [](auto& r) { r.mutable_progress()->set_every_iterations(-2); },
       C::INVALID_ARGUMENT, "progress.every_iterations"},
      {"unknown smoothing", [](auto& r) { r.set_smoothing("sandpaper"); }, C::INVALID_ARGUMENT,
       "smoothing"},
      {"start outside the map", [](auto& r) { r.mutable_start()->set_x(-3); },
       C::FAILED_PRECONDITION, "start"},
      {"goal outside the map", [](auto& r) { r.mutable_goal()->set_y(40); }, C::FAILED_PRECONDITION,
       "goal"},
      {"goal inside the wall", [](auto& r) { r.mutable_goal()->set_x(3.5); },
       C::FAILED_PRECONDITION, "goal"},
      {"start not finite", [](auto& r) { r.mutable_start()->set_x(std::nan("")); },
       C::INVALID_ARGUMENT, "start"},
      {"algorithm cannot plan on this map kind",
       [world](auto& r) {
         r.set_algorithm("astar");
         r.clear_parameters();
         r.set_map_id(world);
       },
       C::FAILED_PRECONDITION, "astar"},
  };
  for (const PlanCase& c : cases) {
    SCOPED_TRACE(c.name);
    v1::PlanRequest request = TestServer::SlowRequest(grid_id_, 1, 0);
    c.mutate(request);
    v1::SubmitPlanResponse response;
    grpc::ClientContext context;
    grpc::Status status = server_.jobs().SubmitPlan(&context, request, &response);
    EXPECT_EQ(status.error_code(), c.code) << status.error_message();
    EXPECT_NE(status.error_message().find(c.message), std::string::npos) << status.error_message();
    // Plan rejects the same way, before any event.
    grpc::ClientContext plan_context;
    auto reader = server_.jobs().Plan(&plan_context, request);
    grpc::Status plan_status;
    EXPECT_TRUE(TestServer::ReadAll(*reader, &plan_status).empty());
    EXPECT_EQ(plan_status.error_code(), c.code);
  }
  v1::ListJobsResponse jobs;
  grpc::ClientContext context;
  ASSERT_TRUE(server_.jobs().ListJobs(&context, {}, &jobs).ok());
  EXPECT_EQ(jobs.jobs_size(), 0);  // nothing was queued
  ExpectHealthyAndNothingLost();
}

TEST_F(BadInputTest, SizesAndCountsOfRequestFieldsAreBoundedAndTheMessageNamesTheBound) {
  struct BoundCase {
    const char* name;
    std::function<void(v1::PlanRequest&)> mutate;
    const char* field;
    const char* bound;
  };
  const std::vector<BoundCase> cases = {
      {"too many labels",
       [](auto& r) {
         for (int i = 0; i < 65; ++i) (*r.mutable_labels())["k" + std::to_string(i)] = "v";
       },
       "labels", "64"},
      {"label key too long", [](auto& r) { (*r.mutable_labels())[std::string(64, 'k')] = "v"; },
       "labels", "63"},
      {"empty label key", [](auto& r) { (*r.mutable_labels())[""] = "v"; }, "labels", "1"},
      {"label value too long",
       [](auto& r) { (*r.mutable_labels())["robot"] = std::string(257, 'v'); }, "labels['robot']",
       "256"},
      {"client_request_id too long",
       [](auto& r) { r.set_client_request_id(std::string(129, 'r')); }, "client_request_id", "128"},
  };
  for (const BoundCase& c : cases) {
    SCOPED_TRACE(c.name);
    v1::PlanRequest request = TestServer::SlowRequest(grid_id_, 1, 0);
    c.mutate(request);
    v1::SubmitPlanResponse response;
    grpc::ClientContext context;
    grpc::Status status = server_.jobs().SubmitPlan(&context, request, &response);
    EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT) << status.error_message();
    EXPECT_NE(status.error_message().find(c.field), std::string::npos) << status.error_message();
    EXPECT_NE(status.error_message().find(c.bound), std::string::npos) << status.error_message();
  }
  v1::PlanRequest at_the_bounds = TestServer::SlowRequest(grid_id_, 1, 0);
  for (int i = 0; i < 63; ++i) (*at_the_bounds.mutable_labels())["k" + std::to_string(i)] = "v";
  (*at_the_bounds.mutable_labels())[std::string(63, 'k')] = std::string(256, 'v');
  at_the_bounds.set_client_request_id(std::string(128, 'r'));
  EXPECT_EQ(server_.WaitUntilFinal(server_.SubmitOk(at_the_bounds).id()).state(),
            v1::JOB_STATE_SUCCEEDED);

  v1::UploadMapRequest upload;
  upload.set_name(std::string(257, 'n'));
  SetFile(upload, "ascii", "a.txt", "..\n");
  v1::UploadMapResponse uploaded;
  grpc::ClientContext context;
  grpc::Status status = server_.maps().UploadMap(&context, upload, &uploaded);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_NE(status.error_message().find("name"), std::string::npos) << status.error_message();
  EXPECT_NE(status.error_message().find("256"), std::string::npos) << status.error_message();
}

TEST_F(BadInputTest, ListJobsRefusesAStateFilterOutsideTheEnum) {
  for (int state : {99, -1, 0}) {
    SCOPED_TRACE(state);
    v1::ListJobsRequest request;
    request.add_states(v1::JOB_STATE_SUCCEEDED);
    request.add_states(static_cast<v1::JobState>(state));
    v1::ListJobsResponse response;
    grpc::ClientContext context;
    grpc::Status status = server_.jobs().ListJobs(&context, request, &response);
    EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
    EXPECT_NE(status.error_message().find("states[1]"), std::string::npos)
        << status.error_message();
  }
}

TEST_F(BadInputTest, GarbageAndTamperedPageTokensAreInvalidArguments) {
  v1::ListMapsRequest first_maps;
  first_maps.set_page_size(1);
  v1::ListMapsResponse maps;
  {
    grpc::ClientContext context;
    ASSERT_TRUE(server_.maps().ListMaps(&context, first_maps, &maps).ok());
    ASSERT_FALSE(maps.next_page_token().empty());
  }
  std::string tampered = maps.next_page_token();
  tampered[tampered.size() / 2] = tampered[tampered.size() / 2] == 'A' ? 'B' : 'A';
  for (const std::string& token : {std::string("garbage"), tampered, grid_id_}) {
    SCOPED_TRACE(token);
    v1::ListMapsRequest request;
    request.set_page_token(token);
    grpc::ClientContext c1, c2;
    grpc::Status status = server_.maps().ListMaps(&c1, request, &maps);
    EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
    EXPECT_NE(status.error_message().find("page_token"), std::string::npos);
    v1::ListJobsRequest jobs_request;
    jobs_request.set_page_token(token);
    v1::ListJobsResponse jobs;
    status = server_.jobs().ListJobs(&c2, jobs_request, &jobs);
    EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
    EXPECT_NE(status.error_message().find("page_token"), std::string::npos);
  }
  ExpectHealthyAndNothingLost();
}

TEST_F(BadInputTest, EveryBadUploadGetsTheRightCodeAndNamesTheFieldOrFile) {
  using C = grpc::StatusCode;
  auto file = [](const char* format, const char* name, std::string content) {
    return [=](v1::UploadMapRequest& r) { SetFile(r, format, name, content); };
  };
  const std::vector<UploadCase> cases = {
      {"no name", [](auto& r) { r.clear_name(); }, C::INVALID_ARGUMENT, "name"},
      {"no source", [](auto& r) { r.clear_source(); }, C::INVALID_ARGUMENT, "source"},
      {"unknown format", file("bmp", "a.bmp", "BM"), C::INVALID_ARGUMENT, "bmp"},
      {"no format", file("", "a.txt", ".."), C::INVALID_ARGUMENT, "format"},
      {"ascii with a stray character", file("ascii", "bad.txt", "..\n.x\n"), C::INVALID_ARGUMENT,
       "bad.txt"},
      {"movingai without header", file("movingai", "bad.map", "hello\n"), C::INVALID_ARGUMENT,
       "bad.map"},
      {"shapes-json not json", file("shapes-json", "bad.json", "{nope"), C::INVALID_ARGUMENT,
       "bad.json"},
      {"geojson without features", file("geojson", "bad.geojson", "{\"type\": \"Point\"}"),
       C::INVALID_ARGUMENT, "bad.geojson"},
      {"terrain-asc truncated", file("terrain-asc", "bad.asc", "ncols 3\nnrows 2\n"),
       C::INVALID_ARGUMENT, "bad.asc"},
      {"terrain-csv ragged", file("terrain-csv", "bad.csv", "1,2,3\n4,5\n"), C::INVALID_ARGUMENT,
       "bad.csv"},
      {"terrain-pgm not an image", file("terrain-pgm", "bad.pgm", "P7 what"), C::INVALID_ARGUMENT,
       "bad.pgm"},
      {"pgm not an image", file("pgm", "bad.pgm", "nothing"), C::INVALID_ARGUMENT, "bad.pgm"},
      {"ros-yaml-pgm with one file", file("ros-yaml-pgm", "map.yaml", "image: map.pgm\n"),
       C::INVALID_ARGUMENT, "2 files"},
      {"ros-yaml-pgm with bad yaml",
       [](auto& r) {
         SetFile(r, "ros-yaml-pgm", "map.yaml", "image: [unclosed\n");
         v1::MapFile* image = r.mutable_source()->mutable_files()->add_files();
         image->set_name("map.pgm");
         image->set_content("P2\n1 1\n255\n0\n");
       },
       C::INVALID_ARGUMENT, "map.yaml"},
      {"ascii grid beyond the cell limit", file("ascii", "huge.txt", std::string(10001, '.')),
       C::RESOURCE_EXHAUSTED, "huge.txt"},
      {"structured grid beyond the cell limit",
       [](auto& r) {
         v1::OccupancyGridData* g =
             r.mutable_source()->mutable_structured()->mutable_occupancy_grid();
         g->set_width(200);
         g->set_height(200);
         g->set_cells(std::string(40000, '\0'));
       },
       C::RESOURCE_EXHAUSTED, "limit"},
      {"structured grid with too few cells",
       [](auto& r) {
         v1::OccupancyGridData* g =
             r.mutable_source()->mutable_structured()->mutable_occupancy_grid();
         g->set_width(4);
         g->set_height(4);
         g->set_cells(std::string(15, '\0'));
       },
       C::INVALID_ARGUMENT, "occupancy_grid.cells"},
      {"structured grid with a bad value",
       [](auto& r) {
         v1::OccupancyGridData* g =
             r.mutable_source()->mutable_structured()->mutable_occupancy_grid();
         g->set_width(2);
         g->set_height(1);
         g->set_cells(std::string("\x00\x7f", 2));
       },
       C::INVALID_ARGUMENT, "cells[1]"},
      {"structured world with a negative radius",
       [](auto& r) {
         v1::ShapeWorldData* w = r.mutable_source()->mutable_structured()->mutable_shape_world();
         w->mutable_max()->set_x(5);
         w->mutable_max()->set_y(5);
         w->add_circles()->set_radius(-1);
       },
       C::INVALID_ARGUMENT, "shape_world"},
      {"structured terrain with too few heights",
       [](auto& r) {
         v1::TerrainData* t = r.mutable_source()->mutable_structured()->mutable_terrain();
         t->set_width(2);
         t->set_depth(2);
         t->add_heights(1);
       },
       C::INVALID_ARGUMENT, "terrain.heights"},
      {"structured map of no kind", [](auto& r) { r.mutable_source()->mutable_structured(); },
       C::INVALID_ARGUMENT, "structured"},
  };
  for (const UploadCase& c : cases) {
    SCOPED_TRACE(c.name);
    v1::UploadMapRequest request;
    request.set_name("bad");
    c.mutate(request);
    v1::UploadMapResponse response;
    grpc::ClientContext context;
    grpc::Status status = server_.maps().UploadMap(&context, request, &response);
    EXPECT_EQ(status.error_code(), c.code) << status.error_message();
    EXPECT_NE(status.error_message().find(c.message), std::string::npos) << status.error_message();
  }
  ExpectHealthyAndNothingLost();
}

TEST_F(BadInputTest, AMessageAboveTheSizeLimitIsRejectedAndTheServerCarriesOn) {
  TempDir dir;
  server::ServerConfig config = TestServer::DefaultConfig();
  config.max_message_bytes = 64 * 1024;
  TestServer small(dir.path(), config);
  v1::UploadMapRequest request;
  request.set_name("big");
  SetFile(request, "ascii", "big.txt", std::string(100 * 1024, '.'));
  v1::UploadMapResponse response;
  grpc::ClientContext context;
  EXPECT_EQ(small.maps().UploadMap(&context, request, &response).error_code(),
            grpc::StatusCode::RESOURCE_EXHAUSTED);
  EXPECT_FALSE(small.UploadGrid("fine", 4, 4).empty());
}

TEST_F(BadInputTest, EmptyIdsAndNegativePageSizesAreInvalidArguments) {
  using C = grpc::StatusCode;
  v1::GetMapResponse map;
  v1::Job job;
  v1::ListMapsResponse maps;
  v1::ListJobsResponse jobs;
  grpc::ClientContext c1, c2, c3, c4, c5;
  v1::ListMapsRequest list_maps;
  list_maps.set_page_size(-1);
  v1::ListJobsRequest list_jobs;
  list_jobs.set_page_size(-5);
  EXPECT_EQ(server_.maps().GetMap(&c1, {}, &map).error_code(), C::INVALID_ARGUMENT);
  EXPECT_EQ(server_.jobs().GetJob(&c2, {}, &job).error_code(), C::INVALID_ARGUMENT);
  EXPECT_EQ(server_.jobs().CancelJob(&c3, {}, &job).error_code(), C::INVALID_ARGUMENT);
  EXPECT_EQ(server_.maps().ListMaps(&c4, list_maps, &maps).error_code(), C::INVALID_ARGUMENT);
  grpc::Status status = server_.jobs().ListJobs(&c5, list_jobs, &jobs);
  EXPECT_EQ(status.error_code(), C::INVALID_ARGUMENT);
  EXPECT_NE(status.error_message().find("page_size"), std::string::npos);
  ExpectHealthyAndNothingLost();
}

// A goal 0.3 from a polygon: a grid planner whose 1-unit raster cell there is blocked is
// rejected at submission, naming the planner and the cell; on the automatic raster (the
// default) the same request is accepted and succeeds.
TEST_F(BadInputTest, RasterCellAPlannerCannotUseIsRejectedAtSubmission) {
  v1::UploadMapRequest upload;
  upload.set_name("block");
  v1::ShapeWorldData* w = upload.mutable_source()->mutable_structured()->mutable_shape_world();
  w->mutable_max()->set_x(20);
  w->mutable_max()->set_y(10);
  v1::Polygon* block = w->add_polygons();
  for (const auto& [x, y] : {std::pair{10.3, 0.0}, {12.0, 0.0}, {12.0, 6.0}, {10.3, 6.0}}) {
    v1::Point* p = block->add_vertices();
    p->set_x(x);
    p->set_y(y);
  }
  v1::UploadMapResponse uploaded;
  grpc::ClientContext upload_context;
  ASSERT_TRUE(server_.maps().UploadMap(&upload_context, upload, &uploaded).ok());
  v1::PlanRequest request = TestServer::Request(uploaded.map().id(), "as-bfo", 10.0);
  request.mutable_start()->set_x(2);
  request.mutable_start()->set_y(8);
  request.mutable_goal()->set_y(3);
  (*request.mutable_parameters())["population"].set_int_value(10);
  request.mutable_limits()->set_max_iterations(20);

  v1::PlanRequest coarse = request;
  (*coarse.mutable_parameters())["resolution"].set_double_value(1.0);
  v1::SubmitPlanResponse response;
  grpc::ClientContext context;
  const grpc::Status status = server_.jobs().SubmitPlan(&context, coarse, &response);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::FAILED_PRECONDITION) << status.error_message();
  EXPECT_NE(status.error_message().find("'as-bfo'"), std::string::npos) << status.error_message();
  EXPECT_NE(status.error_message().find("cell (10, 3)"), std::string::npos)
      << status.error_message();

  const v1::Job job = server_.WaitUntilFinal(server_.SubmitOk(request).id());
  EXPECT_EQ(job.state(), v1::JOB_STATE_SUCCEEDED);
}

}  // namespace
}  // namespace swarmplan::testing
