// Unit tests of the client's local pieces: argument parsing, path files, SVG rendering, exit
// codes. The end-to-end behaviour against the server is in cli_test.py.
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "client/arguments.h"
#include "client/exit_codes.h"
#include "client/map_render.h"
#include "client/output.h"
#include "client/path_files.h"
#include "client/server_list.h"
#include "core/map/io/map_io.h"
#include "gtest/gtest.h"

namespace swarmplan::client {
namespace {

TEST(ClientArguments, ParsesPointsAndNamesTheFlagOnError) {
  absl::StatusOr<v1::Point> point = ParsePoint("--start", "2.5, 3");
  ASSERT_TRUE(point.ok());
  EXPECT_EQ(point->x(), 2.5);
  EXPECT_EQ(point->y(), 3.0);
  EXPECT_EQ(point->z(), 0.0);
  EXPECT_EQ(ParsePoint("--goal", "1,2,3")->z(), 3.0);
  absl::StatusOr<v1::Point> bad = ParsePoint("--goal", "1;2");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.status().message().find("--goal"), std::string::npos);
  EXPECT_FALSE(ParsePoint("--start", "1,2,3,4").ok());
  EXPECT_FALSE(ParsePoint("--start", "nan,1").ok());
}

TEST(ClientArguments, TypesParametersByTheirSchema) {
  v1::ParameterSpec spec;
  spec.set_type(v1::PARAMETER_TYPE_DOUBLE);
  EXPECT_EQ(ParseParamValue("step", "2", &spec)->double_value(), 2.0);
  spec.set_type(v1::PARAMETER_TYPE_INT);
  EXPECT_EQ(ParseParamValue("population", "40", &spec)->int_value(), 40);
  EXPECT_FALSE(ParseParamValue("population", "4.5", &spec).ok());
  spec.set_type(v1::PARAMETER_TYPE_BOOL);
  EXPECT_TRUE(ParseParamValue("elitism", "yes", &spec)->bool_value());
  // Without a schema: the value's own look.
  EXPECT_EQ(ParseParamValue("a", "7", nullptr)->kind_case(), v1::ParamValue::kIntValue);
  EXPECT_EQ(ParseParamValue("a", "0.5", nullptr)->kind_case(), v1::ParamValue::kDoubleValue);
  EXPECT_EQ(ParseParamValue("a", "linear", nullptr)->string_value(), "linear");
  auto pair = ParseKeyValue("--param", "w=0.9");
  ASSERT_TRUE(pair.ok());
  EXPECT_EQ(pair->first, "w");
  EXPECT_EQ(pair->second, "0.9");
  EXPECT_FALSE(ParseKeyValue("--param", "=1").ok());
}

TEST(ClientArguments, ParsesDurations) {
  EXPECT_DOUBLE_EQ(*ParseSeconds("--time-budget", "30"), 30.0);
  EXPECT_DOUBLE_EQ(*ParseSeconds("--time-budget", "500ms"), 0.5);
  EXPECT_DOUBLE_EQ(*ParseSeconds("--time-budget", "2m"), 120.0);
  EXPECT_FALSE(ParseSeconds("--time-budget", "-1s").ok());
  EXPECT_FALSE(ParseSeconds("--time-budget", "soon").ok());
}

TEST(ClientServerList, OneAddressStaysAsGivenAndAListBecomesOneBalancedTarget) {
  EXPECT_EQ(*client::ChannelTarget("example.org:50051"), "example.org:50051");
  EXPECT_EQ(*client::ChannelTarget("127.0.0.1:7001, 127.0.0.1:7002,127.0.0.1:7001"),
            "ipv4:127.0.0.1:7001,127.0.0.1:7002");
  EXPECT_EQ(*client::ChannelTarget("[::1]:7001,[::1]:7002"), "ipv6:[::1]:7001,[::1]:7002");
  const absl::StatusOr<std::string> no_port = client::ChannelTarget("127.0.0.1:7001,127.0.0.1");
  ASSERT_FALSE(no_port.ok());
  EXPECT_NE(no_port.status().message().find("--server"), std::string::npos);
  EXPECT_FALSE(client::ChannelTarget("127.0.0.1:7001,[::1]:7002").ok());  // two families
}

TEST(ClientExitCodes, MapStatusCodesAndJobStates) {
  EXPECT_EQ(ExitCodeForStatus(grpc::StatusCode::UNAVAILABLE), kExitUnavailable);
  EXPECT_EQ(ExitCodeForStatus(grpc::StatusCode::NOT_FOUND), kExitNotFound);
  EXPECT_EQ(ExitCodeForStatus(grpc::StatusCode::FAILED_PRECONDITION), kExitInvalid);
  EXPECT_EQ(ExitCodeForStatus(grpc::StatusCode::RESOURCE_EXHAUSTED), kExitResourceExhausted);
  EXPECT_EQ(ExitCodeForStatus(grpc::StatusCode::UNAUTHENTICATED), kExitUnauthenticated);
  EXPECT_EQ(ExitCodeForStatus(grpc::StatusCode::INTERNAL), kExitOther);
  EXPECT_EQ(ExitCodeForJobState(v1::JOB_STATE_SUCCEEDED), kExitOk);
  EXPECT_EQ(ExitCodeForJobState(v1::JOB_STATE_DEADLINE_EXCEEDED), kExitNoPath);
  EXPECT_EQ(ParseJobState("no_path_found"), v1::JOB_STATE_NO_PATH_FOUND);
  EXPECT_EQ(ParseJobState("JOB_STATE_CANCELLED"), v1::JOB_STATE_CANCELLED);
  EXPECT_EQ(ParseJobState("bogus"), v1::JOB_STATE_UNSPECIFIED);
}

v1::Job JobWithPath() {
  v1::Job job;
  job.set_id("job-1");
  job.set_state(v1::JOB_STATE_SUCCEEDED);
  for (auto [x, y] : {std::pair{0.5, 0.5}, std::pair{3.5, 0.5}, std::pair{3.5, 2.5}}) {
    v1::Point* p = job.mutable_result()->add_raw_path();
    p->set_x(x);
    p->set_y(y);
  }
  return job;
}

TEST(ClientPathFiles, RoundTripInEveryFormat) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "swarmplan-client-test";
  std::filesystem::create_directories(dir);
  for (const std::string& format : PathFormats()) {
    const std::string file = (dir / ("path." + format)).string();
    // A VDA 5050 order is a .json file: its format is given, not guessed.
    ASSERT_EQ(*PathFormatFor(file, format == "vda5050" ? format : ""), format);
    ASSERT_TRUE(WritePathFile(file, format, JobWithPath()).ok()) << format;
    absl::StatusOr<PathFile> read = ReadPathFile(file);
    ASSERT_TRUE(read.ok()) << format << ": " << read.status();
    ASSERT_EQ(read->points.size(), 3u) << format;
    EXPECT_EQ(read->points[2].x(), 3.5) << format;
    EXPECT_EQ(read->points[2].y(), 2.5) << format;
  }
  EXPECT_FALSE(PathFormatFor("path.txt", "").ok());
  v1::Job empty;
  EXPECT_EQ(WritePathFile((dir / "none.json").string(), "json", empty).code(),
            absl::StatusCode::kFailedPrecondition);
  std::filesystem::remove_all(dir);
}

int Count(const std::string& text, const std::string& what) {
  int count = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++count;
  return count;
}

TEST(ClientRender, MergesGridRunsAndDrawsPathsWithMarkers) {
  // Row 0: one run of 4 blocked cells; row 1: two runs; row 2: none.
  absl::StatusOr<Map> map = ParseMap("ascii", {MapFile{"t.ascii", "####\n#..#\n....\n"}});
  ASSERT_TRUE(map.ok()) << map.status();
  RenderedPath path{"job-1", {Point3(0.5, 2.5, 0), Point3(3.5, 2.5, 0)}};
  ConvergenceCurve curve{"job-1", {{0, 100, false}, {1, 5, true}, {2, 4, true}}};
  RenderOptions options;
  options.convergence_inset = true;
  options.title = "a <title> & more";
  const std::string svg = RenderMapSvg(*map, {path}, {curve}, options);
  const size_t grid = svg.find("<g shape-rendering");
  const size_t grid_end = svg.find("</g>", grid);
  ASSERT_NE(grid, std::string::npos);
  EXPECT_EQ(Count(svg.substr(grid, grid_end - grid), "<rect"), 3);
  EXPECT_EQ(Count(svg, "<polyline"), 2);  // the path and the convergence curve
  EXPECT_NE(svg.find("a &lt;title&gt; &amp; more"), std::string::npos);
  EXPECT_NE(svg.find("fill=\"#2ecc71\""), std::string::npos);  // start marker
  EXPECT_NE(svg.find("fill=\"#e74c3c\""), std::string::npos);  // goal marker
  EXPECT_EQ(svg.rfind("</svg>\n"), svg.size() - 7);
}

TEST(ClientRender, DrawsShapesAndTerrain) {
  absl::StatusOr<Map> world = ParseMap(
      "shapes-json", {MapFile{"w.json", R"({"bounds": [0, 0, 10, 10], "circles": [{"center": [5, 5],
                "radius": 2}], "polygons": [[[1, 1], [2, 1], [2, 2]]]})"}});
  ASSERT_TRUE(world.ok()) << world.status();
  const std::string svg = RenderMapSvg(*world, {}, {}, RenderOptions{});
  EXPECT_EQ(Count(svg, "<circle"), 1);
  EXPECT_EQ(Count(svg, "<polygon"), 1);
  absl::StatusOr<Map> terrain = ParseMap("terrain-csv", {MapFile{"t.csv", "1,2\n3,nan\n"}});
  ASSERT_TRUE(terrain.ok()) << terrain.status();
  const std::string heights = RenderMapSvg(*terrain, {}, {}, RenderOptions{});
  EXPECT_NE(heights.find("#c0392b"), std::string::npos);  // the no-data cell
  const std::string curve = RenderConvergenceSvg({ConvergenceCurve{"a", {{0, 3, true}}}}, "t");
  EXPECT_NE(curve.find("<circle"), std::string::npos);  // a one-point curve is a dot
}

}  // namespace
}  // namespace swarmplan::client
