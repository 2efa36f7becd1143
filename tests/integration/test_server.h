#pragma once

#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "core/registry.h"
#include "server/config.h"
#include "server/server.h"
#include "swarmplan/v1/algorithms.grpc.pb.h"
#include "swarmplan/v1/jobs.grpc.pb.h"
#include "swarmplan/v1/maps.grpc.pb.h"

namespace swarmplan::testing {

// The default registry plus "test-slow": a planner that runs `iterations` iterations of
// `sleep_ms` each (stopping early when told), then returns the straight segment start-goal.
// It gives the cancel, deadline and queue tests a job that runs as long as they need.
const Registry& TestRegistry();

// Whether the suite runs against Redis (SWARMPLAN_TEST_STORE=redis) rather than SQLite.
bool TestingWithRedis();
// The --store URL of the test store in `data_dir`: sqlite:DATA_DIR, or with Redis the URL of a
// redis-server started for that directory (its AOF there), kept until the TempDir goes.
std::string StoreUrlFor(const std::string& data_dir);

// A temporary data directory under /tmp, removed at destruction (with its redis-server).
class TempDir {
 public:
  TempDir();
  ~TempDir();
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// A server running in-process on 127.0.0.1 (a port gRPC picks) with stubs of every service.
class TestServer {
 public:
  // `config` overrides: listen, data_dir and store are set here; a metrics endpoint, when
  // `config.metrics_port` is not 0, listens on a port the system picks.
  explicit TestServer(const std::string& data_dir, server::ServerConfig config = DefaultConfig());
  ~TestServer();

  // Without a metrics endpoint: its HTTP server takes up to 2 s to stop.
  static server::ServerConfig DefaultConfig();
  static server::ServerConfig WithMetrics(server::ServerConfig config = DefaultConfig());

  server::Server& server() { return *server_; }
  int port() const { return server_->port(); }
  std::shared_ptr<grpc::Channel> channel() const { return channel_; }
  v1::MapService::Stub& maps() { return *maps_; }
  v1::AlgorithmService::Stub& algorithms() { return *algorithms_; }
  v1::JobService::Stub& jobs() { return *jobs_; }

  // Uploads a structured w x h free grid (resolution 1) with an optional blocked column
  // x = wall_x from y = 0 to h - 2. Returns its id.
  std::string UploadGrid(const std::string& name, int w, int h, int wall_x = -1);
  // A request for `algorithm` on `map_id` from (0.5, 0.5) to (w - 0.5, 0.5).
  static v1::PlanRequest Request(const std::string& map_id, const std::string& algorithm,
                                 double goal_x);
  // A test-slow request of `iterations` iterations of `sleep_ms`.
  static v1::PlanRequest SlowRequest(const std::string& map_id, int iterations, int sleep_ms);

  v1::Job SubmitOk(const v1::PlanRequest& request);
  v1::Job GetJob(const std::string& id);
  // Polls GetJob until the job is in `state` or 30 s pass.
  v1::Job WaitForState(const std::string& id, v1::JobState state);
  // Polls GetJob until the job is final or 30 s pass.
  v1::Job WaitUntilFinal(const std::string& id);
  // Reads a Plan/WatchJob stream to its end.
  static std::vector<v1::JobEvent> ReadAll(grpc::ClientReaderInterface<v1::JobEvent>& reader,
                                           grpc::Status* status);

 private:
  std::unique_ptr<server::Server> server_;
  std::shared_ptr<grpc::Channel> channel_;
  std::unique_ptr<v1::MapService::Stub> maps_;
  std::unique_ptr<v1::AlgorithmService::Stub> algorithms_;
  std::unique_ptr<v1::JobService::Stub> jobs_;
};

// GET http://127.0.0.1:port/path over a plain socket; returns the whole response ("" on error).
std::string HttpGet(int port, const std::string& path);

bool IsFinalState(v1::JobState state);

}  // namespace swarmplan::testing
