#pragma once
// The names a browser may use to reach this console (issue 28, item 4): a page on another site
// that makes its own name resolve to this machine (DNS rebinding) sends that name in Host, and
// is refused. Allowed: localhost and the loopback addresses, this machine's host name (and
// NAME.local, mDNS), every address of its interfaces, and the names given.
#include <string>
#include <vector>

namespace planter::console {

class HostNames {
 public:
  explicit HostNames(std::vector<std::string> extra);
  // Host as sent (name or address, with or without :port, IPv6 in brackets). A name that is
  // not known is looked for again among the interfaces' current addresses (DHCP may change
  // them) before it is refused.
  bool allowed(const std::string& host_header);
  [[nodiscard]] std::string known() const;  // for the refusal's words

 private:
  void refresh();
  std::vector<std::string> extra_, names_;
};

}  // namespace planter::console
