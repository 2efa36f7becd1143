#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "absl/base/thread_annotations.h"
#include "absl/status/statusor.h"
#include "absl/synchronization/mutex.h"
#include "absl/time/time.h"

struct redisContext;

namespace swarmplan::server {

// Where a Redis server is: parsed from redis://HOST:PORT[/DB]; the password comes from a file,
// never from the URL.
struct RedisEndpoint {
  std::string host;
  int port = 6379;
  int db = 0;
  std::string password;  // empty: no AUTH
};

// A duration in whole milliseconds (at least 0), as PX, BLOCK and idle-time arguments take it.
std::string RedisMillis(absl::Duration d);
// The longest BLOCK a command asks for: it must end before the client's socket timeout.
inline constexpr absl::Duration kMaxRedisBlock = absl::Seconds(5);

// INVALID_ARGUMENT naming `field` for anything but redis://HOST[:PORT][/DB].
absl::StatusOr<RedisEndpoint> ParseRedisUrl(const std::string& url, const std::string& field);

// One reply, copied out of hiredis. Errors never become a RedisReply: Command returns them as a
// status.
struct RedisReply {
  enum class Type { kNil, kString, kInteger, kArray };
  Type type = Type::kNil;
  std::string str;  // kString (bulk and status replies)
  int64_t integer = 0;
  std::vector<RedisReply> elements;

  bool nil() const { return type == Type::kNil; }
};

// A small pool of blocking connections to one Redis server. Thread-safe: each command borrows a
// connection, so up to `connections` commands run at once. A connection that failed is dropped
// and the command is sent once more on a new one.
class RedisClient {
 public:
  // Connects one connection now, so a wrong address or password fails at start.
  static absl::StatusOr<std::unique_ptr<RedisClient>> Connect(
      const RedisEndpoint& endpoint, int connections = 8,
      absl::Duration timeout = absl::Seconds(10));
  ~RedisClient();
  RedisClient(const RedisClient&) = delete;
  RedisClient& operator=(const RedisClient&) = delete;

  // Sends one command (binary-safe arguments). A Redis error reply becomes INTERNAL with its
  // text; a lost connection UNAVAILABLE.
  absl::StatusOr<RedisReply> Command(const std::vector<std::string>& args);
  // EVALSHA of `script` (loaded on first use, and again after a Redis restart), else EVAL.
  absl::StatusOr<RedisReply> Eval(const std::string& script, const std::vector<std::string>& keys,
                                  const std::vector<std::string>& args);

  const RedisEndpoint& endpoint() const { return endpoint_; }

 private:
  RedisClient(RedisEndpoint endpoint, int connections, absl::Duration timeout)
      : endpoint_(std::move(endpoint)), max_connections_(connections), timeout_(timeout) {}
  struct ContextDeleter {
    void operator()(redisContext* c) const;
  };
  using Context = std::unique_ptr<redisContext, ContextDeleter>;

  absl::StatusOr<Context> Open() const;
  absl::StatusOr<Context> Borrow();
  void Return(Context context);
  absl::StatusOr<RedisReply> Send(redisContext* c, const std::vector<std::string>& args) const;

  const RedisEndpoint endpoint_;
  const int max_connections_;
  const absl::Duration timeout_;
  absl::Mutex mu_;
  std::vector<Context> idle_ ABSL_GUARDED_BY(mu_);
  int open_ ABSL_GUARDED_BY(mu_) = 0;  // idle and borrowed
};

}  // namespace swarmplan::server
