// fgsg view: a live viewer in the browser. A local server (view_server.h) serves a page
// that draws the derived model with three.js; saving the grammar (or a file beside it)
// re-derives and pushes the new model, the page's attribute fields and seed re-derive at
// once, and errors show in the page with the last good model kept (view_session.h).
#include "backend/native/code_loader.h"
#include "cli/command_line.h"
#include "cli/option_help.h"
#include "cli/commands.h"
#include "cli/derive_flags.h"
#include "cli/options.h"
#include "cli/view_access.h"
#include "cli/view_server.h"
#include "cli/view_session.h"
#include "runtime/abandonable.h"
#include "runtime/io/cache_folder.h"
#include "runtime/io/read_input.h"

#include <atomic>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>

namespace fgsg::cli {

namespace {

const char* kViewHelp = R"(usage: fgsg view FILE [--port N] [--host ADDRESS] [--no-token] [--seed N]
                 [--set name=value]... [--surface mesh.off] [--engine jit|interp]
                 [--start-rule NAME] [--seed-points FILE] [--steps] [--step N]

Serves a page at http://ADDRESS:N/?token=... (default 127.0.0.1, port 8765; --port 0
picks a free one) that shows FILE's model and re-derives it live: when FILE or a file in
its folder or its assets/ folder is saved, when an attribute is changed in the page's
inspector, and when the seed is stepped. Each open page has its own values and seed.
Errors show in the page; the last good model stays. Ctrl-C stops the server.

With --steps, an L-system (`derive parallel N;`) gets a slider from 0 (its axiom) to N
and a play button: the page shows its derivation after that many steps (--step N: where
it starts; without --steps, the page shows step N), each step derived when asked and
kept for the next time it is asked.

On a surface the page also edits what a run reads from files: the seeds of on-mesh
marching (click the surface, drag, set a heading), written to FILE of --seed-points
(default: FILE's name with .seeds, beside it) as `fgsg run --seed-points` reads them;
and the grammar's textures, painted with a brush and written back as grey PNG (only
files inside the grammar's folder). Every page re-derives after such an edit.

The server answers only requests that name it (Host 127.0.0.1, localhost, [::1] or
--host), WebSockets only from its own page (Origin), and only with the session token
printed in the address; it serves the page's own files and nothing else. --no-token
drops the token (any program on this machine may then connect); --host 0.0.0.0 or
another address reachable from the network needs the token. Documentation: docs/cli.md
(fgsg view, Security).
)";

std::atomic<bool> stopRequested{false};
extern "C" void onStopSignal(int) { stopRequested = true; }

struct ViewCommandOptions {
  ViewOptions view;
  std::string host = "127.0.0.1";
  uint16_t port = 8765;
  bool noToken = false;
};

ViewCommandOptions parseViewOptions(const Args& args) {
  ViewCommandOptions o;
  CommandLine cl("view");
  cl.input(o.view.file, "grammar file");
  cl.whole("--port", o.port, 0, 65535);
  cl.text("--host", o.host);
  cl.flag("--no-token", o.noToken);
  cl.whole("--seed", o.view.derive.seed);
  surfaceFlags(cl, o.view.derive);
  engineFlag(cl, o.view.engine);
  setFlag(cl, o.view.derive);
  startRuleFlag(cl, o.view.startRule);
  cl.text("--seed-points", o.view.seedFile);
  cl.flag("--steps", o.view.steps);
  stepFlag(cl, o.view.derive);
  cl.parse(args);
  if (o.view.file.empty()) throw UsageError{"no grammar file given: fgsg view FILE [options]"};
  // fgsg view writes its seeds to a file: an inline list ("x,y,z") has nowhere to go.
  if (o.view.seedFile.find_first_of(",;") != std::string::npos)
    throw UsageError{"--seed-points " + o.view.seedFile + ": fgsg view takes a seed file (it writes the seeds the page places)"};
  if (o.noToken && !isLoopbackHost(o.host))
    throw UsageError{"--host " + o.host + " with --no-token: a server reachable from the network needs its token"};
  return o;
}

int view(const Args& args) {
  for (const std::string& a : args)
    if (a == "--help" || a == "-h") {
      std::cout << kViewHelp << optionHelp("view");
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
  if (opt.view.seedFile.empty()) opt.view.seedFile = defaultSeedFile(opt.view.file);
  opt.view.seedFile = std::filesystem::absolute(opt.view.seedFile).lexically_normal().string();
  {
    ViewSeeds seeds;
    if (!readSeedFile(opt.view.seedFile, seeds, error)) {
      std::cerr << "fgsg view: " << error << "\n";
      return 1;
    }
  }
  // Surfaces laid out once are kept, as fgsg run keeps them (a page's edit derives again).
  if (const std::string cache = rt::io::cacheFolder(); !cache.empty()) opt.view.derive.atlasCacheDir = cache + "/atlas";
  const std::string pageDir = findViewerDir(error);
  ViewStaticFiles page;
  if (pageDir.empty() || !page.load(pageDir, error)) {
    std::cerr << "fgsg view: " << error << "\n";
    return 1;
  }

  std::unique_ptr<ViewSession> session;
  ViewServer server(std::move(page), opt.noToken ? std::string() : newViewToken(),
                    {[&](uint64_t id) { session->pageOpened(id); },
                     [&](uint64_t id, const std::string& m) { session->message(id, m); },
                     [&](uint64_t id) { session->pageClosed(id); }});
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
  std::cout << "fgsg view: " << opt.view.file << " at " << server.url() << " (Ctrl-C stops)" << std::endl;
  server.run();
  session.reset();
  return 0;
}

}  // namespace

int viewCommand(const Args& args) {
  const int code = view(args);
  if (backend::native::abandonedCompiles() > 0 || rt::abandonedWorkers() > 0) {
    // A background compile still runs LLVM, or a worker abandoned at --max-seconds still
    // runs CGAL: end without destroying static objects under them.
    std::cout.flush();
    std::fflush(nullptr);
    std::_Exit(code);
  }
  return code;
}

}  // namespace fgsg::cli
