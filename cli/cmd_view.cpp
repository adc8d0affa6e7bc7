// fgsg view: a live viewer in the browser. A local server (view_server.h) serves a page
// that draws the derived model with three.js; saving the grammar (or a file beside it)
// re-derives and pushes the new model, the page's attribute fields and seed re-derive at
// once, and errors show in the page with the last good model kept (view_session.h).
#include "backend/native/code_loader.h"
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/derive_flags.h"
#include "cli/options.h"
#include "cli/view_server.h"
#include "cli/view_session.h"
#include "runtime/io/read_input.h"

#include <atomic>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>

namespace fgsg::cli {

namespace {

const char* kViewHelp = R"(usage: fgsg view FILE [--port N] [--host ADDRESS] [--seed N] [--set name=value]...
                 [--surface mesh.off] [--engine jit|interp]

Serves a page at http://ADDRESS:N/ (default 127.0.0.1, port 8765; --port 0 picks a free
one) that shows FILE's model and re-derives it live: when FILE or a file in its folder
or its assets/ folder is saved, when an attribute is changed in the page's inspector,
and when the seed is stepped. Errors show in the page; the last good model stays.
Ctrl-C stops the server. Documentation: docs/cli.md (fgsg view).
)";

std::atomic<bool> stopRequested{false};
extern "C" void onStopSignal(int) { stopRequested = true; }

struct ViewCommandOptions {
  ViewOptions view;
  std::string host = "127.0.0.1";
  uint16_t port = 8765;
};

ViewCommandOptions parseViewOptions(const Args& args) {
  ViewCommandOptions o;
  CommandLine cl("view");
  cl.input(o.view.file, "grammar file");
  cl.whole("--port", o.port, 0, 65535);
  cl.text("--host", o.host);
  cl.whole("--seed", o.view.derive.seed);
  surfaceFlags(cl, o.view.derive);
  engineFlag(cl, o.view.engine);
  setFlag(cl, o.view.derive);
  cl.parse(args);
  if (o.view.file.empty()) throw UsageError{"no grammar file given: fgsg view FILE [options]"};
  return o;
}

int view(const Args& args) {
  for (const std::string& a : args)
    if (a == "--help" || a == "-h") {
      std::cout << kViewHelp;
      return 0;
    }
  ViewCommandOptions opt;
  try {
    opt = parseViewOptions(args);
  } catch (const UsageError& e) {
    std::cerr << "fgsg view: " << e.message << "\n";
    return 2;
  }
  std::string error;
  if (!rt::io::checkInputFile(opt.view.file, "a grammar file", error)) {
    std::cerr << "fgsg view: " << error << "\n";
    return 1;
  }
  if (!opt.view.derive.surfaceOverride.empty()) {
    if (!rt::io::checkInputFile(opt.view.derive.surfaceOverride, "a mesh file", error)) {
      std::cerr << "fgsg view: --surface " << error << "\n";
      return 1;
    }
    opt.view.derive.surfaceOverride = std::filesystem::absolute(opt.view.derive.surfaceOverride).string();
  }
  const std::string pageDir = findViewerDir(error);
  if (pageDir.empty()) {
    std::cerr << "fgsg view: " << error << "\n";
    return 1;
  }

  std::unique_ptr<ViewSession> session;
  ViewServer server(pageDir, {[&](uint64_t page) { session->pageOpened(page); },
                             [&](uint64_t page, const std::string& m) { session->message(page, m); }});
  if (!server.listen(opt.host, opt.port, error)) {
    std::cerr << "fgsg view: " << error << "\n";
    return 1;
  }
  session = std::make_unique<ViewSession>(opt.view, server);
  std::signal(SIGINT, onStopSignal);
  std::signal(SIGTERM, onStopSignal);
  server.every(200, [&] {
    if (stopRequested) return server.stop();
    session->checkFiles();
  });
  std::cout << "fgsg view: " << opt.view.file << " at http://" << opt.host << ":" << server.port() << "/"
            << " (Ctrl-C stops)" << std::endl;
  server.run();
  session.reset();
  return 0;
}

}  // namespace

int viewCommand(const Args& args) {
  const int code = view(args);
  if (backend::native::abandonedCompiles() > 0) {
    // A background compile still runs LLVM: end without destroying its static objects.
    std::cout.flush();
    std::fflush(nullptr);
    std::_Exit(code);
  }
  return code;
}

}  // namespace fgsg::cli
