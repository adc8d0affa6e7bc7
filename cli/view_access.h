// Who may talk to `fgsg view`'s server, decided from a request's headers alone (as
// Jupyter's server does): the Host must name this server (no DNS rebinding), a WebSocket's
// Origin must be the page's own (no cross-site WebSocket hijacking), and every request
// carries the session token printed in the URL, as ?token=, the cookie the page got with
// it, or "Authorization: token ...". Pure functions of text: tests/unit/cli/.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace fgsg::cli {

class ViewAccess {
 public:
  // `host` as --host gave it; `token` empty: no token required (--no-token).
  ViewAccess(const std::string& host, uint16_t port, std::string token);

  // The Host header names this server: 127.0.0.1, localhost, [::1] or --host, with the
  // port. Listening on every address (0.0.0.0, ::) any name passes: the token guards then.
  bool hostAllowed(const std::string& hostHeader) const;
  // A WebSocket's Origin is the page's own: http:// and the request's (allowed) Host. No
  // Origin (not a browser) passes, as in Jupyter: the token still has to be there.
  bool originAllowed(const std::string& originHeader, const std::string& hostHeader) const;
  // The request carries the token (compared in constant time).
  bool tokenPresented(const std::string& resource, const std::string& cookieHeader,
                      const std::string& authorizationHeader) const;
  bool tokenRequired() const { return !token_.empty(); }

  // What the page gets with its first authorised request, so that its scripts and its
  // WebSocket need not repeat the token: HttpOnly, SameSite=Strict, per port.
  std::string cookieName() const;
  std::string setCookieHeader() const;
  // The URL to print: http://HOST:PORT/?token=... (IPv6 in brackets).
  std::string url(const std::string& host) const;

 private:
  bool sameToken(const std::string& candidate) const;
  std::vector<std::string> hosts_;  // "127.0.0.1:8765", lower case
  bool anyHost_ = false;            // --host 0.0.0.0 or ::
  uint16_t port_;
  std::string token_;
};

// 48 hex digits from the system's random source.
std::string newViewToken();
// --host that reaches beyond this machine (anything but a loopback address).
bool isLoopbackHost(const std::string& host);

}  // namespace fgsg::cli
