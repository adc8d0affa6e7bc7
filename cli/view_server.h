// The local server of `fgsg view`: the viewer's page and its scripts over HTTP, and the
// models pushed to each open page over a WebSocket, on one port (websocketpp from
// Debian's libwebsocketpp-dev, on Boost.Asio). Everything it calls back runs on the
// thread inside run(); the send and post functions may be called from any thread.
//
// It is careful as Jupyter's server is (docs/cli.md, "Security"): it serves only the
// page's own files, read at start (view_static_files.h); every request must name this
// server in its Host, a WebSocket must come from the page's own Origin, and both must
// carry the session token (view_access.h); messages and pages are bounded in size and
// number.
#pragma once

#include "cli/view_static_files.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace fgsg::cli {

class ViewAccess;

// At most this many pages at once; more get 503 until one closes.
constexpr size_t kMaxViewPages = 64;

class ViewServer {
 public:
  struct Handlers {
    std::function<void(uint64_t page)> opened;            // a page connected (ids count up)
    std::function<void(uint64_t page, const std::string&)> message;  // a page sent a text message
    std::function<void(uint64_t page)> closed;            // a page went away
  };

  // `files`: the page (index.html, viewer.js, three.js's modules); `token`: what every
  // request must carry (empty: none, --no-token).
  ViewServer(ViewStaticFiles files, std::string token, Handlers handlers);
  ~ViewServer();
  ViewServer(const ViewServer&) = delete;
  ViewServer& operator=(const ViewServer&) = delete;

  // Binds `host`:`port` (port 0: any free one). False with a message.
  bool listen(const std::string& host, uint16_t port, std::string& error);
  uint16_t port() const;
  // The page's address with its token, for the user to open (after listen).
  std::string url() const;
  // Serves until stop().
  void run();
  void stop();

  void sendText(uint64_t page, std::string text);  // to one page (gone: dropped)
  void sendBinary(uint64_t page, std::string bytes);
  void post(std::function<void()> task);  // runs `task` on the server's thread
  // Calls `tick` every `milliseconds` on the server's thread.
  void every(int milliseconds, std::function<void()> tick);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The folder of the viewer's page: $FGSG_VIEWER_DIR, else share/fgsg/viewer beside the
// executable's bin/. Empty, with a message, when its index.html is not there.
std::string findViewerDir(std::string& error);

}  // namespace fgsg::cli
