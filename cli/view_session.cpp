#include "cli/view_session.h"

#include "backend/derive_messages.h"
#include "backend/interp/eval.h"
#include "backend/native/code_loader.h"
#include "cli/compile_file.h"
#include "cli/derive_stats.h"
#include "cli/grammar_files.h"
#include "cli/options.h"
#include "cli/view_message.h"
#include "cli/view_scene.h"
#include "runtime/assemble.h"
#include "runtime/io/write_instances.h"

#include <Eigen/Dense>

#include <nlohmann/json.hpp>

#include <chrono>
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
  // The page sends every value its user has set; the others take the starting values.
  if (request.hasAttrs) p.attrs = std::map<std::string, std::string>(request.attrs.begin(), request.attrs.end());
  if (request.hasSeed) p.seed = request.seed;
  p.pending = true;
  wake_.notify_all();
}

std::map<std::string, fs::file_time_type> ViewSession::watchedFiles(const std::vector<std::string>& data) const {
  std::map<std::string, fs::file_time_type> out;
  std::error_code ec;
  for (const std::string& f : data) out[f] = fs::last_write_time(f, ec);
  const fs::path grammar = fs::absolute(options_.file, ec);
  out[grammar.string()] = fs::last_write_time(grammar, ec);
  for (const fs::path& dir : {grammar.parent_path(), grammar.parent_path() / "assets"}) {
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
      if (it->is_regular_file(ec)) out[it->path().string()] = fs::last_write_time(it->path(), ec);
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
  seen_ = std::move(now);
  recompile_ = true;
  for (auto& [id, p] : pages_) p.pending = true;  // each page again, with its own values
  wake_.notify_all();
}

void ViewSession::work() {
  for (;;) {
    bool recompile = false;
    struct Group {
      std::map<std::string, std::string> attrs;
      uint64_t seed;
      std::vector<uint64_t> pages;
    };
    std::map<std::pair<uint64_t, std::map<std::string, std::string>>, Group> groups;  // by seed and values
    {
      std::unique_lock<std::mutex> lock(mutex_);
      auto anyPending = [this] {
        for (const auto& [id, p] : pages_)
          if (p.pending) return true;
        return false;
      };
      wake_.wait(lock, [&] { return stopping_ || anyPending(); });
      if (stopping_) return;
      recompile = recompile_;
      recompile_ = false;
      for (auto& [id, p] : pages_) {
        if (!p.pending) continue;
        p.pending = false;
        Group& g = groups[{p.seed, p.attrs}];
        g.attrs = p.attrs;
        g.seed = p.seed;
        g.pages.push_back(id);
      }
    }
    for (auto& [key, g] : groups) {
      const std::string progress = Json{{"type", "progress"}, {"state", "deriving"}}.dump();
      for (uint64_t page : g.pages) server_.sendText(page, progress);
      std::shared_ptr<Derived> d;
      try {
        d = derive(recompile, g.attrs, g.seed);
      } catch (const std::exception& e) {  // the JIT's plugin missing, out of memory ...
        d = std::make_shared<Derived>();
        d->error = options_.file + ": " + e.what();
      }
      recompile = false;
      std::lock_guard<std::mutex> lock(mutex_);
      for (uint64_t page : g.pages) {
        const auto it = pages_.find(page);
        // A page that changed its values meanwhile is pending again: it gets that result.
        if (it != pages_.end() && !it->second.pending) send(page, it->second, d);
      }
    }
  }
}

void ViewSession::send(uint64_t page, Page& state, const std::shared_ptr<const Derived>& d) {
  if (!d->info.empty() && d->info != state.infoSent) server_.sendText(page, state.infoSent = d->info);
  if (d->modelJson.empty()) return server_.sendText(page, errorJson(d->error));
  state.model = d;
  server_.sendText(page, d->modelJson);
  for (const std::string& p : d->parts) server_.sendBinary(page, p);
}

std::string ViewSession::infoJson(const std::map<std::string, std::string>& attrs, uint64_t seed) const {
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
  return Json{{"type", "info"}, {"file", options_.file}, {"attrs", list}, {"seed", seed}}.dump();
}

std::shared_ptr<ViewSession::Derived> ViewSession::derive(bool recompile, const std::map<std::string, std::string>& attrs,
                                                          uint64_t seed) {
  std::unique_ptr<backend::native::CodeLoader>& loader = loader_;
  const auto start = std::chrono::steady_clock::now();
  auto d = std::make_shared<Derived>();
  auto fail = [&](const std::string& diagnostics) {
    d->error = diagnostics;
    return d;
  };
  if (recompile || !compiled_) {
    std::ostringstream diagnostics;
    auto fresh = compileFile(options_.file, diagnostics, false, options_.startRule);
    if (!fresh) return fail(compileError_ = diagnostics.str());
    compileError_.clear();
    compiled_ = std::move(fresh);
    loader.reset();  // a new grammar: its own code
    // Watch what this version reads too (its modules, a mesh, a texture, a field file beyond
    // the folder).
    std::vector<std::string> extra;
    if (!options_.derive.surfaceOverride.empty()) extra.push_back(options_.derive.surfaceOverride);
    for (const auto& m : compiled_->source.modules) extra.push_back(m.key);  // its imported modules
    std::vector<std::string> data = grammarDataFiles(compiled_->module, options_.file, extra);
    std::lock_guard<std::mutex> lock(mutex_);
    // What the pages' values are checked against (message()).
    attrShape_ = ir::Module{};
    attrShape_.attrs = compiled_->module.attrs;
    attrShape_.countAttr = compiled_->module.countAttr;
    attrShape_.mode = compiled_->module.mode;
    compiledOnce_ = true;
    if (data != dataFiles_) {
      std::error_code ec;
      for (const std::string& f : data) seen_.emplace(f, fs::last_write_time(f, ec));
      dataFiles_ = std::move(data);
    }
  }
  // The file as it is now does not compile: not the last version that did.
  if (!compileError_.empty()) return fail(compileError_);
  // The page's values for attributes this grammar has; a value that does not fit its
  // attribute is an error in the page, not a crash.
  d->info = infoJson(attrs, seed);
  rt::DeriveOptions derive = options_.derive;
  derive.seed = seed;
  derive.recordOrigins = true;  // picking shows each instance's rule and depth
  for (const auto& [name, value] : attrs) {
    if (compiled_->module.findAttr(name) < 0) continue;
    const std::string problem = backend::attributeOverrideProblem(compiled_->module, name, value);
    if (!problem.empty()) return fail(options_.file + ": " + name + " = " + value + ": " + problem);
    derive.attrOverrides.push_back({name, value});
  }
  rt::AssetLibrary assets;
  for (const std::string& dir : grammarDataDirs(options_.file)) {
    assets.addSearchDir(dir);
    derive.assetDirs.push_back(dir);
  }
  if (!loader) loader = std::make_unique<backend::native::CodeLoader>();
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
  ViewScene scene;
  if (!buildViewScene(result.instances, assets, meshOf, scene, error)) return fail(options_.file + ": " + error);

  // The header lists the binary messages that follow: the assembled rest, then for each
  // group of instances its asset's mesh, their matrices, colours and instance numbers.
  Json figures = Json::object();
  for (const auto& [name, value] : deriveStatFigures(result.stats, scene.triangles)) figures[name] = value;
  Json groups = Json::array();
  std::vector<std::string> parts = {std::move(scene.restGlb)};
  for (InstanceGroup& g : scene.groups) {
    groups.push_back({{"asset", g.asset}, {"count", g.ids.size()}});
    parts.push_back(std::move(g.meshGlb));
    parts.emplace_back(reinterpret_cast<const char*>(g.matrices.data()), g.matrices.size() * sizeof(float));
    parts.emplace_back(reinterpret_cast<const char*>(g.colours.data()), g.colours.size() * sizeof(float));
    parts.emplace_back(reinterpret_cast<const char*>(g.ids.data()), g.ids.size() * sizeof(uint32_t));
  }
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  const std::string header = Json{{"type", "model"}, {"figures", figures}, {"milliseconds", ms},
                                  {"seed", seed}, {"groups", groups}}.dump();
  d->modelJson = header;
  d->parts = std::move(parts);
  d->instances = std::move(result.instances);
  for (const ir::Rule& r : compiled_->module.rules) {  // "Tree#2 (line 9)", "15: flatbrick (line 68)"
    const std::string& symbol = compiled_->module.symbols[r.symbol].name;
    const bool own = r.label.rfind(symbol + "#", 0) == 0;
    d->rules.push_back((own ? r.label : r.label + ": " + symbol) + " (line " + std::to_string(r.loc.line) + ")");
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
