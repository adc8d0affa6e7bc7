#include "cli/view_server.h"

#include <websocketpp/config/asio_no_tls.hpp>
#include <websocketpp/server.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace fgsg::cli {

namespace fs = std::filesystem;
using Server = websocketpp::server<websocketpp::config::asio>;
using Handle = websocketpp::connection_hdl;

namespace {

const char* contentType(const fs::path& file) {
  const std::string ext = file.extension().string();
  if (ext == ".html") return "text/html; charset=utf-8";
  if (ext == ".js" || ext == ".mjs") return "text/javascript; charset=utf-8";
  if (ext == ".css") return "text/css; charset=utf-8";
  if (ext == ".png") return "image/png";
  if (ext == ".json") return "application/json";
  return "application/octet-stream";
}

}  // namespace

struct ViewServer::Impl {
  std::string staticDir;
  Handlers handlers;
  Server server;
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

  // A file under the static folder for a request's path ("/" is index.html); no "..".
  bool resolve(const std::string& resource, fs::path& file) const {
    std::string path = resource.substr(0, resource.find_first_of("?#"));
    if (path == "/" || path.empty()) path = "/index.html";
    if (path.find("..") != std::string::npos) return false;
    file = fs::path(staticDir) / path.substr(1);
    std::error_code ec;
    return fs::is_regular_file(file, ec);
  }

  void serveFile(Handle h) {
    Server::connection_ptr c = server.get_con_from_hdl(h);
    fs::path file;
    if (c->get_request().get_method() != "GET" || !resolve(c->get_resource(), file)) {
      c->set_status(websocketpp::http::status_code::not_found);
      c->set_body("not found: " + c->get_resource() + "\n");
      return;
    }
    std::ifstream in(file, std::ios::binary);
    std::ostringstream body;
    body << in.rdbuf();
    c->set_status(websocketpp::http::status_code::ok);
    c->append_header("Content-Type", contentType(file));
    c->append_header("Cache-Control", "no-store");
    c->set_body(body.str());
  }

  void sendToAll(const std::string& payload, websocketpp::frame::opcode::value op) {
    for (const auto& [h, id] : pages) {
      websocketpp::lib::error_code ec;
      server.send(h, payload, op, ec);  // a page that went away is dropped on close
    }
  }

  void sendTo(uint64_t page, const std::string& payload, websocketpp::frame::opcode::value op) {
    for (const auto& [h, id] : pages)
      if (id == page) {
        websocketpp::lib::error_code ec;
        server.send(h, payload, op, ec);
      }
  }
};

ViewServer::ViewServer(std::string staticDir, Handlers handlers) : impl_(std::make_unique<Impl>()) {
  Impl& s = *impl_;
  s.staticDir = std::move(staticDir);
  s.handlers = std::move(handlers);
  s.server.clear_access_channels(websocketpp::log::alevel::all);
  s.server.clear_error_channels(websocketpp::log::elevel::all);
  s.server.init_asio();
  s.server.set_reuse_addr(true);
  s.server.set_http_handler([this](Handle h) { impl_->serveFile(h); });
  s.server.set_open_handler([this](Handle h) {
    const uint64_t id = impl_->nextPage++;
    impl_->pages[h] = id;
    if (impl_->handlers.opened) impl_->handlers.opened(id);
  });
  s.server.set_close_handler([this](Handle h) { impl_->pages.erase(h); });
  s.server.set_fail_handler([this](Handle h) { impl_->pages.erase(h); });
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
    error = "cannot listen on " + host + ":" + std::to_string(port) + ": " + wec.message();
    return false;
  }
  impl_->server.start_accept(wec);
  if (wec) {
    error = "cannot accept connections: " + wec.message();
    return false;
  }
  return true;
}

uint16_t ViewServer::port() const {
  websocketpp::lib::asio::error_code ec;
  return impl_->server.get_local_endpoint(ec).port();
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

void ViewServer::sendTextToAll(std::string text) {
  post([this, text = std::move(text)] { impl_->sendToAll(text, websocketpp::frame::opcode::text); });
}

void ViewServer::sendBinaryToAll(std::string bytes) {
  post([this, bytes = std::move(bytes)] { impl_->sendToAll(bytes, websocketpp::frame::opcode::binary); });
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
