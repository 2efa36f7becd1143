#include "client/server_list.h"

#include <netdb.h>
#include <sys/socket.h>

#include <memory>
#include <set>
#include <vector>

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "absl/strings/str_split.h"
#include "absl/strings/strip.h"

namespace swarmplan::client {
namespace {

struct AddrInfoDeleter {
  void operator()(addrinfo* info) const { freeaddrinfo(info); }
};

// "HOST:PORT" or "[V6]:PORT" split into host and port.
absl::StatusOr<std::pair<std::string, std::string>> SplitHostPort(absl::string_view entry) {
  const size_t colon = entry.rfind(':');
  if (colon == absl::string_view::npos || colon + 1 == entry.size() || colon == 0) {
    return absl::InvalidArgumentError(
        absl::StrCat("--server: '", entry, "' is not HOST:PORT (a list is HOST:PORT,HOST:PORT)"));
  }
  absl::string_view host = entry.substr(0, colon);
  if (absl::ConsumePrefix(&host, "[")) host = absl::StripSuffix(host, "]");
  return std::make_pair(std::string(host), std::string(entry.substr(colon + 1)));
}

}  // namespace

bool IsServerList(const std::string& servers) { return absl::StrContains(servers, ','); }

absl::StatusOr<std::string> ChannelTarget(const std::string& servers) {
  if (!IsServerList(servers)) return servers;
  std::vector<std::string> v4, v6;
  std::set<std::string> seen;
  for (absl::string_view entry : absl::StrSplit(servers, ',', absl::SkipWhitespace())) {
    entry = absl::StripAsciiWhitespace(entry);
    absl::StatusOr<std::pair<std::string, std::string>> host_port = SplitHostPort(entry);
    if (!host_port.ok()) return host_port.status();
    addrinfo hints{};
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_STREAM;
    addrinfo* found = nullptr;
    const int error =
        getaddrinfo(host_port->first.c_str(), host_port->second.c_str(), &hints, &found);
    if (error != 0) {
      return absl::InvalidArgumentError(
          absl::StrCat("--server: cannot resolve '", entry, "': ", gai_strerror(error)));
    }
    std::unique_ptr<addrinfo, AddrInfoDeleter> owner(found);
    for (addrinfo* a = found; a != nullptr; a = a->ai_next) {
      char host[NI_MAXHOST] = {};
      if (getnameinfo(a->ai_addr, a->ai_addrlen, host, sizeof(host), nullptr, 0, NI_NUMERICHOST) !=
          0) {
        continue;
      }
      const bool is_v6 = a->ai_family == AF_INET6;
      const std::string address = is_v6 ? absl::StrCat("[", host, "]:", host_port->second)
                                        : absl::StrCat(host, ":", host_port->second);
      if (!seen.insert(address).second) continue;
      (is_v6 ? v6 : v4).push_back(address);
    }
  }
  if (!v4.empty() && !v6.empty()) {
    return absl::InvalidArgumentError(
        "--server: the list resolves to both IPv4 and IPv6 addresses; give one family");
  }
  if (v4.empty() && v6.empty()) {
    return absl::InvalidArgumentError("--server: the list names no address");
  }
  return v4.empty() ? absl::StrCat("ipv6:", absl::StrJoin(v6, ","))
                    : absl::StrCat("ipv4:", absl::StrJoin(v4, ","));
}

}  // namespace swarmplan::client
