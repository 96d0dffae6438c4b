#pragma once
// A console client's address as the limits count it, and an address written into a URL.
// Issue 53, item 10. An IPv6 host is given a /64 (RFC 4291 Sec. 2.5.4 and RFC 7421: a
// network's interface identifiers are the low 64 bits, and privacy addresses (RFC 8981) change
// within them at will), so a per-address cap or lockout counts the /64: one phone cannot take
// a new address for each connection or each wrong secret. An IPv4-mapped address is its IPv4,
// and ::1 is 127.0.0.1: the same machine either way. The audit log keeps the address itself.
#include <arpa/inet.h>

#include <cstdio>
#include <string>

namespace planter::console {

inline std::string client_key(const std::string& ip) {
  in6_addr a{};
  if (ip.find(':') == std::string::npos || inet_pton(AF_INET6, ip.c_str(), &a) != 1) return ip;
  const unsigned char* b = a.s6_addr;
  if (IN6_IS_ADDR_LOOPBACK(&a)) return "127.0.0.1";
  char text[64];
  if (IN6_IS_ADDR_V4MAPPED(&a)) {
    std::snprintf(text, sizeof text, "%u.%u.%u.%u", b[12], b[13], b[14], b[15]);
    return text;
  }
  std::snprintf(text, sizeof text, "%x:%x:%x:%x::/64", b[0] << 8 | b[1], b[2] << 8 | b[3],
                b[4] << 8 | b[5], b[6] << 8 | b[7]);
  return text;
}

// A host for "http://HOST:PORT/": an IPv6 address in brackets (RFC 3986 Sec. 3.2.2).
inline std::string url_host(const std::string& host) {
  return host.find(':') == std::string::npos ? host : "[" + host + "]";
}

}  // namespace planter::console
