#include "cli/view_access.h"

#include <algorithm>
#include <cctype>
#include <random>

namespace fgsg::cli {

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string trimBlanks(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t") - a + 1);
}

// "::1" -> "[::1]": how a browser writes an IPv6 address in Host and Origin.
std::string hostForm(const std::string& host) {
  return host.find(':') != std::string::npos ? "[" + host + "]" : host;
}

}  // namespace

bool isLoopbackHost(const std::string& host) {
  const std::string h = lower(host);
  return h == "localhost" || h == "::1" || h == "[::1]" || h.rfind("127.", 0) == 0;
}

std::string newViewToken() {
  std::random_device source;  // /dev/urandom with glibc
  static const char* digits = "0123456789abcdef";
  std::string token;
  for (int i = 0; i < 6; ++i) {  // 6 x 32 bits: 192
    uint32_t word = source();
    for (int k = 0; k < 4; ++k, word >>= 8) {
      token += digits[(word >> 4) & 15];
      token += digits[word & 15];
    }
  }
  return token;
}

ViewAccess::ViewAccess(const std::string& host, uint16_t port, std::string token)
    : port_(port), token_(std::move(token)) {
  const std::string h = lower(host);
  anyHost_ = h == "0.0.0.0" || h == "::" || h == "[::]";
  std::vector<std::string> names = {"127.0.0.1", "localhost", "[::1]"};
  if (!anyHost_ && !isLoopbackHost(h)) names.push_back(hostForm(h));
  if (isLoopbackHost(h) && h.rfind("127.", 0) == 0 && h != "127.0.0.1") names.push_back(h);
  for (const std::string& n : names) {
    hosts_.push_back(n + ":" + std::to_string(port));
    if (port == 80) hosts_.push_back(n);  // a browser leaves out the default port
  }
}

bool ViewAccess::hostAllowed(const std::string& hostHeader) const {
  const std::string h = lower(trimBlanks(hostHeader));
  if (h.empty() || h.size() > 255) return false;
  if (anyHost_) return true;
  return std::find(hosts_.begin(), hosts_.end(), h) != hosts_.end();
}

bool ViewAccess::originAllowed(const std::string& originHeader, const std::string& hostHeader) const {
  const std::string origin = lower(trimBlanks(originHeader));
  if (origin.empty()) return true;
  return hostAllowed(hostHeader) && origin == "http://" + lower(trimBlanks(hostHeader));
}

bool ViewAccess::sameToken(const std::string& candidate) const {
  if (candidate.size() != token_.size()) return false;
  unsigned char differ = 0;  // every byte compared: no timing clue to a prefix
  for (size_t i = 0; i < token_.size(); ++i) differ |= static_cast<unsigned char>(candidate[i] ^ token_[i]);
  return differ == 0;
}

bool ViewAccess::tokenPresented(const std::string& resource, const std::string& cookieHeader,
                                const std::string& authorizationHeader) const {
  if (token_.empty()) return true;
  // ?token=... among the query's parameters (the token is hex: nothing to decode).
  const size_t q = resource.find('?');
  if (q != std::string::npos) {
    const std::string query = resource.substr(q + 1, resource.find('#', q) - q - 1);
    for (size_t at = 0; at <= query.size();) {
      const size_t end = std::min(query.find('&', at), query.size());
      const std::string param = query.substr(at, end - at);
      if (param.rfind("token=", 0) == 0 && sameToken(param.substr(6))) return true;
      at = end + 1;
    }
  }
  // Cookie: a=b; fgsg-view-token-8765=...
  const std::string name = cookieName() + "=";
  for (size_t at = 0; at < cookieHeader.size();) {
    const size_t end = std::min(cookieHeader.find(';', at), cookieHeader.size());
    const std::string pair = trimBlanks(cookieHeader.substr(at, end - at));
    if (pair.rfind(name, 0) == 0 && sameToken(pair.substr(name.size()))) return true;
    at = end + 1;
  }
  const std::string auth = trimBlanks(authorizationHeader);
  return auth.size() > 6 && lower(auth.substr(0, 6)) == "token " && sameToken(trimBlanks(auth.substr(6)));
}

std::string ViewAccess::cookieName() const { return "fgsg-view-token-" + std::to_string(port_); }

std::string ViewAccess::setCookieHeader() const {
  return cookieName() + "=" + token_ + "; Path=/; HttpOnly; SameSite=Strict";
}

std::string ViewAccess::url(const std::string& host) const {
  std::string u = "http://" + hostForm(host) + ":" + std::to_string(port_) + "/";
  if (!token_.empty()) u += "?token=" + token_;
  return u;
}

}  // namespace fgsg::cli
