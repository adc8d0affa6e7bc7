// fgsg view's gate (cli/view_access.h): which Host, Origin and token a request may carry.
#include "cli/view_access.h"

#include <catch2/catch.hpp>

using fgsg::cli::ViewAccess;

TEST_CASE("view access: only this server's own names pass as Host") {
  const ViewAccess a("127.0.0.1", 8765, "ab12");
  CHECK(a.hostAllowed("127.0.0.1:8765"));
  CHECK(a.hostAllowed("localhost:8765"));
  CHECK(a.hostAllowed("LocalHost:8765"));
  CHECK(a.hostAllowed("[::1]:8765"));
  CHECK_FALSE(a.hostAllowed("evil.example:8765"));  // DNS rebinding
  CHECK_FALSE(a.hostAllowed("127.0.0.1:8766"));
  CHECK_FALSE(a.hostAllowed("127.0.0.1"));
  CHECK_FALSE(a.hostAllowed("localhost.evil.example:8765"));
  CHECK_FALSE(a.hostAllowed(""));
  CHECK_FALSE(a.hostAllowed("127.0.0.1:8765\r\nX: y"));
  const ViewAccess lan("192.168.1.5", 9000, "ab12");
  CHECK(lan.hostAllowed("192.168.1.5:9000"));
  CHECK(lan.hostAllowed("127.0.0.1:9000"));
  CHECK_FALSE(lan.hostAllowed("192.168.1.6:9000"));
  const ViewAccess everywhere("0.0.0.0", 9000, "ab12");  // the token guards then
  CHECK(everywhere.hostAllowed("my-machine.lan:9000"));
  const ViewAccess v6("::1", 80, "");
  CHECK(v6.hostAllowed("[::1]"));  // a browser leaves out port 80
  CHECK(v6.hostAllowed("[::1]:80"));
}

TEST_CASE("view access: a WebSocket's Origin must be the page's own") {
  const ViewAccess a("127.0.0.1", 8765, "ab12");
  CHECK(a.originAllowed("http://127.0.0.1:8765", "127.0.0.1:8765"));
  CHECK(a.originAllowed("http://localhost:8765", "localhost:8765"));
  CHECK(a.originAllowed("", "127.0.0.1:8765"));  // not a browser: the token decides
  CHECK_FALSE(a.originAllowed("http://evil.example.com", "127.0.0.1:8765"));
  CHECK_FALSE(a.originAllowed("http://localhost:8765", "127.0.0.1:8765"));  // another origin
  CHECK_FALSE(a.originAllowed("https://127.0.0.1:8765", "127.0.0.1:8765"));
  CHECK_FALSE(a.originAllowed("null", "127.0.0.1:8765"));  // a sandboxed or file: page
  CHECK_FALSE(a.originAllowed("http://evil.example:8765", "evil.example:8765"));
}

TEST_CASE("view access: the token by query, cookie or Authorization header") {
  const std::string token = fgsg::cli::newViewToken();
  REQUIRE(token.size() == 48);
  CHECK(token.find_first_not_of("0123456789abcdef") == std::string::npos);
  CHECK(token != fgsg::cli::newViewToken());
  const ViewAccess a("127.0.0.1", 8765, token);
  CHECK(a.tokenRequired());
  CHECK(a.tokenPresented("/?token=" + token, "", ""));
  CHECK(a.tokenPresented("/?x=1&token=" + token + "&y=2", "", ""));
  CHECK(a.tokenPresented("/viewer.js", "other=1; fgsg-view-token-8765=" + token, ""));
  CHECK(a.tokenPresented("/", "", "token " + token));
  CHECK_FALSE(a.tokenPresented("/", "", ""));
  CHECK_FALSE(a.tokenPresented("/?token=", "", ""));
  CHECK_FALSE(a.tokenPresented("/?token=" + token.substr(1), "", ""));
  CHECK_FALSE(a.tokenPresented("/?token=" + token + "0", "", ""));
  CHECK_FALSE(a.tokenPresented("/?notoken=" + token, "", ""));
  CHECK_FALSE(a.tokenPresented("/", "fgsg-view-token-8766=" + token, ""));  // another server's cookie
  CHECK_FALSE(a.tokenPresented("/", "", "Bearer " + token));
  CHECK(a.setCookieHeader().find("HttpOnly") != std::string::npos);
  CHECK(a.setCookieHeader().find("SameSite=Strict") != std::string::npos);
  CHECK(a.url("127.0.0.1") == "http://127.0.0.1:8765/?token=" + token);
  const ViewAccess open("127.0.0.1", 8765, "");
  CHECK_FALSE(open.tokenRequired());
  CHECK(open.tokenPresented("/", "", ""));
  CHECK(open.url("::1") == "http://[::1]:8765/");
}

TEST_CASE("view access: which --host counts as this machine only") {
  CHECK(fgsg::cli::isLoopbackHost("127.0.0.1"));
  CHECK(fgsg::cli::isLoopbackHost("127.0.0.2"));
  CHECK(fgsg::cli::isLoopbackHost("::1"));
  CHECK_FALSE(fgsg::cli::isLoopbackHost("0.0.0.0"));
  CHECK_FALSE(fgsg::cli::isLoopbackHost("::"));
  CHECK_FALSE(fgsg::cli::isLoopbackHost("192.168.1.5"));
}
