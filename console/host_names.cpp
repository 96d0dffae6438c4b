#include "console/host_names.h"

#include <arpa/inet.h>
#include <ifaddrs.h>
#include <netinet/in.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>

#include "console/console_request.h"

namespace planter::console {

HostNames::HostNames(std::vector<std::string> extra) : extra_(std::move(extra)) { refresh(); }

void HostNames::refresh() {
  std::vector<std::string> names = {"localhost", "127.0.0.1", "::1"};
  for (const std::string& e : extra_) names.push_back(host_of(e));
  char host[256] = {};
  if (gethostname(host, sizeof host - 1) == 0 && host[0] != '\0') {
    names.push_back(host_of(host));
    names.push_back(host_of(std::string(host) + ".local"));
  }
  ifaddrs* list = nullptr;
  if (getifaddrs(&list) == 0) {
    for (const ifaddrs* a = list; a != nullptr; a = a->ifa_next) {
      if (a->ifa_addr == nullptr) continue;
      char text[INET6_ADDRSTRLEN] = {};
      if (a->ifa_addr->sa_family == AF_INET) {
        const auto* in = reinterpret_cast<const sockaddr_in*>(a->ifa_addr);
        if (inet_ntop(AF_INET, &in->sin_addr, text, sizeof text)) names.emplace_back(text);
      } else if (a->ifa_addr->sa_family == AF_INET6) {
        const auto* in6 = reinterpret_cast<const sockaddr_in6*>(a->ifa_addr);
        if (inet_ntop(AF_INET6, &in6->sin6_addr, text, sizeof text)) names.emplace_back(text);
      }
    }
    freeifaddrs(list);
  }
  names_ = std::move(names);
}

bool HostNames::allowed(const std::string& host_header) {
  const std::string host = host_of(host_header);
  if (host.empty()) return false;
  const auto known = [&] { return std::find(names_.begin(), names_.end(), host) != names_.end(); };
  if (known()) return true;
  refresh();
  return known();
}

std::string HostNames::known() const {
  std::string out;
  for (const std::string& n : names_) out += (out.empty() ? "" : ", ") + n;
  return out;
}

}  // namespace planter::console
