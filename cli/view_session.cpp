#include "cli/view_session.h"

#include "backend/derive_messages.h"
#include "backend/interp/eval.h"
#include "backend/native/code_loader.h"
#include "cli/compile_file.h"
#include "cli/derive_stats.h"
#include "cli/grammar_files.h"
#include "cli/options.h"
#include "cli/view_field.h"
#include "cli/view_message.h"
#include "cli/view_scene.h"
#include "cli/view_surface.h"
#include "runtime/assemble.h"
#include "runtime/io/atomic_file.h"
#include "runtime/io/stale_temps.h"
#include "runtime/io/write_instances.h"

#include <Eigen/Dense>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

namespace fgsg::cli {

namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace {

Json attrDefault(const ir::Module& m, const ir::Attr& a) {
  switch (a.type) {
    case ir::Type::Num: return a.value.num;
    case ir::Type::Bool: return a.value.num != 0;
    case ir::Type::Str: return m.strings.at(static_cast<size_t>(a.value.num));
    case ir::Type::Vec3: {  // as --set writes it: x,y,z
      std::ostringstream text;
      text << a.value.vec[0] << "," << a.value.vec[1] << "," << a.value.vec[2];
      return text.str();
    }
  }
  return nullptr;
}

const char* attrType(ir::Type t) {
  switch (t) {
    case ir::Type::Num: return "number";
    case ir::Type::Bool: return "boolean";
    case ir::Type::Str: return "string";
    case ir::Type::Vec3: return "vector";
  }
  return "?";
}

std::string errorJson(const std::string& diagnostics) {
  return Json{{"type", "error"}, {"diagnostics", diagnostics}}.dump();
}

}  // namespace

ViewSession::ViewSession(ViewOptions options, ViewServer& server)
    : options_(std::move(options)), server_(server) {
  startSeed_ = options_.derive.seed;
  for (const auto& [name, value] : options_.derive.attrOverrides) startAttrs_[name] = value;
  options_.derive.attrOverrides.clear();
  startStep_ = options_.derive.parallelStep;  // --step: each page's own from here
  options_.derive.parallelStep = -1;
  std::string error;
  if (!readSeedFile(options_.seedFile, seeds_, error)) std::cerr << "fgsg view: " << error << "\n";
  seen_ = watchedFiles({});
  worker_ = std::thread([this] { work(); });
}

ViewSession::~ViewSession() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  worker_.join();
  loader_.reset();  // waits for its background compile
}

void ViewSession::pageOpened(uint64_t page) {
  std::lock_guard<std::mutex> lock(mutex_);
  Page& p = pages_[page];
  p.attrs = startAttrs_;
  p.seed = startSeed_;
  p.step = startStep_;
  p.pending = true;
  wake_.notify_all();
}

void ViewSession::pageClosed(uint64_t page) {
  std::lock_guard<std::mutex> lock(mutex_);
  pages_.erase(page);
}

void ViewSession::reject(uint64_t page, const std::string& reason) {
  server_.sendText(page, Json{{"type", "rejected"}, {"reason", reason}}.dump());
}

void ViewSession::message(uint64_t page, const std::string& text) {
  PageRequest request;
  std::string reason;
  if (!parsePageRequest(text, request, reason)) return reject(page, reason);
  if (request.kind == PageRequest::Kind::Pick) return pick(page, request.instance);
  if (request.kind == PageRequest::Kind::Field) return askField(page);
  if (request.kind == PageRequest::Kind::Resend) return resend(page);
  if (request.kind != PageRequest::Kind::Set) return editFiles(page, request);
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = pages_.find(page);
  if (it == pages_.end()) return;
  // Every value is checked before any is taken: a bad one changes nothing.
  if (!request.attrs.empty() && !compiledOnce_)
    return reject(page, "the grammar has not compiled yet: no attributes to set");
  for (const auto& [name, value] : request.attrs) {
    const std::string problem = backend::attributeOverrideProblem(attrShape_, name, value);
    if (!problem.empty()) return reject(page, problem);
  }
  Page& p = it->second;
  const std::map<std::string, std::string> attrs =
      request.hasAttrs ? std::map<std::string, std::string>(request.attrs.begin(), request.attrs.end()) : p.attrs;
  if (request.hasStep) {
    const std::string problem = stepProblem(request.step, attrs);
    if (!problem.empty()) return reject(page, problem);
  }
  // The page sends every value its user has set; the others take the starting values.
  p.attrs = attrs;
  if (request.hasSeed) p.seed = request.seed;
  if (request.hasStep) p.step = static_cast<int32_t>(request.step);
  p.pending = true;
  wake_.notify_all();
}

std::string ViewSession::stepProblem(uint32_t step, const std::map<std::string, std::string>& attrs) const {
  const std::string what = "set: step " + std::to_string(step);
  if (!options_.steps) return what + ": fgsg view was started without --steps";
  if (!compiledOnce_) return what + ": the grammar has not compiled yet";
  std::vector<std::pair<std::string, std::string>> values;  // those the grammar has, as derive() takes them
  for (const auto& [name, value] : attrs)
    if (attrShape_.findAttr(name) >= 0) values.emplace_back(name, value);
  int length = -1;
  try {
    length = backend::parallelDerivationLength(attrShape_, values);
  } catch (const backend::DeriveError& e) {
    return what + ": " + e.message;
  } catch (const std::exception& e) {
    return what + ": " + e.what();
  }
  if (length < 0) return what + ": " + options_.file + " is no L-system (derive parallel N;): its derivation has no steps";
  if (step > static_cast<uint32_t>(length))
    return what + " is past the derivation's length " + std::to_string(length) + " (steps 0 to " +
           std::to_string(length) + ")";
  return "";
}

// The last model sent to the page again, every piece of it (a piece it could not read
// leaves it showing other pieces than the server believes). Nothing is derived.
void ViewSession::resend(uint64_t page) {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = pages_.find(page);
  if (it == pages_.end()) return;
  Page& state = it->second;
  state.pieces.clear();
  if (state.model) send(page, state, state.model);
}

void ViewSession::askField(uint64_t page) {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = pages_.find(page);
  if (it == pages_.end()) return;
  it->second.fieldAsked = it->second.fieldDue = true;
  wake_.notify_all();
}

void ViewSession::sendFields(bool recompiled) {
  if (recompiled) field_.clear();  // computed again when next asked for
  std::vector<uint64_t> due;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (auto& [id, p] : pages_) {
      if (recompiled && p.fieldAsked) p.fieldDue = true;  // the grammar changed: its field again
      if (p.fieldDue) due.push_back(id), p.fieldDue = false;
    }
  }
  if (due.empty()) return;
  std::string name;
  FieldEditBounds bounds;
  const bool fresh = field_.empty();
  if (fresh) {
    if (!compiled_) {
      field_ = Json{{"type", "field"}, {"error", "the grammar has not compiled"}}.dump();
    } else {
      // The surface and fields the last derivation built, when it derived what the overlay
      // shows (the grammar's own values and the start seed): not built a second time.
      std::shared_ptr<const backend::SurfaceWorld> world;
      if (surfaceReuse_ && surfaceReuseKey_.first.empty() && surfaceReuseKey_.second == options_.derive.seed) {
        std::lock_guard<std::mutex> lock(surfaceReuse_->mutex);
        world = surfaceReuse_->world;
      }
      try {
        field_ = fieldOverlayJson(compiled_->module, options_.derive, grammarDataDirs(options_.file), &name, &bounds,
                                  &world, &surfaceGeometries_);
      } catch (const std::exception& e) {  // out of memory ...
        field_ = Json{{"type", "field"}, {"error", e.what()}}.dump();
      }
      // Built here (the overlay went first): the derivation with the same values and seed
      // takes it rather than designing the fields again.
      if (world && !surfaceReuse_) {
        surfaceReuse_ = std::make_unique<backend::SurfaceReuse>();
        surfaceReuse_->geometries = &surfaceGeometries_;
        surfaceReuse_->world = std::move(world);
        surfaceReuseKey_ = {{}, options_.derive.seed};
      }
    }
  }
  std::lock_guard<std::mutex> lock(mutex_);
  if (fresh) fieldName_ = name, fieldBounds_ = bounds;  // what element edits refer to
  for (uint64_t page : due)
    if (pages_.count(page)) server_.sendText(page, field_);
  if (!compiled_) field_.clear();  // asked again once it compiles
}

void ViewSession::editFiles(uint64_t page, const PageRequest& request) {
  std::lock_guard<std::mutex> lock(mutex_);
  std::string file, reason;
  bool done = false;
  switch (request.kind) {
    case PageRequest::Kind::Seeds: {
      ViewSeeds seeds;
      for (const PageSeed& p : request.seeds) {
        rt::DeriveOptions::Seed s;
        std::copy(p.point, p.point + 3, s.point);
        std::copy(p.direction, p.direction + 3, s.direction);
        s.hasDirection = p.hasDirection;
        seeds.push_back(s);
      }
      done = writeSeedFile(options_.seedFile, seeds, fs::path(options_.file).filename().string(), reason);
      if (done) seeds_ = std::move(seeds), file = options_.seedFile;
      break;
    }
    case PageRequest::Kind::Paint: done = paint_.paint(request.paint, file, reason); break;
    case PageRequest::Kind::Undo:
    case PageRequest::Kind::Redo: {
      const bool undo = request.kind == PageRequest::Kind::Undo;
      if (request.history == PageRequest::History::Paint) {
        done = undo ? paint_.undo(file, reason) : paint_.redo(file, reason);
        break;
      }
      done = undo ? fieldHistory_.undo(options_.file, reason) : fieldHistory_.redo(options_.file, reason);
      file = fs::absolute(options_.file).string();
      break;
    }
    case PageRequest::Kind::FieldElement:
      done = editFieldElement(page, request.element, reason);
      file = fs::absolute(options_.file).string();
      break;
    default: break;
  }
  if (!done) return reject(page, reason);
  const bool undoRedo = request.kind == PageRequest::Kind::Undo || request.kind == PageRequest::Kind::Redo;
  if (request.kind == PageRequest::Kind::Paint || (undoRedo && request.history == PageRequest::History::Paint))
    paintedFiles_.push_back(file);  // pieces embedding its image hold the old texels
  edited(page, file);
  if (request.kind == PageRequest::Kind::FieldElement || request.history == PageRequest::History::Field)
    recompile_ = true;  // the grammar itself changed
}

bool ViewSession::editFieldElement(uint64_t page, const PageFieldElement& edit, std::string& reason) {
  if (fieldName_.empty()) {
    reason = "fieldElement: no field overlay shown yet (ask for it: {\"type\":\"field\"})";
    return false;
  }
  std::string text;
  if (!readGrammarToEdit(options_.file, "fieldElement", text, reason)) return false;
  std::string error, rewritten;
  if (!editFieldDesignText(options_.file, text, fieldName_, edit, fieldBounds_, rewritten, reason)) {
    reason = "fieldElement: " + reason;
    return false;
  }
  if (!rt::io::writeFileAtomically(options_.file, rewritten, error)) {
    reason = "fieldElement: " + error;
    return false;
  }
  fieldHistory_.record(text, rewritten, page, edit.drag);
  return true;
}

void ViewSession::edited(uint64_t page, const std::string& file) {
  // Written here: the watcher has no reason to compile again. Its names for the file may
  // be spelt otherwise (relative data folders): each that is the same file is updated.
  std::error_code ec;
  const auto now = watchedFiles(dataFiles_);
  for (auto it = seen_.begin(); it != seen_.end();)
    it = it->first == file && !now.count(file) ? seen_.erase(it) : std::next(it);  // a seed file removed
  for (const auto& [name, time] : now)
    if (name == file || fs::equivalent(name, file, ec)) seen_[name] = time;
  for (auto& [id, p] : pages_) p.pending = true;
  ++stepsEpoch_;  // the steps derived before read the file as it was
  server_.sendText(page, Json{{"type", "written"}, {"file", fs::path(file).filename().string()}}.dump());
  wake_.notify_all();
}

std::map<std::string, fs::file_time_type> ViewSession::watchedFiles(const std::vector<std::string>& data) const {
  std::map<std::string, fs::file_time_type> out;
  std::error_code ec;
  for (const std::string& f : data) out[f] = fs::last_write_time(f, ec);
  const fs::path grammar = fs::absolute(options_.file, ec);
  out[grammar.string()] = fs::last_write_time(grammar, ec);
  if (fs::exists(options_.seedFile, ec)) out[options_.seedFile] = fs::last_write_time(options_.seedFile, ec);
  for (const fs::path& dir : {grammar.parent_path(), grammar.parent_path() / "assets"}) {
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
      // An output being written (`fgsg run -o` in this folder: its temporary, then the
      // rename) is one change when it lands, not one per temporary.
      if (it->is_regular_file(ec) && !rt::io::isOutputTemporary(it->path().filename().string()))
        out[it->path().string()] = fs::last_write_time(it->path(), ec);
  }
  return out;
}

void ViewSession::checkFiles() {
  std::vector<std::string> data;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    data = dataFiles_;
  }
  auto now = watchedFiles(data);
  std::lock_guard<std::mutex> lock(mutex_);
  if (now == seen_) return;
  // Read again under the lock: a file the page's edit wrote after the read above (and
  // recorded in seen_ by edited()) is no outside change; taking it for one recompiled and
  // cleared the paint's undo history.
  now = watchedFiles(dataFiles_);
  if (now == seen_) return;
  // The seed file edited outside the page: its seeds from now on (a bad one: the last).
  const auto seedFile = [&](const auto& files) {
    const auto it = files.find(options_.seedFile);
    return it == files.end() ? std::optional<fs::file_time_type>() : it->second;
  };
  if (seedFile(now) != seedFile(seen_)) {
    std::string error;
    ViewSeeds seeds;
    if (readSeedFile(options_.seedFile, seeds, error)) seeds_ = std::move(seeds);
    else std::cerr << "fgsg view: " << error << " (the last seeds kept)\n";
  }
  seen_ = std::move(now);
  recompile_ = true;
  ++stepsEpoch_;
  for (auto& [id, p] : pages_) p.pending = true;  // each page again, with its own values
  wake_.notify_all();
}

void ViewSession::work() {
  for (;;) {
    bool recompile = false, recompiled = false, fieldShown = false;
    struct Group {
      std::map<std::string, std::string> attrs;
      uint64_t seed;
      int32_t step;
      std::vector<uint64_t> pages;
    };
    ViewSeeds seeds;
    uint64_t epoch = 0;
    // By seed, values and step.
    std::map<std::tuple<uint64_t, std::map<std::string, std::string>, int32_t>, Group> groups;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      auto anyPending = [this] {
        for (const auto& [id, p] : pages_)
          if (p.pending || p.fieldDue) return true;
        return false;
      };
      wake_.wait(lock, [&] { return stopping_ || anyPending(); });
      if (stopping_) return;
      recompile = recompile_;
      recompile_ = false;
      seeds = seeds_;
      epoch = stepsEpoch_;
      for (auto& [id, p] : pages_) {
        if (!p.pending) continue;
        p.pending = false;
        Group& g = groups[{p.seed, p.attrs, p.step}];
        g.attrs = p.attrs;
        g.seed = p.seed;
        g.step = p.step;
        g.pages.push_back(id);
      }
      if (groups.empty()) recompile_ = recompile;  // woken for a field overlay only: the next derivation compiles
      for (const auto& [id, p] : pages_) fieldShown = fieldShown || p.fieldAsked;
    }
    if (!groups.empty() && (recompile || epoch != stepCacheEpoch_)) {  // the steps kept are of another grammar
      stepCache_.clear();
      stepCacheBytes_ = 0;
      stepCacheEpoch_ = epoch;
    }
    // A grammar edit while a page shows the field (a design element dragged, #49): the
    // overlay first — compiled, the field designed, traced and sent — then the model,
    // derived on the surface and fields the overlay built, so the page's new streamlines
    // do not wait for the derivation.
    const bool overlayFirst = recompile && !groups.empty() && fieldShown;
    if (overlayFirst) {
      compile();
      surfaceReuse_.reset();  // a new grammar: its surface and fields afresh (sendFields)
      recompile = false;
      sendFields(true);
    }
    for (auto& [key, g] : groups) {
      const std::string progress = Json{{"type", "progress"}, {"state", "deriving"}}.dump();
      for (uint64_t page : g.pages) server_.sendText(page, progress);
      std::shared_ptr<Derived> d;
      try {
        d = derive(recompile, g.attrs, g.seed, seeds, g.step);
      } catch (const std::exception& e) {  // the JIT's plugin missing, out of memory ...
        d = std::make_shared<Derived>();
        d->error = options_.file + ": " + e.what();
      }
      if (recompile) recompiled = true;
      recompile = false;
      std::lock_guard<std::mutex> lock(mutex_);
      for (uint64_t page : g.pages) {
        const auto it = pages_.find(page);
        // A page that changed its values meanwhile is pending again: it gets that result.
        if (it != pages_.end() && !it->second.pending) send(page, it->second, d);
      }
    }
    sendFields(recompiled);  // the pages that asked meanwhile
  }
}

void ViewSession::send(uint64_t page, Page& state, const std::shared_ptr<const Derived>& d) {
  if (!d->info.empty() && d->info != state.infoSent) server_.sendText(page, state.infoSent = d->info);
  if (d->surface && d->surface.get() != state.surfaceSent) {
    state.surfaceSent = d->surface.get();
    server_.sendText(page, d->surface->first);
    server_.sendBinary(page, d->surface->second);
  }
  if (d->modelJson.empty()) return server_.sendText(page, errorJson(d->error));
  state.model = d;
  if (!d->pieces.pieces.empty()) return sendPieces(page, state, *d);
  state.pieces.clear();
  server_.sendText(page, d->modelJson);
  for (const std::string& p : d->parts) server_.sendBinary(page, p);
}

// Only the pieces the page does not show already (a seed dragged: that seed's).
void ViewSession::sendPieces(uint64_t page, Page& state, const Derived& d) {
  const std::vector<std::shared_ptr<const ViewPiece>>& pieces = d.pieces.pieces;
  Json header = Json::parse(d.modelJson);
  Json sent = Json::array();
  std::vector<size_t> due;
  for (size_t k = 0; k < pieces.size(); ++k) {
    if (k < state.pieces.size() && state.pieces[k] == pieces[k]) continue;
    Json placing = Json::array();
    for (const auto& [node, count] : pieces[k]->placing) placing.push_back({node, count});
    sent.push_back({{"piece", k}, {"placing", placing}, {"bytes", pieces[k]->glb.size()}});
    due.push_back(k);
  }
  header["sent"] = sent;
  state.pieces = pieces;
  server_.sendText(page, header.dump());
  for (size_t k : due) {
    server_.sendBinary(page, pieces[k]->glb);
    const std::vector<uint32_t>& ids = pieces[k]->ids;
    server_.sendBinary(page, std::string(reinterpret_cast<const char*>(ids.data()), ids.size() * sizeof(uint32_t)));
  }
}

std::string ViewSession::infoJson(const std::map<std::string, std::string>& attrs, uint64_t seed,
                                  const ViewSeeds& seeds) const {
  Json list = Json::array();
  for (const ir::Attr& a : compiled_->module.attrs) {
    if (a.name.rfind("lot:", 0) == 0) continue;  // Lot.* queries, set by --lots only
    Json entry{{"name", a.name}, {"type", attrType(a.type)}, {"default", attrDefault(compiled_->module, a)}};
    auto it = attrs.find(a.name);
    entry["value"] = it != attrs.end() ? Json(it->second) : entry["default"];
    // A .cga attr's @Range, @Enum ...: {"Range": [["min", "0"], ["max", "10"]], ...}.
    if (!a.annotations.empty()) {
      Json notes = Json::object();
      for (const ir::AttrAnnotation& n : a.annotations) {
        Json args = Json::array();
        for (const auto& [key, value] : n.args) args.push_back(Json::array({key, value}));
        notes[n.name] = args;
      }
      entry["annotations"] = notes;
    }
    list.push_back(entry);
  }
  Json seedList = Json::array();
  for (const auto& s : seeds) {
    Json one = {s.point[0], s.point[1], s.point[2]};
    if (s.hasDirection) one.insert(one.end(), {s.direction[0], s.direction[1], s.direction[2]});
    seedList.push_back(one);
  }
  return Json{{"type", "info"}, {"file", options_.file}, {"attrs", list}, {"seed", seed}, {"seeds", seedList},
              {"seedFile", fs::path(options_.seedFile).filename().string()}}
      .dump();
}

void ViewSession::prepareSurface(const std::vector<std::string>& dataDirs) {
  ViewSurface surface;
  std::string error;
  rt::DeriveOptions options = options_.derive;
  options.assetDirs = dataDirs;
  // A surface that cannot be built fails the derivation too, which says why.
  // The same mesh as the last compile's: its surface as it was (not laid out, encoded nor
  // sent to the pages again).
  const bool built =
      buildViewSurface(compiled_->module, options, dataDirs, surface, error, &surfaceGeometries_, &viewSurface_);
  viewSurface_ = built ? surface : ViewSurface{};
  Json textures = Json::array();
  std::lock_guard<std::mutex> lock(mutex_);
  paint_.reset(compiled_->module, options_.file, dataDirs, built ? surface.marching : nullptr);
  for (const ViewPaint::Texture& t : paint_.textures())
    textures.push_back({{"name", t.name}, {"width", t.width}, {"height", t.height}, {"why", t.why},
                        {"file", fs::path(t.file).filename().string()}});
  if (!built || surface.glb.empty()) {
    surface_.reset();
    return;
  }
  std::string header = Json{{"type", "surface"}, {"triangles", surface.triangles}, {"textures", textures}}.dump();
  if (surface_ && surface_->first == header && surface_->second == surface.glb) return;  // the pages have it
  surface_ = std::make_shared<std::pair<std::string, std::string>>(std::move(header), std::move(surface.glb));
}

void ViewSession::compile() {
  std::ostringstream diagnostics;
  auto fresh = compileFile(options_.file, diagnostics, false, options_.startRule);
  if (!fresh) {
    compileError_ = diagnostics.str();
    return;
  }
  compileError_.clear();
  compiled_ = std::move(fresh);
  lastPieces_ = ViewPieces{};  // pieces of another grammar (or of files it read as they were)
  loader_.reset();  // a new grammar: its own code
  // Watch what this version reads too (its modules, a mesh, a texture, a field file beyond
  // the folder).
  std::vector<std::string> extra;
  if (!options_.derive.surfaceOverride.empty()) extra.push_back(options_.derive.surfaceOverride);
  for (const auto& m : compiled_->source.modules) extra.push_back(m.key);  // its imported modules
  std::vector<std::string> data = grammarDataFiles(compiled_->module, options_.file, extra);
  prepareSurface(grammarDataDirs(options_.file));
  std::lock_guard<std::mutex> lock(mutex_);
  // What the pages' values are checked against (message()).
  attrShape_ = ir::Module{};
  attrShape_.attrs = compiled_->module.attrs;
  attrShape_.countAttr = compiled_->module.countAttr;
  attrShape_.mode = compiled_->module.mode;
  attrShape_.steps = compiled_->module.steps;      // and the derivation's length (stepProblem)
  attrShape_.strings = compiled_->module.strings;  // an import's attrs may read them
  compiledOnce_ = true;
  if (data != dataFiles_) {
    std::error_code ec;
    for (const std::string& f : data) seen_.emplace(f, fs::last_write_time(f, ec));
    dataFiles_ = std::move(data);
  }
}

std::shared_ptr<ViewSession::Derived> ViewSession::derive(bool recompile, const std::map<std::string, std::string>& attrs,
                                                          uint64_t seed, const ViewSeeds& seeds, int32_t step) {
  std::unique_ptr<backend::native::CodeLoader>& loader = loader_;
  const auto start = std::chrono::steady_clock::now();
  auto d = std::make_shared<Derived>();
  auto fail = [&](const std::string& diagnostics) {
    d->error = diagnostics;
    return d;
  };
  if (recompile || !compiled_) compile();
  // The file as it is now does not compile: not the last version that did.
  if (!compileError_.empty()) return fail(compileError_);
  // The page's values for attributes this grammar has; a value that does not fit its
  // attribute is an error in the page, not a crash.
  d->info = infoJson(attrs, seed, seeds);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    d->surface = surface_;
  }
  rt::DeriveOptions derive = options_.derive;
  derive.seed = seed;
  derive.seeds = seeds;
  derive.recordOrigins = true;  // picking shows each instance's rule and depth
  for (const auto& [name, value] : attrs) {
    if (compiled_->module.findAttr(name) < 0) continue;
    const std::string problem = backend::attributeOverrideProblem(compiled_->module, name, value);
    if (!problem.empty()) return fail(options_.file + ": " + name + " = " + value + ": " + problem);
    derive.attrOverrides.push_back({name, value});
  }
  // An L-system's step (--step, the page's slider): the derivation up to it, kept with
  // --steps for when the slider comes back to it.
  int length = -1;
  if (step >= 0 || options_.steps) {
    try {
      length = backend::parallelDerivationLength(compiled_->module, derive.attrOverrides);
    } catch (const backend::DeriveError& e) {
      return fail(options_.file + ": " + e.message);
    }
  }
  if (step >= 0 && length < 0)
    return fail(options_.file + ": --step " + std::to_string(step) +
                ": the grammar is no L-system (derive parallel N;): its derivation has no steps");
  const int32_t shownStep = length < 0 ? -1 : step < 0 ? length : std::min(step, int32_t(length));
  derive.parallelStep = shownStep;
  const auto cacheKey = std::make_tuple(seed, attrs, shownStep);
  const bool cached = options_.steps && length >= 0;
  if (cached)
    if (const auto it = stepCache_.find(cacheKey); it != stepCache_.end()) return it->second;
  rt::AssetLibrary assets;
  for (const std::string& dir : grammarDataDirs(options_.file)) {
    assets.addSearchDir(dir);
    derive.assetDirs.push_back(dir);
  }
  if (!loader) loader = std::make_unique<backend::native::CodeLoader>();
  if (recompile || !surfaceReuse_ || surfaceReuseKey_ != std::make_pair(attrs, seed)) {
    surfaceReuse_ = std::make_unique<backend::SurfaceReuse>();
    surfaceReuse_->geometries = &surfaceGeometries_;
    surfaceReuseKey_ = {attrs, seed};
    lastPieces_ = ViewPieces{};  // of other values (a recompile: see compile())
  }
  std::vector<std::string> painted;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    painted.swap(paintedFiles_);
  }
  // A painted texture a piece embeds (a finish's image): its .glb is stale though its
  // instances are the same.
  if (viewPiecesEmbedAny(lastPieces_, painted)) lastPieces_ = ViewPieces{};
  const backend::SurfaceReuseScope reuseSurface(*surfaceReuse_);
  rt::DeriveResult result =
      backend::derive(options_.engine, compiled_->module, compiled_->source.text, derive, assets, nullptr, loader.get());
  frontend::Diagnostics diags(&compiled_->source);
  backend::addDeriveMessages(result, diags);
  if (diags.hasErrors()) {
    std::ostringstream text;
    diags.print(text);
    return fail(text.str());
  }
  std::vector<int> meshOf;
  std::string error;
  if (!rt::resolveAssets(result.instances, assets, meshOf, error)) return fail(options_.file + ": " + error);
  const auto derived = std::chrono::steady_clock::now();
  const auto since = [](std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
  };
  const auto rules = [&] {
    for (const ir::Rule& r : compiled_->module.rules) {  // "Tree#2 (line 9)", "15: flatbrick (line 68)"
      const std::string& symbol = compiled_->module.symbols[r.symbol].name;
      const bool own = r.label.rfind(symbol + "#", 0) == 0;
      d->rules.push_back((own ? r.label : r.label + ": " + symbol) + " (line " + std::to_string(r.loc.line) + ")");
    }
  };
  if (viewByPieces(derive, result)) {  // seeds derived apart: only the changed ones go out
    ViewPieces pieces;
    if (!buildViewPieces(compiled_->module, derive, result, assets, meshOf, lastPieces_, pieces, error))
      return fail(options_.file + ": " + error);
    lastPieces_ = pieces;
    Json figures = Json::object();
    for (const auto& [name, value] : deriveStatFigures(result.stats, pieces.triangles)) figures[name] = value;
    Json header{{"type", "pieces"},
                {"figures", figures},
                {"milliseconds", since(start)},
                {"server", {{"derive", std::chrono::duration<double, std::milli>(derived - start).count()},
                            {"pieces", since(derived)},
                            {"built", pieces.built}}},
                {"seed", seed},
                {"bases", pieces.bases}};
    d->modelJson = header.dump();
    d->pieces = std::move(pieces);
    d->instances = std::move(result.instances);
    rules();
    return d;
  }
  ViewScene scene;
  if (!buildViewScene(compiled_->module, derive, result, assets, meshOf, scene, error))
    return fail(options_.file + ": " + error);

  // The header says what the binary messages that follow hold: the scene as .glb, then
  // the instance numbers of its placing nodes, "placing" giving each node and its count.
  Json figures = Json::object();
  for (const auto& [name, value] : deriveStatFigures(result.stats, scene.triangles)) figures[name] = value;
  Json placing = Json::array();
  for (const auto& [node, count] : scene.placing) placing.push_back({node, count});
  std::vector<std::string> parts;  // (an initializer list would copy the .glb)
  parts.push_back(std::move(scene.glb));
  parts.emplace_back(reinterpret_cast<const char*>(scene.ids.data()), scene.ids.size() * sizeof(uint32_t));
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  Json header{{"type", "model"}, {"figures", figures}, {"milliseconds", ms}, {"seed", seed}, {"placing", placing},
              {"server", {{"derive", std::chrono::duration<double, std::milli>(derived - start).count()},
                          {"scene", ms - std::chrono::duration<double, std::milli>(derived - start).count()}}}};
  if (options_.steps && length >= 0) header["steps"] = {{"step", shownStep}, {"length", length}};
  d->modelJson = header.dump();
  d->parts = std::move(parts);
  d->instances = std::move(result.instances);
  rules();
  if (cached) {
    size_t bytes = d->modelJson.size();
    for (const std::string& part : d->parts) bytes += part.size();
    if (stepCacheBytes_ + bytes > kMaxStepCacheBytes) stepCache_.clear(), stepCacheBytes_ = 0;  // full: afresh
    stepCache_[cacheKey] = d;
    stepCacheBytes_ += bytes;
  }
  return d;
}

void ViewSession::pick(uint64_t page, uint32_t instance) {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = pages_.find(page);
  if (it == pages_.end() || !it->second.model) return reject(page, "pick: no model shown yet");
  const rt::InstanceList& shown = it->second.model->instances;
  const std::vector<std::string>& rules = it->second.model->rules;
  if (instance >= shown.instances.size()) return reject(page, "pick: no instance " + std::to_string(instance));
  const rt::Instance& inst = shown.instances[instance];
  const Json params = Json::parse(rt::io::instanceParamsJson(shown, inst), nullptr, false);
  const Eigen::Map<const Eigen::Matrix4d> t(inst.transform.data());
  const Eigen::Vector4d centre = t * Eigen::Vector4d(0.5, 0.5, 0.5, 1);
  // Lines and the surface are placed by no rule; the axiom's own I() by the axiom.
  const rt::InstanceOrigin origin =
      instance < shown.origins.size() ? shown.origins[instance] : rt::InstanceOrigin{};
  const Json rule = origin.rule < rules.size() ? Json(rules[origin.rule])
                    : origin.depth != UINT32_MAX    ? Json("the axiom")
                                                    : Json(nullptr);
  const Json depth = origin.depth == UINT32_MAX ? Json(nullptr) : Json(origin.depth);
  server_.sendText(page, Json{{"type", "picked"},
                             {"instance", instance},
                             {"rule", rule},
                             {"depth", depth},
                             {"symbol", inst.symbol < shown.symbols.size() ? shown.symbols[inst.symbol] : ""},
                             {"asset", inst.asset < shown.assets.size() ? shown.assets[inst.asset] : ""},
                             {"params", params.is_discarded() ? Json::array() : params},
                             {"colour", inst.color},
                             {"centre", {centre.x(), centre.y(), centre.z()}}}
                            .dump());
}

}  // namespace fgsg::cli
