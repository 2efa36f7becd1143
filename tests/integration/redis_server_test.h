#pragma once

#include <gtest/gtest.h>

#include <memory>

#include "server/redis_client.h"
#include "tests/integration/redis_test_server.h"
#include "tests/integration/test_server.h"

namespace swarmplan::testing {

// A test with a real redis-server of its own, its AOF in dir_; skipped with a message when
// redis-server is not installed.
class RedisServerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    absl::StatusOr<std::unique_ptr<RedisTestServer>> redis = RedisTestServer::Start(dir_.path());
    if (absl::IsFailedPrecondition(redis.status())) GTEST_SKIP() << redis.status().message();
    ASSERT_TRUE(redis.ok()) << redis.status();
    redis_ = std::move(*redis);
  }

  server::RedisEndpoint Endpoint() const {
    absl::StatusOr<server::RedisEndpoint> endpoint = server::ParseRedisUrl(redis_->url(), "url");
    EXPECT_TRUE(endpoint.ok()) << endpoint.status();
    return endpoint.ok() ? *endpoint : server::RedisEndpoint{};
  }

  TempDir dir_;
  std::unique_ptr<RedisTestServer> redis_;
};

}  // namespace swarmplan::testing
