#include "cli/view_server.h"

#include "cli/view_access.h"

#include <websocketpp/config/asio_no_tls.hpp>
#include <websocketpp/server.hpp>

#include <cstdlib>
#include <filesystem>
#include <map>

namespace fgsg::cli {

namespace fs = std::filesystem;
using Server = websocketpp::server<websocketpp::config::asio>;
using Handle = websocketpp::connection_hdl;
using Status = websocketpp::http::status_code::value;

namespace {

// Frames beyond this are refused by the protocol layer (close 1009); up to it the session
// answers an oversized message with a reason (view_message.h caps it lower).
constexpr size_t kMaxFrameBytes = size_t(256) << 10;
// A page that reads more slowly than models come is closed before its queue grows past this.
constexpr size_t kMaxQueuedBytes = size_t(512) << 20;
constexpr size_t kMaxResourceBytes = 2048;

}  // namespace

struct ViewServer::Impl {
  ViewStaticFiles files;
  std::string token;
  Handlers handlers;
  Server server;
  std::string host;
  std::unique_ptr<ViewAccess> access;  // made by listen(), once the port is known
  std::map<Handle, uint64_t, std::owner_less<Handle>> pages;  // open pages and their ids
  uint64_t nextPage = 0;
  struct Ticker {
    boost::asio::steady_timer timer;
    int milliseconds;
    std::function<void()> tick;
  };
  std::vector<std::unique_ptr<Ticker>> tickers;

  void arm(Ticker* t) {
    t->timer.expires_after(std::chrono::milliseconds(t->milliseconds));
    t->timer.async_wait([this, t](const boost::system::error_code& ec) {
      if (ec) return;  // cancelled: the server stops
      t->tick();
      arm(t);
    });
  }

  static void refuse(Server::connection_ptr c, Status status, const std::string& why) {
    c->set_status(status);
    c->append_header("Content-Type", "text/plain; charset=utf-8");
    c->set_body("fgsg view: " + why + "\n");
  }

  // Host, then token: which requests may be answered at all. False: refused (set on `c`).
  bool admitted(Server::connection_ptr c) {
    const auto& request = c->get_request();
    if (!access || !access->hostAllowed(request.get_header("Host"))) {
      refuse(c, websocketpp::http::status_code::forbidden, "this server answers only to its own address (Host)");
      return false;
    }
    if (c->get_resource().size() > kMaxResourceBytes) {
      refuse(c, websocketpp::http::status_code::not_found, "not found");
      return false;
    }
    if (!access->tokenPresented(c->get_resource(), request.get_header("Cookie"), request.get_header("Authorization"))) {
      refuse(c, websocketpp::http::status_code::forbidden,
             "open the page with the address fgsg view printed, token included (http://HOST:PORT/?token=...)");
      return false;
    }
    return true;
  }

  void serveFile(Handle h) {
    Server::connection_ptr c = server.get_con_from_hdl(h);
    if (!admitted(c)) return;
    const std::string& method = c->get_request().get_method();
    if (method != "GET" && method != "HEAD") {
      refuse(c, websocketpp::http::status_code::method_not_allowed, "only GET");
      return;
    }
    const ViewStaticFiles::File* file = files.find(c->get_resource());
    if (!file) {
      refuse(c, websocketpp::http::status_code::not_found, "not found");
      return;
    }
    c->set_status(websocketpp::http::status_code::ok);
    c->append_header("Content-Type", file->contentType);
    c->append_header("Cache-Control", "no-store");
    c->append_header("X-Content-Type-Options", "nosniff");
    c->append_header("X-Frame-Options", "DENY");
    c->append_header("Referrer-Policy", "no-referrer");  // the token stays out of other sites' logs
    // The page's scripts and WebSocket then carry the token without repeating it.
    if (access->tokenRequired()) c->append_header("Set-Cookie", access->setCookieHeader());
    c->set_body(method == "HEAD" ? std::string() : file->body);
  }

  // A WebSocket handshake: as HTTP, and from the page's own Origin, and not too many.
  bool validate(Handle h) {
    Server::connection_ptr c = server.get_con_from_hdl(h);
    if (!admitted(c)) return false;
    const auto& request = c->get_request();
    if (!access->originAllowed(request.get_header("Origin"), request.get_header("Host"))) {
      refuse(c, websocketpp::http::status_code::forbidden, "a page of another site (Origin) may not connect");
      return false;
    }
    if (pages.size() >= kMaxViewPages) {
      refuse(c, websocketpp::http::status_code::service_unavailable,
             "too many pages open (at most " + std::to_string(kMaxViewPages) + ")");
      return false;
    }
    return true;
  }

  void sendTo(uint64_t page, const std::string& payload, websocketpp::frame::opcode::value op) {
    for (const auto& [h, id] : pages)
      if (id == page) {
        websocketpp::lib::error_code ec;
        Server::connection_ptr c = server.get_con_from_hdl(h, ec);
        if (ec) return;
        if (c->get_buffered_amount() + payload.size() > kMaxQueuedBytes) {
          server.close(h, websocketpp::close::status::policy_violation, "the page reads too slowly", ec);
          return;
        }
        server.send(h, payload, op, ec);  // a page that went away is dropped on close
        return;
      }
  }

  void forget(Handle h) {
    const auto it = pages.find(h);
    if (it == pages.end()) return;
    const uint64_t id = it->second;
    pages.erase(it);
    if (handlers.closed) handlers.closed(id);
  }
};

ViewServer::ViewServer(ViewStaticFiles files, std::string token, Handlers handlers)
    : impl_(std::make_unique<Impl>()) {
  Impl& s = *impl_;
  s.files = std::move(files);
  s.token = std::move(token);
  s.handlers = std::move(handlers);
  s.server.clear_access_channels(websocketpp::log::alevel::all);
  s.server.clear_error_channels(websocketpp::log::elevel::all);
  s.server.init_asio();
  s.server.set_reuse_addr(true);
  s.server.set_max_message_size(kMaxFrameBytes);
  s.server.set_max_http_body_size(4096);  // GET has no body
  s.server.set_http_handler([this](Handle h) { impl_->serveFile(h); });
  s.server.set_validate_handler([this](Handle h) { return impl_->validate(h); });
  s.server.set_open_handler([this](Handle h) {
    const uint64_t id = impl_->nextPage++;
    impl_->pages[h] = id;
    if (impl_->handlers.opened) impl_->handlers.opened(id);
  });
  s.server.set_close_handler([this](Handle h) { impl_->forget(h); });
  s.server.set_fail_handler([this](Handle h) { impl_->forget(h); });
  s.server.set_message_handler([this](Handle h, Server::message_ptr m) {
    auto page = impl_->pages.find(h);
    if (m->get_opcode() == websocketpp::frame::opcode::text && impl_->handlers.message && page != impl_->pages.end())
      impl_->handlers.message(page->second, m->get_payload());
  });
}

ViewServer::~ViewServer() = default;

bool ViewServer::listen(const std::string& host, uint16_t port, std::string& error) {
  boost::system::error_code ec;
  const auto address = boost::asio::ip::make_address(host, ec);
  if (ec) {
    error = "--host " + host + ": not an IP address (" + ec.message() + ")";
    return false;
  }
  websocketpp::lib::error_code wec;
  impl_->server.listen(boost::asio::ip::tcp::endpoint(address, port), wec);
  if (wec) {
    // websocketpp says only "Underlying Transport Error": ask the system what it was.
    boost::asio::io_context probeContext;
    boost::asio::ip::tcp::acceptor probe(probeContext);
    boost::system::error_code why;
    probe.open(address.is_v6() ? boost::asio::ip::tcp::v6() : boost::asio::ip::tcp::v4(), why);
    if (!why) probe.bind(boost::asio::ip::tcp::endpoint(address, port), why);
    error = "cannot listen on " + host + ":" + std::to_string(port) + ": " + (why ? why.message() : wec.message());
    if (why == boost::asio::error::address_in_use)
      error += " (another fgsg view?): choose another --port, or --port 0 for a free one";
    return false;
  }
  impl_->server.start_accept(wec);
  if (wec) {
    error = "cannot accept connections: " + wec.message();
    return false;
  }
  impl_->host = host;
  impl_->access = std::make_unique<ViewAccess>(host, this->port(), impl_->token);
  return true;
}

uint16_t ViewServer::port() const {
  websocketpp::lib::asio::error_code ec;
  return impl_->server.get_local_endpoint(ec).port();
}

std::string ViewServer::url() const {
  // Listening on every address, the page is still opened here.
  const bool everywhere = impl_->host == "0.0.0.0" || impl_->host == "::";
  return impl_->access->url(everywhere ? "127.0.0.1" : impl_->host);
}

void ViewServer::run() { impl_->server.run(); }

void ViewServer::stop() {
  post([this] {
    websocketpp::lib::error_code ec;
    impl_->server.stop_listening(ec);
    for (const auto& [h, id] : impl_->pages) impl_->server.close(h, websocketpp::close::status::going_away, "bye", ec);
    for (auto& t : impl_->tickers) t->timer.cancel();
    impl_->server.stop();
  });
}

void ViewServer::sendText(uint64_t page, std::string text) {
  post([this, page, text = std::move(text)] { impl_->sendTo(page, text, websocketpp::frame::opcode::text); });
}

void ViewServer::sendBinary(uint64_t page, std::string bytes) {
  post([this, page, bytes = std::move(bytes)] { impl_->sendTo(page, bytes, websocketpp::frame::opcode::binary); });
}

void ViewServer::post(std::function<void()> task) { boost::asio::post(impl_->server.get_io_service(), std::move(task)); }

void ViewServer::every(int milliseconds, std::function<void()> tick) {
  impl_->tickers.push_back(std::make_unique<Impl::Ticker>(
      Impl::Ticker{boost::asio::steady_timer(impl_->server.get_io_service()), milliseconds, std::move(tick)}));
  impl_->arm(impl_->tickers.back().get());
}

std::string findViewerDir(std::string& error) {
  std::error_code ec;
  fs::path dir;
  const char* env = std::getenv("FGSG_VIEWER_DIR");
  if (env && *env) {
    dir = fs::absolute(env, ec);
  } else {
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    dir = exe.parent_path().parent_path() / "share" / "fgsg" / "viewer";
  }
  if (!fs::is_regular_file(dir / "index.html", ec) || !fs::is_regular_file(dir / "three" / "build" / "three.module.js", ec)) {
    error = "the viewer's page is not in " + dir.lexically_normal().string() +
            " (index.html and three/build/three.module.js): build fgsg after scripts/install-deps.sh has installed "
            "three.js, or set FGSG_VIEWER_DIR";
    return "";
  }
  return dir.lexically_normal().string();
}

}  // namespace fgsg::cli
