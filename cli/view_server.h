// The local server of `fgsg view`: the viewer's page and its scripts over HTTP, and the
// models pushed to every open page over a WebSocket, on one port (websocketpp from
// Debian's libwebsocketpp-dev, on Boost.Asio). Everything it calls back runs on the
// thread inside run(); the send and post functions may be called from any thread.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace fgsg::cli {

class ViewServer {
 public:
  struct Handlers {
    std::function<void(uint64_t page)> opened;            // a page connected (ids count up)
    std::function<void(uint64_t page, const std::string&)> message;  // a page sent a text message
  };

  // `staticDir` holds index.html, viewer.js and three/ (the build's share/fgsg/viewer).
  ViewServer(std::string staticDir, Handlers handlers);
  ~ViewServer();
  ViewServer(const ViewServer&) = delete;
  ViewServer& operator=(const ViewServer&) = delete;

  // Binds `host`:`port` (port 0: any free one). False with a message.
  bool listen(const std::string& host, uint16_t port, std::string& error);
  uint16_t port() const;
  // Serves until stop().
  void run();
  void stop();

  void sendTextToAll(std::string text);
  void sendBinaryToAll(std::string bytes);
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
