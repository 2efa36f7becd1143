#include "server/server.h"

#include <grpcpp/grpcpp.h>
#include <grpcpp/health_check_service_interface.h>
#include <spdlog/spdlog.h>

#include <fstream>
#include <sstream>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "absl/synchronization/mutex.h"
#include "server/auth.h"
#include "server/job_manager.h"
#include "server/map_catalog.h"
#include "server/metrics.h"
#include "server/redis_store.h"
#include "server/reflection.h"
#include "server/rpc_metrics.h"
#include "server/services.h"
#include "server/store_url.h"

namespace swarmplan::server {
namespace {

absl::StatusOr<std::string> ReadFile(const std::string& flag, const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    return absl::FailedPreconditionError(absl::StrCat("--", flag, " ", path, ": cannot read"));
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

absl::StatusOr<std::shared_ptr<grpc::ServerCredentials>> Credentials(const ServerConfig& config) {
  if (config.tls_cert_file.empty()) return grpc::InsecureServerCredentials();
  absl::StatusOr<std::string> cert = ReadFile("tls-cert-file", config.tls_cert_file);
  if (!cert.ok()) return cert.status();
  absl::StatusOr<std::string> key = ReadFile("tls-key-file", config.tls_key_file);
  if (!key.ok()) return key.status();
  grpc::SslServerCredentialsOptions options;
  options.pem_key_cert_pairs.push_back({*key, *cert});
  return grpc::SslServerCredentials(options);
}

// The queue and event streams replicas share, for a redis:// store; none for SQLite.
absl::StatusOr<SharedJobs> OpenSharedJobs(Store& store, const ServerConfig& config) {
  auto* redis = dynamic_cast<RedisStore*>(&store);
  if (redis == nullptr) return SharedJobs{};
  constexpr absl::Duration kShortestLease = absl::Milliseconds(300);
  if (config.job_lease < kShortestLease) {
    return absl::InvalidArgumentError(
        absl::StrCat("--job-lease: ", absl::FormatDuration(config.job_lease), " is shorter than ",
                     absl::FormatDuration(kShortestLease)));
  }
  SharedJobQueue::Options options;
  options.consumer = UniqueConsumerName();
  options.lease = config.job_lease;
  options.capacity = config.queue_capacity;
  absl::StatusOr<std::unique_ptr<SharedJobQueue>> queue =
      SharedJobQueue::Open(redis->client(), redis->prefix(), options);
  if (!queue.ok()) return queue.status();
  SharedJobs shared;
  shared.queue = std::move(*queue);
  shared.events = std::make_unique<SharedJobEvents>(redis->client(), redis->prefix());
  spdlog::info("shared job queue: replica {} (lease {})", options.consumer,
               absl::FormatDuration(options.lease));
  return shared;
}

}  // namespace

struct Server::Impl {
  ServerConfig config;
  const Registry* registry = nullptr;
  std::unique_ptr<Store> store;
  Metrics metrics;
  std::unique_ptr<MapCatalog> maps;
  std::unique_ptr<JobManager> jobs;
  Authenticator auth;
  std::unique_ptr<MapServiceImpl> map_service;
  std::unique_ptr<AlgorithmServiceImpl> algorithm_service;
  std::unique_ptr<JobServiceImpl> job_service;
  std::unique_ptr<ReflectionServiceImpl> reflection_service;
  std::unique_ptr<grpc::Server> grpc_server;
  int port = 0;

  absl::Mutex mu;
  bool shutdown_started ABSL_GUARDED_BY(mu) = false;
  bool shutdown_done ABSL_GUARDED_BY(mu) = false;
};

Server::Server(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

Server::~Server() { Shutdown(); }

absl::StatusOr<std::unique_ptr<Server>> Server::Start(const ServerConfig& config,
                                                      const Registry& registry) {
  auto impl = std::make_unique<Impl>();
  impl->config = config;
  impl->registry = &registry;

  absl::StatusOr<Authenticator> auth = Authenticator::FromFile(config.token_file);
  if (!auth.ok()) return auth.status();
  impl->auth = *auth;
  if (std::string warning = TokenFileModeWarning(config.token_file); !warning.empty()) {
    spdlog::warn("{}", warning);
  }
  absl::StatusOr<std::shared_ptr<grpc::ServerCredentials>> credentials = Credentials(config);
  if (!credentials.ok()) return credentials.status();

  absl::StatusOr<std::unique_ptr<Store>> store = OpenStore(config);
  if (!store.ok()) return store.status();
  impl->store = std::move(*store);

  LoadOptions load_options;
  load_options.limits.max_cells = config.max_map_cells;
  load_options.limits.max_file_bytes = config.max_message_bytes;
  impl->maps = std::make_unique<MapCatalog>(*impl->store, load_options, config.map_cache_entries);
  absl::StatusOr<std::vector<std::string>> warnings = impl->maps->Load();
  if (!warnings.ok()) return warnings.status();
  for (const std::string& w : *warnings) spdlog::warn("{}", w);
  impl->metrics.SetMapsStored(impl->maps->size());

  if (config.metrics_port != 0) {
    if (absl::Status s = impl->metrics.Serve(config.metrics_address,
                                             config.metrics_port < 0 ? 0 : config.metrics_port);
        !s.ok()) {
      return s;
    }
  }

  absl::StatusOr<SharedJobs> shared = OpenSharedJobs(*impl->store, config);
  if (!shared.ok()) return shared.status();
  impl->jobs = std::make_unique<JobManager>(impl->config, registry, *impl->maps, *impl->store,
                                            impl->metrics, std::move(*shared));
  if (absl::Status s = impl->jobs->Recover(); !s.ok()) return s;

  impl->map_service = std::make_unique<MapServiceImpl>(*impl->maps, *impl->jobs, impl->metrics,
                                                       impl->config, impl->auth);
  impl->algorithm_service = std::make_unique<AlgorithmServiceImpl>(registry, impl->auth);
  impl->job_service = std::make_unique<JobServiceImpl>(*impl->jobs, impl->config, impl->auth);

  // Our own reflection service, not gRPC's plugin: that one answers without the token.
  impl->reflection_service = std::make_unique<ReflectionServiceImpl>(
      std::vector<std::string>{v1::MapService::service_full_name(),
                               v1::AlgorithmService::service_full_name(),
                               v1::JobService::service_full_name(), "grpc.health.v1.Health",
                               grpc::reflection::v1alpha::ServerReflection::service_full_name()},
      impl->auth);

  grpc::EnableDefaultHealthCheckService(true);
  grpc::ServerBuilder builder;
  builder.AddListeningPort(config.listen, *credentials, &impl->port);
  builder.SetMaxReceiveMessageSize(config.max_message_bytes);
  builder.SetMaxSendMessageSize(config.max_message_bytes);
  builder.RegisterService(impl->map_service.get());
  builder.RegisterService(impl->algorithm_service.get());
  builder.RegisterService(impl->job_service.get());
  builder.RegisterService(impl->reflection_service.get());
  std::vector<std::unique_ptr<grpc::experimental::ServerInterceptorFactoryInterface>> interceptors;
  interceptors.push_back(std::make_unique<RpcMetricsInterceptorFactory>(impl->metrics));
  builder.experimental().SetInterceptorCreators(std::move(interceptors));
  impl->grpc_server = builder.BuildAndStart();
  if (impl->grpc_server == nullptr || impl->port == 0) {
    impl->jobs->Shutdown(absl::ZeroDuration());
    return absl::UnavailableError(absl::StrCat(
        "--listen ", config.listen, ": cannot listen there (address in use or invalid)"));
  }
  if (grpc::HealthCheckServiceInterface* health = impl->grpc_server->GetHealthCheckService()) {
    for (const char* service :
         {v1::MapService::service_full_name(), v1::AlgorithmService::service_full_name(),
          v1::JobService::service_full_name()}) {
      health->SetServingStatus(service, true);
    }
  }
  spdlog::info("swarmplan-server listening on port {} (metrics: {}, store: {}, auth: {}, tls: {})",
               impl->port,
               impl->metrics.port() > 0 ? absl::StrCat(impl->metrics.port()) : std::string("off"),
               DescribeStore(config), impl->auth.enabled() ? "on" : "off",
               config.tls_cert_file.empty() ? "off" : "on");
  return std::unique_ptr<Server>(new Server(std::move(impl)));
}

int Server::port() const { return impl_->port; }
int Server::metrics_port() const { return impl_->metrics.port(); }

void Server::Shutdown() {
  {
    absl::MutexLock lock(&impl_->mu);
    if (impl_->shutdown_started) return;
    impl_->shutdown_started = true;
  }
  spdlog::info("shutting down: no new jobs; running jobs get {}",
               absl::FormatDuration(impl_->config.shutdown_grace));
  if (grpc::HealthCheckServiceInterface* health = impl_->grpc_server->GetHealthCheckService()) {
    health->SetServingStatus(false);
  }
  impl_->jobs->Shutdown(impl_->config.shutdown_grace);
  // Streams of jobs that did not finish are cut now; their jobs stay queued in the store.
  impl_->grpc_server->Shutdown(std::chrono::system_clock::now() + std::chrono::seconds(1));
  impl_->grpc_server->Wait();
  spdlog::info("shut down");
  absl::MutexLock lock(&impl_->mu);
  impl_->shutdown_done = true;
}

void Server::Wait() {
  absl::MutexLock lock(&impl_->mu);
  impl_->mu.Await(absl::Condition(&impl_->shutdown_done));
}

}  // namespace swarmplan::server
