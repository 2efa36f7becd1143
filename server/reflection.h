#pragma once

#include <string>
#include <vector>

#include "grpc/reflection/v1alpha/reflection.grpc.pb.h"
#include "server/auth.h"

namespace swarmplan::server {

// grpc.reflection.v1alpha.ServerReflection over the descriptors linked into the server, behind the
// same bearer-token check as every other service (gRPC's stock reflection plugin answers without
// it). It lists `services` and answers file, symbol and extension queries from the generated pool.
class ReflectionServiceImpl final
    : public grpc::reflection::v1alpha::ServerReflection::CallbackService {
 public:
  ReflectionServiceImpl(std::vector<std::string> services, const Authenticator& auth)
      : services_(std::move(services)), auth_(auth) {}

  grpc::ServerBidiReactor<grpc::reflection::v1alpha::ServerReflectionRequest,
                          grpc::reflection::v1alpha::ServerReflectionResponse>*
  ServerReflectionInfo(grpc::CallbackServerContext* context) override;

  // The answer to one request; `sent` holds the files this stream has already sent.
  grpc::reflection::v1alpha::ServerReflectionResponse Answer(
      const grpc::reflection::v1alpha::ServerReflectionRequest& request,
      std::vector<std::string>& sent) const;

 private:
  const std::vector<std::string> services_;
  const Authenticator& auth_;
};

}  // namespace swarmplan::server
