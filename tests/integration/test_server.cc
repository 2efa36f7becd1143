#include "tests/integration/test_server.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <map>

#include "absl/base/thread_annotations.h"
#include "absl/synchronization/mutex.h"
#include "absl/time/clock.h"
#include "tests/integration/redis_test_server.h"

namespace swarmplan::testing {
namespace {

class SlowPlanner final : public Planner {
 public:
  SlowPlanner(int iterations, int sleep_ms) : iterations_(iterations), sleep_ms_(sleep_ms) {}

  absl::StatusOr<SearchResult> Solve(const Problem& problem, const StopToken& stop,
                                     Observer& observer) override {
    SearchResult result;
    const absl::Time start = absl::Now();
    for (int i = 0; i < iterations_; ++i) {
      if (StopReason reason = stop.Check(i); reason != StopReason::kNone) {
        result.stop_reason = reason;
        return result;
      }
      absl::SleepFor(absl::Milliseconds(sleep_ms_));
      IterationStats stats;
      stats.iteration = i;
      stats.best_fitness = 1000.0 / (i + 1);
      stats.mean_fitness = 2000.0 / (i + 1);
      stats.evaluations = (i + 1) * 10;
      stats.elapsed = absl::Now() - start;
      observer.OnIteration(stats);
      result.convergence.push_back(stats);
      result.iterations = i + 1;
      result.evaluations = stats.evaluations;
    }
    result.found = true;
    result.path = {problem.start, problem.goal};
    result.fitness = (problem.goal - problem.start).norm();
    return result;
  }

 private:
  const int iterations_;
  const int sleep_ms_;
};

Registry MakeTestRegistry() {
  Registry registry = DefaultRegistry();
  PlannerInfo info;
  info.id = "test-slow";
  info.description = "Test-only planner: sleeps through its iterations, then goes straight.";
  info.encoding = Encoding::kWaypoints;
  info.map_kinds = {MapKind::kOccupancyGrid, MapKind::kShapeWorld, MapKind::kTerrain};
  info.params = {
      ParamSpec::Int("iterations", 10, 1, 1000000, "iterations", "how many"),
      ParamSpec::Int("sleep_ms", 1, 0, 10000, "ms", "sleep per iteration"),
      ParamSpec::Int("population", 10, 1, 1000000, "", "unused; tests the limit").PopulationSize()};
  info.factory = [](const ParamSet& p) -> std::unique_ptr<Planner> {
    return std::make_unique<SlowPlanner>(static_cast<int>(p.Int("iterations")),
                                         static_cast<int>(p.Int("sleep_ms")));
  };
  if (absl::Status s = registry.Register(std::move(info)); !s.ok()) std::abort();
  return registry;
}

absl::Mutex redis_mu;
// The redis-server of each data directory, in Redis mode.
std::map<std::string, std::unique_ptr<RedisTestServer>>& RedisServers()
    ABSL_EXCLUSIVE_LOCKS_REQUIRED(redis_mu) {
  static auto* servers = new std::map<std::string, std::unique_ptr<RedisTestServer>>();
  return *servers;
}

}  // namespace

bool TestingWithRedis() {
  const char* store = std::getenv("SWARMPLAN_TEST_STORE");
  return store != nullptr && std::string(store) == "redis";
}

std::string StoreUrlFor(const std::string& data_dir) {
  if (!TestingWithRedis()) return "sqlite:" + data_dir;
  absl::MutexLock lock(&redis_mu);
  std::unique_ptr<RedisTestServer>& redis = RedisServers()[data_dir];
  if (redis == nullptr) {
    absl::StatusOr<std::unique_ptr<RedisTestServer>> started = RedisTestServer::Start(data_dir);
    if (!started.ok()) {
      ADD_FAILURE() << started.status();
      std::abort();
    }
    redis = std::move(*started);
  }
  return redis->url();
}

const Registry& TestRegistry() {
  static const Registry* registry = new Registry(MakeTestRegistry());
  return *registry;
}

TempDir::TempDir() {
  std::string pattern =
      (std::filesystem::temp_directory_path() / "swarmplan-itest-XXXXXX").string();
  path_ = mkdtemp(pattern.data());
}

TempDir::~TempDir() {
  {
    absl::MutexLock lock(&redis_mu);
    RedisServers().erase(path_);
  }
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

server::ServerConfig TestServer::DefaultConfig() {
  server::ServerConfig config;
  config.workers = 1;
  config.queue_capacity = 4;
  config.shutdown_grace = absl::Seconds(5);
  config.log_level = "warn";
  config.metrics_port = 0;
  return config;
}

server::ServerConfig TestServer::WithMetrics(server::ServerConfig config) {
  config.metrics_port = -1;
  return config;
}

TestServer::TestServer(const std::string& data_dir, server::ServerConfig config) {
  config.listen = "127.0.0.1:0";
  config.data_dir = data_dir;
  if (TestingWithRedis()) config.store = StoreUrlFor(data_dir);
  if (config.metrics_port != 0) config.metrics_port = -1;
  config.metrics_address = "127.0.0.1";
  absl::StatusOr<std::unique_ptr<server::Server>> server =
      server::Server::Start(config, TestRegistry());
  if (!server.ok()) {
    ADD_FAILURE() << server.status();
    std::abort();
  }
  server_ = std::move(*server);
  channel_ = grpc::CreateChannel("127.0.0.1:" + std::to_string(server_->port()),
                                 grpc::InsecureChannelCredentials());
  maps_ = v1::MapService::NewStub(channel_);
  algorithms_ = v1::AlgorithmService::NewStub(channel_);
  jobs_ = v1::JobService::NewStub(channel_);
}

TestServer::~TestServer() { server_->Shutdown(); }

std::string TestServer::UploadGrid(const std::string& name, int w, int h, int wall_x) {
  v1::UploadMapRequest request;
  request.set_name(name);
  v1::OccupancyGridData* grid =
      request.mutable_source()->mutable_structured()->mutable_occupancy_grid();
  grid->set_width(w);
  grid->set_height(h);
  grid->set_resolution(1.0);
  std::string cells(static_cast<size_t>(w) * h, '\0');
  if (wall_x >= 0) {
    for (int y = 0; y < h - 1; ++y) cells[static_cast<size_t>(y) * w + wall_x] = 100;
  }
  grid->set_cells(cells);
  v1::UploadMapResponse response;
  grpc::ClientContext context;
  grpc::Status status = maps_->UploadMap(&context, request, &response);
  EXPECT_TRUE(status.ok()) << status.error_message();
  return response.map().id();
}

v1::PlanRequest TestServer::Request(const std::string& map_id, const std::string& algorithm,
                                    double goal_x) {
  v1::PlanRequest request;
  request.set_map_id(map_id);
  request.set_algorithm(algorithm);
  request.mutable_start()->set_x(0.5);
  request.mutable_start()->set_y(0.5);
  request.mutable_goal()->set_x(goal_x);
  request.mutable_goal()->set_y(0.5);
  request.set_seed(7);
  return request;
}

v1::PlanRequest TestServer::SlowRequest(const std::string& map_id, int iterations, int sleep_ms) {
  v1::PlanRequest request = Request(map_id, "test-slow", 5.5);
  (*request.mutable_parameters())["iterations"].set_int_value(iterations);
  (*request.mutable_parameters())["sleep_ms"].set_int_value(sleep_ms);
  return request;
}

v1::Job TestServer::SubmitOk(const v1::PlanRequest& request) {
  v1::SubmitPlanResponse response;
  grpc::ClientContext context;
  grpc::Status status = jobs_->SubmitPlan(&context, request, &response);
  EXPECT_TRUE(status.ok()) << status.error_message();
  return response.job();
}

v1::Job TestServer::GetJob(const std::string& id) {
  v1::GetJobRequest request;
  request.set_id(id);
  v1::Job job;
  grpc::ClientContext context;
  grpc::Status status = jobs_->GetJob(&context, request, &job);
  EXPECT_TRUE(status.ok()) << status.error_message();
  return job;
}

v1::Job TestServer::WaitForState(const std::string& id, v1::JobState state) {
  const absl::Time give_up = absl::Now() + absl::Seconds(30);
  v1::Job job = GetJob(id);
  while (job.state() != state && absl::Now() < give_up) {
    absl::SleepFor(absl::Milliseconds(5));
    job = GetJob(id);
  }
  EXPECT_EQ(job.state(), state) << job.ShortDebugString();
  return job;
}

v1::Job TestServer::WaitUntilFinal(const std::string& id) {
  const absl::Time give_up = absl::Now() + absl::Seconds(30);
  v1::Job job = GetJob(id);
  while (!IsFinalState(job.state()) && absl::Now() < give_up) {
    absl::SleepFor(absl::Milliseconds(5));
    job = GetJob(id);
  }
  EXPECT_TRUE(IsFinalState(job.state())) << job.ShortDebugString();
  return job;
}

std::vector<v1::JobEvent> TestServer::ReadAll(grpc::ClientReaderInterface<v1::JobEvent>& reader,
                                              grpc::Status* status) {
  std::vector<v1::JobEvent> events;
  v1::JobEvent event;
  while (reader.Read(&event)) events.push_back(event);
  *status = reader.Finish();
  return events;
}

bool IsFinalState(v1::JobState state) {
  return state != v1::JOB_STATE_UNSPECIFIED && state != v1::JOB_STATE_QUEUED &&
         state != v1::JOB_STATE_RUNNING;
}

std::string HttpGet(int port, const std::string& path) {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) return "";
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(static_cast<uint16_t>(port));
  inet_pton(AF_INET, "127.0.0.1", &addr.sin_addr);
  std::string response;
  if (connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)) == 0) {
    const std::string request =
        "GET " + path + " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n";
    if (write(fd, request.data(), request.size()) == static_cast<ssize_t>(request.size())) {
      char buffer[4096];
      ssize_t n;
      while ((n = read(fd, buffer, sizeof(buffer))) > 0) response.append(buffer, n);
    }
  }
  close(fd);
  return response;
}

}  // namespace swarmplan::testing
