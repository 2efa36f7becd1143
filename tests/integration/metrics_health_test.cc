// Operations over loopback: Prometheus metrics scraped over HTTP, gRPC health checking and
// server reflection (spoken with a generic stub, so no generated code of theirs is needed).
#include <grpcpp/generic/generic_stub.h>
#include <sys/stat.h>

#include "absl/time/clock.h"
#include "server/auth.h"
#include "tests/integration/test_server.h"

namespace swarmplan::testing {
namespace {

// One unary call with raw bytes.
grpc::Status RawUnary(grpc::Channel& channel, const std::string& method, const std::string& request,
                      std::string* response) {
  grpc::GenericStub stub(std::shared_ptr<grpc::Channel>(&channel, [](grpc::Channel*) {}));
  grpc::CompletionQueue cq;
  grpc::ClientContext context;
  grpc::Slice slice(request);
  grpc::ByteBuffer send(&slice, 1), receive;
  auto call = stub.PrepareUnaryCall(&context, method, send, &cq);
  call->StartCall();
  grpc::Status status;
  call->Finish(&receive, &status, reinterpret_cast<void*>(1));
  void* tag;
  bool ok;
  cq.Next(&tag, &ok);
  std::vector<grpc::Slice> slices;
  receive.Dump(&slices);
  response->clear();
  for (const grpc::Slice& s : slices)
    response->append(reinterpret_cast<const char*>(s.begin()), s.size());
  return status;
}

// One request, one response on a bidi stream with raw bytes.
grpc::Status RawBidiOnce(grpc::Channel& channel, const std::string& method,
                         const std::string& request, std::string* response,
                         const std::string& authorization = "") {
  grpc::GenericStub stub(std::shared_ptr<grpc::Channel>(&channel, [](grpc::Channel*) {}));
  grpc::CompletionQueue cq;
  grpc::ClientContext context;
  if (!authorization.empty()) context.AddMetadata("authorization", authorization);
  void* tag;
  bool ok;
  auto call = stub.PrepareCall(&context, method, &cq);
  call->StartCall(reinterpret_cast<void*>(1));
  cq.Next(&tag, &ok);
  grpc::Slice slice(request);
  grpc::ByteBuffer send(&slice, 1), receive;
  call->Write(send, reinterpret_cast<void*>(2));
  cq.Next(&tag, &ok);
  call->WritesDone(reinterpret_cast<void*>(3));
  cq.Next(&tag, &ok);
  call->Read(&receive, reinterpret_cast<void*>(4));
  cq.Next(&tag, &ok);
  std::vector<grpc::Slice> slices;
  if (ok) receive.Dump(&slices);
  response->clear();
  for (const grpc::Slice& s : slices)
    response->append(reinterpret_cast<const char*>(s.begin()), s.size());
  grpc::Status status;
  call->Finish(&status, reinterpret_cast<void*>(5));
  cq.Next(&tag, &ok);
  return status;
}

TEST(OperationsTest, MetricsAreServedOverHttpWithConventionalNames) {
  TempDir dir;
  TestServer server(dir.path(), TestServer::WithMetrics());
  const std::string map_id = server.UploadGrid("grid", 6, 4);
  server.WaitUntilFinal(server.SubmitOk(TestServer::SlowRequest(map_id, 3, 0)).id());
  v1::GetJobRequest missing;
  missing.set_id("job-missing");
  v1::Job job;
  grpc::ClientContext context;
  ASSERT_EQ(server.jobs().GetJob(&context, missing, &job).error_code(),
            grpc::StatusCode::NOT_FOUND);

  ASSERT_GT(server.server().metrics_port(), 0);
  const std::string body = HttpGet(server.server().metrics_port(), "/metrics");
  ASSERT_NE(body.find("200 OK"), std::string::npos) << body.substr(0, 200);
  for (const char* line : {
           "# TYPE swarmplan_jobs_total counter",
           "swarmplan_jobs_total{algorithm=\"test-slow\",state=\"succeeded\"} 1",
           "# TYPE swarmplan_job_duration_seconds histogram",
           "swarmplan_job_duration_seconds_count{algorithm=\"test-slow\"} 1",
           "# TYPE swarmplan_job_queue_wait_seconds histogram",
           "swarmplan_job_queue_wait_seconds_count{algorithm=\"test-slow\"} 1",
           "# TYPE swarmplan_job_queue_depth gauge",
           "# TYPE swarmplan_workers_busy gauge",
           "swarmplan_workers 1",
           "swarmplan_fitness_evaluations_total{algorithm=\"test-slow\"} 30",
           "# TYPE swarmplan_rpc_requests_total counter",
           "swarmplan_rpc_requests_total{code=\"OK\",method=\"swarmplan.v1.MapService/UploadMap\"} "
           "1",
           "swarmplan_rpc_requests_total{code=\"NOT_FOUND\",method=\"swarmplan.v1.JobService/"
           "GetJob\"} 1",
           "# TYPE swarmplan_rpc_duration_seconds histogram",
           "swarmplan_maps_stored 1",
           "swarmplan_build_info{version=",
       }) {
    EXPECT_NE(body.find(line), std::string::npos) << "missing: " << line;
  }
}

// The value of an unlabelled metric in a scrape, or -1 when absent.
double MetricValue(const std::string& body, const std::string& name) {
  const std::string prefix = "\n" + name + " ";
  const size_t at = body.find(prefix);
  if (at == std::string::npos) return -1;
  return std::stod(body.substr(at + prefix.size()));
}

TEST(OperationsTest, WorkersBusyReturnsToZeroAfterJobsFinish) {
  TempDir dir;
  TestServer server(dir.path(), TestServer::WithMetrics());
  const std::string map_id = server.UploadGrid("grid", 6, 4);
  const std::string running = server.SubmitOk(TestServer::SlowRequest(map_id, 100, 10)).id();
  server.WaitForState(running, v1::JOB_STATE_RUNNING);
  EXPECT_EQ(
      MetricValue(HttpGet(server.server().metrics_port(), "/metrics"), "swarmplan_workers_busy"),
      1);
  server.WaitUntilFinal(running);
  server.WaitUntilFinal(server.SubmitOk(TestServer::SlowRequest(map_id, 2, 0)).id());
  // The worker lets go of the job just after its final state is visible: allow it a moment.
  const absl::Time give_up = absl::Now() + absl::Seconds(5);
  double busy = -1;
  do {
    busy =
        MetricValue(HttpGet(server.server().metrics_port(), "/metrics"), "swarmplan_workers_busy");
    if (busy == 0) break;
    absl::SleepFor(absl::Milliseconds(20));
  } while (absl::Now() < give_up);
  EXPECT_EQ(busy, 0);
  EXPECT_EQ(
      MetricValue(HttpGet(server.server().metrics_port(), "/metrics"), "swarmplan_job_queue_depth"),
      0);
}

TEST(OperationsTest, HealthCheckSaysServing) {
  TempDir dir;
  TestServer server(dir.path());
  std::string response;
  // HealthCheckRequest{service: ""} is empty; HealthCheckResponse{status: SERVING} is 08 01.
  grpc::Status status = RawUnary(*server.channel(), "/grpc.health.v1.Health/Check", "", &response);
  ASSERT_TRUE(status.ok()) << status.error_message();
  EXPECT_EQ(response, std::string("\x08\x01", 2));
}

TEST(OperationsTest, HealthCheckOfEachServiceSaysServing) {
  TempDir dir;
  TestServer server(dir.path());
  for (const std::string service :
       {"swarmplan.v1.MapService", "swarmplan.v1.JobService", "swarmplan.v1.AlgorithmService"}) {
    SCOPED_TRACE(service);
    // HealthCheckRequest{service}: field 1, length-delimited.
    const std::string request =
        std::string("\x0a", 1) + static_cast<char>(service.size()) + service;
    std::string response;
    grpc::Status status =
        RawUnary(*server.channel(), "/grpc.health.v1.Health/Check", request, &response);
    ASSERT_TRUE(status.ok()) << status.error_message();
    EXPECT_EQ(response, std::string("\x08\x01", 2));
  }
  std::string response;
  const std::string unknown = std::string("\x0a\x0d", 2) + "no.SuchThing1";
  EXPECT_EQ(
      RawUnary(*server.channel(), "/grpc.health.v1.Health/Check", unknown, &response).error_code(),
      grpc::StatusCode::NOT_FOUND);
}

TEST(OperationsTest, ReflectionListsTheSwarmplanServices) {
  TempDir dir;
  TestServer server(dir.path());
  std::string response;
  // ServerReflectionRequest{list_services: ""}: field 7, length 0.
  grpc::Status status = RawBidiOnce(
      *server.channel(), "/grpc.reflection.v1alpha.ServerReflection/ServerReflectionInfo",
      std::string("\x3a\x00", 2), &response);
  ASSERT_TRUE(status.ok()) << status.error_message();
  for (const char* service : {"swarmplan.v1.MapService", "swarmplan.v1.AlgorithmService",
                              "swarmplan.v1.JobService", "grpc.health.v1.Health"}) {
    EXPECT_NE(response.find(service), std::string::npos) << service;
  }
}

// Writes "s3cret\n" to `path` with permission bits `mode`.
void WriteTokenFile(const std::string& path, mode_t mode) {
  FILE* f = fopen(path.c_str(), "w");
  ASSERT_NE(f, nullptr);
  fputs("s3cret\n", f);
  fclose(f);
  ASSERT_EQ(chmod(path.c_str(), mode), 0);
}

// The default configuration with the token "s3cret" in a private file under `dir`.
server::ServerConfig TokenServerConfig(const TempDir& dir) {
  server::ServerConfig config = TestServer::DefaultConfig();
  config.token_file = dir.path() + "/token";
  WriteTokenFile(config.token_file, 0600);
  return config;
}

constexpr char kReflectionMethod[] =
    "/grpc.reflection.v1alpha.ServerReflection/ServerReflectionInfo";
// ServerReflectionRequest{list_services: ""}: field 7, length 0.
const std::string kListServices("\x3a\x00", 2);

TEST(OperationsTest, ReflectionAnswersSymbolQueriesWithTheFileAndItsImports) {
  TempDir dir;
  TestServer server(dir.path());
  // ServerReflectionRequest{file_containing_symbol: "swarmplan.v1.JobService"}: field 4.
  const std::string symbol = "swarmplan.v1.JobService";
  std::string response;
  grpc::Status status =
      RawBidiOnce(*server.channel(), kReflectionMethod,
                  std::string("\x22", 1) + static_cast<char>(symbol.size()) + symbol, &response);
  ASSERT_TRUE(status.ok()) << status.error_message();
  EXPECT_NE(response.find("swarmplan/v1/jobs.proto"), std::string::npos);
  EXPECT_NE(response.find("swarmplan/v1/common.proto"), std::string::npos);
  // An unknown symbol is an error response in the stream, not a failed call.
  const std::string unknown = "no.Such";
  status =
      RawBidiOnce(*server.channel(), kReflectionMethod,
                  std::string("\x22", 1) + static_cast<char>(unknown.size()) + unknown, &response);
  ASSERT_TRUE(status.ok()) << status.error_message();
  EXPECT_NE(response.find("file_containing_symbol: no symbol no.Such"), std::string::npos);
}

TEST(OperationsTest, ReflectionNeedsTheTokenWhenOneIsSet) {
  TempDir dir, data;
  TestServer server(data.path(), TokenServerConfig(dir));
  std::string response;
  EXPECT_EQ(
      RawBidiOnce(*server.channel(), kReflectionMethod, kListServices, &response).error_code(),
      grpc::StatusCode::UNAUTHENTICATED);
  EXPECT_EQ(response.find("swarmplan.v1.JobService"), std::string::npos);
  EXPECT_EQ(
      RawBidiOnce(*server.channel(), kReflectionMethod, kListServices, &response, "Bearer wrong")
          .error_code(),
      grpc::StatusCode::UNAUTHENTICATED);
  grpc::Status status =
      RawBidiOnce(*server.channel(), kReflectionMethod, kListServices, &response, "Bearer s3cret");
  ASSERT_TRUE(status.ok()) << status.error_message();
  EXPECT_NE(response.find("swarmplan.v1.JobService"), std::string::npos);
}

TEST(OperationsTest, TheBearerSchemeWordIsCaseInsensitiveTheTokenIsNot) {
  TempDir dir, data;
  TestServer server(data.path(), TokenServerConfig(dir));
  v1::ListMapsResponse maps;
  for (const std::string value :
       {"Bearer s3cret", "bearer s3cret", "BEARER s3cret", "bEaReR s3cret", "Bearer  s3cret"}) {
    SCOPED_TRACE(value);
    grpc::ClientContext context;
    context.AddMetadata("authorization", value);
    grpc::Status status = server.maps().ListMaps(&context, {}, &maps);
    EXPECT_TRUE(status.ok()) << status.error_message();
  }
  for (const std::string value :
       {"Bearer S3CRET", "Basic s3cret", "Bearers3cret", "s3cret", "Bearer", "Bearer s3cret2"}) {
    SCOPED_TRACE(value);
    grpc::ClientContext context;
    context.AddMetadata("authorization", value);
    EXPECT_EQ(server.maps().ListMaps(&context, {}, &maps).error_code(),
              grpc::StatusCode::UNAUTHENTICATED);
  }
}

TEST(OperationsTest, AGroupOrWorldReadableTokenFileIsWarnedAbout) {
  EXPECT_EQ(server::TokenFileModeWarning("/t", 0100600), "");
  EXPECT_EQ(server::TokenFileModeWarning("/t", 0100400), "");
  EXPECT_EQ(server::TokenFileModeWarning("/t", 0100620), "");
  const std::string world = server::TokenFileModeWarning("/etc/t", 0100644);
  EXPECT_NE(world.find("--token-file /etc/t has mode 0644"), std::string::npos) << world;
  EXPECT_NE(world.find("group and others"), std::string::npos) << world;
  const std::string group = server::TokenFileModeWarning("/t", 0100640);
  EXPECT_NE(group.find("mode 0640: readable by its group;"), std::string::npos) << group;
  const std::string others = server::TokenFileModeWarning("/t", 0100604);
  EXPECT_NE(others.find("readable by others;"), std::string::npos) << others;

  TempDir dir;
  const std::string token_file = dir.path() + "/token";
  WriteTokenFile(token_file, 0644);
  EXPECT_NE(server::TokenFileModeWarning(token_file).find(token_file + " has mode 0644"),
            std::string::npos);
  ASSERT_EQ(chmod(token_file.c_str(), 0600), 0);
  EXPECT_EQ(server::TokenFileModeWarning(token_file), "");
}

TEST(OperationsTest, BearerTokenGuardsEveryRpcButHealth) {
  TempDir dir, data;
  TestServer server(data.path(), TokenServerConfig(dir));
  v1::ListMapsResponse maps;
  {
    grpc::ClientContext context;
    grpc::Status status = server.maps().ListMaps(&context, {}, &maps);
    EXPECT_EQ(status.error_code(), grpc::StatusCode::UNAUTHENTICATED);
  }
  {
    grpc::ClientContext context;
    context.AddMetadata("authorization", "Bearer wrong");
    EXPECT_EQ(server.maps().ListMaps(&context, {}, &maps).error_code(),
              grpc::StatusCode::UNAUTHENTICATED);
  }
  {
    grpc::ClientContext context;
    context.AddMetadata("authorization", "Bearer s3cret");
    EXPECT_TRUE(server.maps().ListMaps(&context, {}, &maps).ok());
  }
  {
    grpc::ClientContext context;
    v1::WatchJobRequest request;
    request.set_id("job-x");
    auto reader = server.jobs().WatchJob(&context, request);
    grpc::Status status;
    TestServer::ReadAll(*reader, &status);
    EXPECT_EQ(status.error_code(), grpc::StatusCode::UNAUTHENTICATED);
  }
  std::string response;
  EXPECT_TRUE(RawUnary(*server.channel(), "/grpc.health.v1.Health/Check", "", &response).ok());
}

}  // namespace
}  // namespace swarmplan::testing
