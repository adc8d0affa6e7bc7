// What `fgsg view` shows: the grammar derived with each page's own attribute values and
// seed (a new page starts from the command line's --set and --seed, else the grammar's
// defaults), derived again on a worker thread whenever a page asks or a file the grammar
// may read (the grammar, its folder, its assets/ folder) changes. Pages asking for the
// same values share one derivation. Each result reaches its pages as a JSON message,
// then the model as binary glTF; a grammar with errors sends its diagnostics and the
// pages keep their last good model. Messages (docs/cli.md):
//   to the page:   {"type":"info", "file", "attrs":[{name, type, default, value}], "seed"}
//                  {"type":"progress", "state":"deriving"}
//                  {"type":"model", "figures":{...}, "milliseconds", "placing":[[node, count], ...],
//                   "steps":{"step", "length"} (with --steps, for an L-system)},
//                   then binary: the scene as .glb (as fgsg run -o FILE.glb writes it),
//                   and the instance numbers (Uint32) in the derivation that its placing
//                   nodes hold, node after node (view_scene.h)
//                  {"type":"pieces", "figures", "milliseconds", "seed", "bases", "sent":[{"piece", "placing"}, ...]}:
//                   a model of seeds derived apart, a piece per seed and the rest after them
//                   (view_pieces.h), then binary: per piece in "sent", its .glb and instance
//                   numbers (from "bases"[piece]); the page keeps the pieces not sent
//                  {"type":"picked", "instance", "symbol", "asset", "params", "colour", "centre"}
//                  {"type":"error", "diagnostics":"file:line:col: error[...] ...\n  line\n  ^"}
//                  {"type":"rejected", "reason"}: a message of the page's that changed nothing
//                  {"type":"surface", "triangles", "textures":[{name, width, height, why}]},
//                   then binary: the surface as .glb (view_surface.h), for seeds and paint
//                  {"type":"written", "file"}: a seed file or texture the page's edit wrote
//                  {"type":"field", ...}: the field overlay (view_field.h), asked for
//   from the page: {"type":"set", "attrs":{"name":"value", ...}, "seed":N, "step":N}
//                   ("step" with --steps only, 0 to the derivation's length)
//                  {"type":"pick", "instance":N}
//                  {"type":"seeds", ...}, {"type":"paint", ...}, {"type":"undo"|"redo"}, {"type":"field"}
//                  {"type":"undo"|"redo", "history":"field"}: the last design element edit
//                  {"type":"fieldElement", ...}: a design element of the first field edited in
//                   the grammar's text (view_field_edit.h), then compiled again
//                  {"type":"resend"}: the last model again, every piece (the page lost some)
//                                                          (checked first: view_message.h)
// Seeds and painted textures are files, so they are the session's, not a page's: an
// edit re-derives every page (#49).
#pragma once

#include "backend/engine.h"
#include "backend/commands/surface_geometry.h"
#include "backend/engine/surface_reuse.h"
#include "cli/view_field_edit.h"
#include "cli/view_field_history.h"
#include "cli/view_paint.h"
#include "cli/view_pieces.h"
#include "cli/view_seed_file.h"
#include "cli/view_server.h"
#include "cli/view_surface.h"
#include "ir/ir.h"
#include "runtime/derivation.h"

#include <condition_variable>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <tuple>

namespace fgsg::backend::native {
class CodeLoader;
}

namespace fgsg::cli {

struct CompiledFile;

struct ViewOptions {
  std::string file;
  std::string startRule;     // --start-rule: a .cga grammar's rule instead of its @StartRule
  rt::DeriveOptions derive;  // --surface, --set (the first values), --seed ...
  backend::Engine engine = backend::Engine::Jit;
  std::string seedFile;  // absolute: where the page's seeds are written (view_seed_file.h)
  bool steps = false;    // --steps: the page steps through an L-system's derivation
};

class ViewSession {
 public:
  ViewSession(ViewOptions options, ViewServer& server);
  ~ViewSession();  // stops and joins the worker
  ViewSession(const ViewSession&) = delete;
  ViewSession& operator=(const ViewSession&) = delete;

  void pageOpened(uint64_t page);             // a new page: the starting values, derived
  void pageClosed(uint64_t page);
  void message(uint64_t page, const std::string& json);  // a page's {"type":"set" / "pick", ...}
  void checkFiles();                          // the server's timer: re-derive on a change

 private:
  // One derivation's messages, shared by the pages that asked for the same values.
  struct Derived {
    std::string info;       // empty when the grammar did not compile
    std::string modelJson;  // empty when it failed: `error` says why
    std::string error;
    std::vector<std::string> parts;  // the model's binary messages
    ViewPieces pieces;               // or its pieces (modelJson then the "pieces" header without "sent")
    rt::InstanceList instances;      // for picking
    std::vector<std::string> rules;  // the grammar's rules as picking names them
    std::shared_ptr<const std::pair<std::string, std::string>> surface;  // JSON, .glb (null: none)
  };
  struct Page {
    std::map<std::string, std::string> attrs;  // the page's values, by attribute name
    uint64_t seed = 1;
    int32_t step = -1;  // the L-system's derivation step shown; -1: its whole length
    bool pending = true;
    std::string infoSent;
    std::shared_ptr<const Derived> model;  // its last good model, for picking
    const void* surfaceSent = nullptr;
    std::vector<std::shared_ptr<const ViewPiece>> pieces;  // the pieces it shows (held: compared by address)
    bool fieldAsked = false, fieldDue = false;  // the field overlay: wanted, owed (view_field.h)
  };

  void work();
  // Compiles the grammar file: compiled_ and its surface, or compileError_ (worker).
  void compile();
  std::shared_ptr<Derived> derive(bool recompile, const std::map<std::string, std::string>& attrs, uint64_t seed,
                                  const ViewSeeds& seeds, int32_t step);
  // {"type":"set", "step":N}: why the page cannot be shown step N with these values
  // (not --steps, no L-system, past its length); empty when it can. Under mutex_.
  std::string stepProblem(uint32_t step, const std::map<std::string, std::string>& attrs) const;
  void prepareSurface(const std::vector<std::string>& dataDirs);  // after a compile (worker)
  // A seed file or texture written for a page: seen (no second derivation), every page
  // derived again, the page told. Under mutex_.
  void edited(uint64_t page, const std::string& file);
  void editFiles(uint64_t page, const PageRequest& request);  // seeds, paint, undo, redo, fieldElement
  // A design element's edit written into the grammar (view_field_edit.h), kept for undo
  // (view_field_history.h). Under mutex_.
  bool editFieldElement(uint64_t page, const PageFieldElement& edit, std::string& reason);
  void send(uint64_t page, Page& state, const std::shared_ptr<const Derived>& d);  // under mutex_
  void sendPieces(uint64_t page, Page& state, const Derived& d);                    // under mutex_
  void pick(uint64_t page, uint32_t instance);  // {"type":"pick","instance":N}: who placed it
  void reject(uint64_t page, const std::string& reason);
  void resend(uint64_t page);    // {"type":"resend"}: the last model again, every piece
  void askField(uint64_t page);  // {"type":"field"}: the overlay now and after each recompile
  // The overlay to the pages owed it, computed once per compile (worker).
  void sendFields(bool recompiled);
  std::string infoJson(const std::map<std::string, std::string>& attrs, uint64_t seed, const ViewSeeds& seeds) const;
  // The grammar, its folder and assets/, and the data files it names (grammarDataFiles).
  std::map<std::string, std::filesystem::file_time_type> watchedFiles(const std::vector<std::string>& data) const;

  ViewOptions options_;
  ViewServer& server_;
  std::unique_ptr<CompiledFile> compiled_;  // the last grammar that compiled (worker only)
  std::unique_ptr<backend::native::CodeLoader> loader_;  // its JIT code (worker only)
  std::string compileError_;  // the file's diagnostics while it does not compile (worker only)
  // The surface of the last derivation, kept for the next with the same values and seed
  // (a seed or paint edit); any other starts afresh (worker only).
  std::unique_ptr<backend::SurfaceReuse> surfaceReuse_;
  // Meshes with their frames and factorisations, kept across recompiles (#49): a field
  // edit redesigns the field on them (surface_geometry.h). The last compile's surface for
  // the page, taken again while the geometry stays (worker thread only).
  backend::SurfaceGeometryCache surfaceGeometries_;
  ViewSurface viewSurface_;
  std::pair<std::map<std::string, std::string>, uint64_t> surfaceReuseKey_;
  ViewPieces lastPieces_;  // the last derivation's pieces with surfaceReuse_'s values (worker only)
  std::vector<std::string> paintedFiles_;  // texture files painted since the last derivation (under mutex_)
  std::string field_;  // the field overlay's message for compiled_; empty: not computed (worker only)
  // --steps: the steps derived for these values, seed and step, kept until the grammar or
  // a file it reads changes (stepsEpoch_) or they hold kMaxStepCacheBytes (worker only).
  static constexpr size_t kMaxStepCacheBytes = size_t(256) << 20;
  std::map<std::tuple<uint64_t, std::map<std::string, std::string>, int32_t>, std::shared_ptr<Derived>> stepCache_;
  size_t stepCacheBytes_ = 0;
  uint64_t stepCacheEpoch_ = 0;

  std::mutex mutex_;  // guards what follows
  std::condition_variable wake_;
  bool recompile_ = true, stopping_ = false;
  std::map<std::string, std::string> startAttrs_;  // --set: where a new page starts
  uint64_t startSeed_ = 1;
  int32_t startStep_ = -1;  // --step: where a new page starts
  uint64_t stepsEpoch_ = 0;  // counts the edits that change what a derivation reads
  std::map<uint64_t, Page> pages_;
  bool compiledOnce_ = false;
  ir::Module attrShape_;  // the compiled grammar's attributes, to check pages' values
  std::map<std::string, std::filesystem::file_time_type> seen_;
  std::vector<std::string> dataFiles_;  // the files the last compiled grammar names
  ViewSeeds seeds_;                      // the seed file's, as the page last set them
  ViewPaint paint_;                      // the textures the page paints
  std::shared_ptr<const std::pair<std::string, std::string>> surface_;  // the last compile's
  std::string fieldName_;        // the field the last overlay showed ("": none yet)
  FieldEditBounds fieldBounds_;  // its surface's box, for element edits
  ViewFieldHistory fieldHistory_;  // the element edits' undo and redo

  std::thread worker_;
};

}  // namespace fgsg::cli
