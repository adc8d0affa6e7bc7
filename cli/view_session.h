// What `fgsg view` shows: the grammar derived with the page's attribute values and
// seed, derived again on a worker thread whenever a page asks or a file the grammar may
// read (the grammar, its folder, its assets/ folder) changes. Each result reaches the
// pages as a JSON message, then the model as binary glTF; a grammar with errors sends
// its diagnostics and the pages keep the last good model. Messages (docs/cli.md):
//   to the page:   {"type":"info", "file", "attrs":[{name, type, default, value}], "seed"}
//                  {"type":"progress", "state":"deriving"}
//                  {"type":"model", "figures":{...}, "milliseconds", "groups":[{asset, count}]},
//                   then binary: the rest of the model as .glb, and per group its asset's
//                   .glb, its matrices and colours (Float32) and its instances' numbers
//                   (Uint32) in the derivation (view_scene.h)
//                  {"type":"picked", "instance", "symbol", "asset", "params", "colour", "centre"}
//                  {"type":"error", "diagnostics":"file:line:col: error[...] ...\n  line\n  ^"}
//   from the page: {"type":"set", "attrs":{"name":"value", ...}, "seed":N}
//                  {"type":"pick", "instance":N}
#pragma once

#include "backend/engine.h"
#include "cli/view_server.h"
#include "runtime/derivation.h"

#include <condition_variable>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

namespace fgsg::backend::native {
class CodeLoader;
}

namespace fgsg::cli {

struct CompiledFile;

struct ViewOptions {
  std::string file;
  rt::DeriveOptions derive;  // --surface, --set (the first values), --seed ...
  backend::Engine engine = backend::Engine::Jit;
};

class ViewSession {
 public:
  ViewSession(ViewOptions options, ViewServer& server);
  ~ViewSession();  // stops and joins the worker
  ViewSession(const ViewSession&) = delete;
  ViewSession& operator=(const ViewSession&) = delete;

  void pageOpened(uint64_t page);             // a new page gets the last info and model
  void message(uint64_t page, const std::string& json);  // a page's {"type":"set" / "pick", ...}
  void checkFiles();                          // the server's timer: re-derive on a change

 private:
  void work();
  void deriveOnce(bool recompile, const std::map<std::string, std::string>& attrs, uint64_t seed);
  void pick(uint64_t page, uint32_t instance);  // {"type":"pick","instance":N}: who placed it
  std::string infoJson(const std::map<std::string, std::string>& attrs, uint64_t seed) const;
  // The grammar, its folder and assets/, and the data files it names (grammarDataFiles).
  std::map<std::string, std::filesystem::file_time_type> watchedFiles(const std::vector<std::string>& data) const;

  ViewOptions options_;
  ViewServer& server_;
  std::unique_ptr<CompiledFile> compiled_;  // the last grammar that compiled (worker only)
  std::unique_ptr<backend::native::CodeLoader> loader_;  // its JIT code (worker only)

  std::mutex mutex_;  // guards what follows
  std::condition_variable wake_;
  bool pending_ = true, recompile_ = true, stopping_ = false;
  std::map<std::string, std::string> attrs_;  // the page's values, by attribute name
  uint64_t seed_ = 1;
  std::string lastInfo_, lastModelJson_, lastError_;
  std::vector<std::string> lastParts_;  // the last model's binary messages
  rt::InstanceList lastInstances_;      // its instances, for picking
  std::vector<std::string> lastRules_;  // its grammar's rules as picking names them
  std::map<std::string, std::filesystem::file_time_type> seen_;
  std::vector<std::string> dataFiles_;  // the files the last compiled grammar names

  std::thread worker_;
};

}  // namespace fgsg::cli
