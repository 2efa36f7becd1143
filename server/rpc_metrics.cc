#include "server/rpc_metrics.h"

#include "absl/status/status.h"
#include "absl/time/clock.h"

namespace swarmplan::server {
namespace {

class RpcMetricsInterceptor final : public grpc::experimental::Interceptor {
 public:
  RpcMetricsInterceptor(Metrics& metrics, const char* method)
      : metrics_(metrics), method_(method != nullptr && method[0] == '/' ? method + 1 : method) {}

  void Intercept(grpc::experimental::InterceptorBatchMethods* methods) override {
    if (methods->QueryInterceptionHookPoint(
            grpc::experimental::InterceptionHookPoints::PRE_SEND_STATUS)) {
      metrics_.RpcHandled(method_, StatusCodeName(methods->GetSendStatus().error_code()),
                          absl::ToDoubleSeconds(absl::Now() - start_));
    }
    methods->Proceed();
  }

 private:
  Metrics& metrics_;
  const std::string method_;
  const absl::Time start_ = absl::Now();
};

}  // namespace

grpc::experimental::Interceptor* RpcMetricsInterceptorFactory::CreateServerInterceptor(
    grpc::experimental::ServerRpcInfo* info) {
  return new RpcMetricsInterceptor(metrics_, info->method());
}

std::string StatusCodeName(grpc::StatusCode code) {
  // gRPC's codes are the canonical codes, which absl::StatusCode numbers identically.
  return absl::StatusCodeToString(static_cast<absl::StatusCode>(code));
}

}  // namespace swarmplan::server
