#include "server/redis_client.h"

#include <hiredis/hiredis.h>
#include <sys/time.h>

#include <algorithm>
#include <map>

#include "absl/strings/match.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"

namespace swarmplan::server {

std::string RedisMillis(absl::Duration d) {
  return absl::StrCat(std::max<int64_t>(absl::ToInt64Milliseconds(d), 0));
}
namespace {

RedisReply Copy(const redisReply& r) {
  RedisReply out;
  switch (r.type) {
    case REDIS_REPLY_STRING:
    case REDIS_REPLY_STATUS:
      out.type = RedisReply::Type::kString;
      out.str.assign(r.str, r.len);
      break;
    case REDIS_REPLY_INTEGER:
      out.type = RedisReply::Type::kInteger;
      out.integer = r.integer;
      break;
    case REDIS_REPLY_ARRAY:
      out.type = RedisReply::Type::kArray;
      out.elements.reserve(r.elements);
      for (size_t i = 0; i < r.elements; ++i) out.elements.push_back(Copy(*r.element[i]));
      break;
    default:
      break;  // nil
  }
  return out;
}

// The first error reply anywhere in `r` (EXEC and scripts nest them), or null.
const redisReply* FindError(const redisReply& r) {
  if (r.type == REDIS_REPLY_ERROR) return &r;
  if (r.type == REDIS_REPLY_ARRAY) {
    for (size_t i = 0; i < r.elements; ++i) {
      if (const redisReply* e = FindError(*r.element[i]); e != nullptr) return e;
    }
  }
  return nullptr;
}

// SHA1 of each script, as SCRIPT LOAD returned it; shared by every client of the process.
absl::Mutex script_mu;
std::map<std::string, std::string>& ScriptShas() ABSL_EXCLUSIVE_LOCKS_REQUIRED(script_mu) {
  static auto* shas = new std::map<std::string, std::string>();
  return *shas;
}

}  // namespace

absl::StatusOr<RedisEndpoint> ParseRedisUrl(const std::string& url, const std::string& field) {
  auto bad = [&](const std::string& why) {
    return absl::InvalidArgumentError(
        absl::StrCat(field, ": '", url, "' ", why, " (expected redis://HOST[:PORT][/DB])"));
  };
  constexpr absl::string_view kScheme = "redis://";
  if (!absl::StartsWith(url, kScheme)) return bad("does not start with redis://");
  std::string rest = url.substr(kScheme.size());
  if (rest.find('@') != std::string::npos) {
    return bad("carries credentials; give the password in a file (--store-password-file)");
  }
  RedisEndpoint endpoint;
  if (size_t slash = rest.find('/'); slash != std::string::npos) {
    const std::string db = rest.substr(slash + 1);
    if (!db.empty() && (!absl::SimpleAtoi(db, &endpoint.db) || endpoint.db < 0)) {
      return bad(absl::StrCat("has a database '", db, "' that is not an integer >= 0"));
    }
    rest = rest.substr(0, slash);
  }
  if (size_t colon = rest.rfind(':'); colon != std::string::npos) {
    const std::string port = rest.substr(colon + 1);
    if (!absl::SimpleAtoi(port, &endpoint.port) || endpoint.port < 1 || endpoint.port > 65535) {
      return bad(absl::StrCat("has a port '", port, "' that is not in 1..65535"));
    }
    rest = rest.substr(0, colon);
  }
  if (rest.empty()) return bad("has no host");
  endpoint.host = rest;
  return endpoint;
}

void RedisClient::ContextDeleter::operator()(redisContext* c) const { redisFree(c); }

absl::StatusOr<std::unique_ptr<RedisClient>> RedisClient::Connect(const RedisEndpoint& endpoint,
                                                                  int connections,
                                                                  absl::Duration timeout) {
  std::unique_ptr<RedisClient> client(new RedisClient(endpoint, std::max(connections, 1), timeout));
  absl::StatusOr<Context> first = client->Open();
  if (!first.ok()) return first.status();
  absl::MutexLock lock(&client->mu_);
  client->idle_.push_back(std::move(*first));
  client->open_ = 1;
  return client;
}

RedisClient::~RedisClient() = default;

absl::StatusOr<RedisClient::Context> RedisClient::Open() const {
  const std::string where = absl::StrCat("redis://", endpoint_.host, ":", endpoint_.port);
  Context c(
      redisConnectWithTimeout(endpoint_.host.c_str(), endpoint_.port, absl::ToTimeval(timeout_)));
  if (c == nullptr) return absl::UnavailableError(absl::StrCat(where, ": cannot connect"));
  if (c->err != 0) {
    return absl::UnavailableError(absl::StrCat(where, ": cannot connect: ", c->errstr));
  }
  redisSetTimeout(c.get(), absl::ToTimeval(timeout_));
  if (!endpoint_.password.empty()) {
    absl::StatusOr<RedisReply> auth = Send(c.get(), {"AUTH", endpoint_.password});
    if (!auth.ok()) {
      return absl::PermissionDeniedError(
          absl::StrCat(where, ": AUTH refused: ", auth.status().message()));
    }
  }
  if (endpoint_.db != 0) {
    absl::StatusOr<RedisReply> select = Send(c.get(), {"SELECT", absl::StrCat(endpoint_.db)});
    if (!select.ok()) {
      return absl::FailedPreconditionError(
          absl::StrCat(where, ": SELECT ", endpoint_.db, ": ", select.status().message()));
    }
  }
  absl::StatusOr<RedisReply> ping = Send(c.get(), {"PING"});
  if (!ping.ok()) {
    return absl::Status(ping.status().code(), absl::StrCat(where, ": ", ping.status().message()));
  }
  return c;
}

absl::StatusOr<RedisClient::Context> RedisClient::Borrow() {
  {
    absl::MutexLock lock(&mu_);
    auto can_proceed = [this]() ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_) {
      return !idle_.empty() || open_ < max_connections_;
    };
    mu_.Await(absl::Condition(&can_proceed));
    if (!idle_.empty()) {
      Context c = std::move(idle_.back());
      idle_.pop_back();
      return c;
    }
    ++open_;
  }
  absl::StatusOr<Context> c = Open();
  if (!c.ok()) {
    absl::MutexLock lock(&mu_);
    --open_;
  }
  return c;
}

void RedisClient::Return(Context context) {
  absl::MutexLock lock(&mu_);
  if (context == nullptr || context->err != 0) {
    --open_;  // dropped; the next Borrow opens a fresh one
    return;
  }
  idle_.push_back(std::move(context));
}

absl::StatusOr<RedisReply> RedisClient::Send(redisContext* c,
                                             const std::vector<std::string>& args) const {
  std::vector<const char*> argv;
  std::vector<size_t> lengths;
  argv.reserve(args.size());
  lengths.reserve(args.size());
  for (const std::string& a : args) {
    argv.push_back(a.data());
    lengths.push_back(a.size());
  }
  auto* reply = static_cast<redisReply*>(
      redisCommandArgv(c, static_cast<int>(args.size()), argv.data(), lengths.data()));
  if (reply == nullptr) {
    return absl::UnavailableError(absl::StrCat("redis ", args.empty() ? "" : args[0], ": ",
                                               c->err != 0 ? c->errstr : "no reply"));
  }
  std::unique_ptr<redisReply, void (*)(void*)> owned(reply, freeReplyObject);
  if (const redisReply* error = FindError(*reply); error != nullptr) {
    return absl::InternalError(
        absl::StrCat("redis ", args[0], ": ", std::string(error->str, error->len)));
  }
  return Copy(*reply);
}

absl::StatusOr<RedisReply> RedisClient::Command(const std::vector<std::string>& args) {
  absl::Status last;
  for (int attempt = 0; attempt < 2; ++attempt) {
    absl::StatusOr<Context> c = Borrow();
    if (!c.ok()) return c.status();
    absl::StatusOr<RedisReply> reply = Send(c->get(), args);
    const bool connection_lost = (*c)->err != 0;
    Return(std::move(*c));
    if (!connection_lost) return reply;
    last = reply.status();
  }
  return last;
}

absl::StatusOr<RedisReply> RedisClient::Eval(const std::string& script,
                                             const std::vector<std::string>& keys,
                                             const std::vector<std::string>& args) {
  auto command = [&](const std::string& verb, const std::string& body) {
    std::vector<std::string> argv = {verb, body, absl::StrCat(keys.size())};
    argv.insert(argv.end(), keys.begin(), keys.end());
    argv.insert(argv.end(), args.begin(), args.end());
    return argv;
  };
  std::string sha;
  {
    absl::MutexLock lock(&script_mu);
    if (auto it = ScriptShas().find(script); it != ScriptShas().end()) sha = it->second;
  }
  if (!sha.empty()) {
    absl::StatusOr<RedisReply> reply = Command(command("EVALSHA", sha));
    if (reply.ok() || !absl::StrContains(reply.status().message(), "NOSCRIPT")) return reply;
  }
  absl::StatusOr<RedisReply> loaded = Command({"SCRIPT", "LOAD", script});
  if (!loaded.ok()) return loaded.status();
  {
    absl::MutexLock lock(&script_mu);
    ScriptShas()[script] = loaded->str;
  }
  return Command(command("EVALSHA", loaded->str));
}

}  // namespace swarmplan::server
