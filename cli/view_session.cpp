#include "cli/view_session.h"

#include "backend/derive_messages.h"
#include "backend/interp/eval.h"
#include "backend/native/code_loader.h"
#include "cli/compile_file.h"
#include "cli/derive_stats.h"
#include "cli/grammar_files.h"
#include "cli/options.h"
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
  seed_ = options_.derive.seed;
  for (const auto& [name, value] : options_.derive.attrOverrides) attrs_[name] = value;
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
  if (!lastInfo_.empty()) server_.sendText(page, lastInfo_);
  if (!lastModelJson_.empty()) {
    server_.sendText(page, lastModelJson_);
    for (const std::string& p : lastParts_) server_.sendBinary(page, p);
  }
  if (!lastError_.empty()) server_.sendText(page, lastError_);
}

void ViewSession::message(uint64_t page, const std::string& text) {
  const Json j = Json::parse(text, nullptr, false);
  if (!j.is_discarded() && j.is_object() && j.value("type", "") == "pick" && j.contains("instance") &&
      j["instance"].is_number_unsigned())
    return pick(page, j["instance"].get<uint32_t>());
  if (j.is_discarded() || !j.is_object() || j.value("type", "") != "set") return;  // not ours
  std::lock_guard<std::mutex> lock(mutex_);
  // The page sends every value its user has set; the others take the grammar's defaults.
  if (j.contains("attrs") && j["attrs"].is_object()) {
    attrs_.clear();
    for (const auto& [name, value] : j["attrs"].items())
      attrs_[name] = value.is_string() ? value.get<std::string>() : value.dump();
  }
  if (j.contains("seed") && j["seed"].is_number_unsigned()) seed_ = j["seed"].get<uint64_t>();
  pending_ = true;
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
  pending_ = recompile_ = true;
  wake_.notify_all();
}

void ViewSession::work() {
  for (;;) {
    bool recompile = false;
    std::map<std::string, std::string> attrs;
    uint64_t seed = 1;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [this] { return pending_ || stopping_; });
      if (stopping_) return;
      recompile = recompile_;
      attrs = attrs_;
      seed = seed_;
      pending_ = recompile_ = false;
    }
    server_.sendTextToAll(Json{{"type", "progress"}, {"state", "deriving"}}.dump());
    try {
      deriveOnce(recompile, attrs, seed);
    } catch (const std::exception& e) {  // the JIT's plugin missing, out of memory ...
      const std::string j = errorJson(options_.file + ": " + e.what());
      std::lock_guard<std::mutex> lock(mutex_);
      lastError_ = j;
      server_.sendTextToAll(j);
    }
  }
}

std::string ViewSession::infoJson(const std::map<std::string, std::string>& attrs, uint64_t seed) const {
  Json list = Json::array();
  for (const ir::Attr& a : compiled_->module.attrs) {
    if (a.name.rfind("lot:", 0) == 0) continue;  // Lot.* queries, set by --lots only
    Json entry{{"name", a.name}, {"type", attrType(a.type)}, {"default", attrDefault(compiled_->module, a)}};
    auto it = attrs.find(a.name);
    entry["value"] = it != attrs.end() ? Json(it->second) : entry["default"];
    list.push_back(entry);
  }
  return Json{{"type", "info"}, {"file", options_.file}, {"attrs", list}, {"seed", seed}}.dump();
}

void ViewSession::deriveOnce(bool recompile, const std::map<std::string, std::string>& attrs, uint64_t seed) {
  std::unique_ptr<backend::native::CodeLoader>& loader = loader_;
  const auto start = std::chrono::steady_clock::now();
  auto fail = [&](const std::string& diagnostics) {
    const std::string j = errorJson(diagnostics);
    std::lock_guard<std::mutex> lock(mutex_);
    lastError_ = j;
    server_.sendTextToAll(j);
  };
  if (recompile || !compiled_) {
    std::ostringstream diagnostics;
    auto fresh = compileFile(options_.file, diagnostics, false);
    if (!fresh) return fail(diagnostics.str());
    compiled_ = std::move(fresh);
    loader.reset();  // a new grammar: its own code
    // Watch what this version reads too (its modules, a mesh, a texture, a field file beyond
    // the folder).
    std::vector<std::string> extra;
    if (!options_.derive.surfaceOverride.empty()) extra.push_back(options_.derive.surfaceOverride);
    for (const auto& m : compiled_->source.modules) extra.push_back(m.key);  // its imported modules
    std::vector<std::string> data = grammarDataFiles(compiled_->module, options_.file, extra);
    std::lock_guard<std::mutex> lock(mutex_);
    if (data != dataFiles_) {
      std::error_code ec;
      for (const std::string& f : data) seen_.emplace(f, fs::last_write_time(f, ec));
      dataFiles_ = std::move(data);
    }
  }
  // The page's values for attributes this grammar has; a value that does not fit its
  // attribute is an error in the page, not a crash.
  rt::DeriveOptions derive = options_.derive;
  derive.seed = seed;
  derive.recordOrigins = true;  // picking shows each instance's rule and depth
  for (const auto& [name, value] : attrs) {
    if (compiled_->module.findAttr(name) < 0) continue;
    const std::string problem = backend::attributeOverrideProblem(compiled_->module, name, value);
    if (!problem.empty()) return fail(options_.file + ": " + name + " = " + value + ": " + problem);
    derive.attrOverrides.push_back({name, value});
  }
  const std::string info = infoJson(attrs, seed);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (info != lastInfo_) server_.sendTextToAll(lastInfo_ = info);
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
  std::lock_guard<std::mutex> lock(mutex_);
  lastError_.clear();
  lastModelJson_ = header;
  lastParts_ = parts;
  lastInstances_ = std::move(result.instances);
  lastRules_.clear();
  for (const ir::Rule& r : compiled_->module.rules) {  // "Tree#2 (line 9)", "15: flatbrick (line 68)"
    const std::string& symbol = compiled_->module.symbols[r.symbol].name;
    const bool own = r.label.rfind(symbol + "#", 0) == 0;
    lastRules_.push_back((own ? r.label : r.label + ": " + symbol) + " (line " + std::to_string(r.loc.line) + ")");
  }
  server_.sendTextToAll(header);
  for (std::string& p : parts) server_.sendBinaryToAll(std::move(p));
}

void ViewSession::pick(uint64_t page, uint32_t instance) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (instance >= lastInstances_.instances.size()) return;
  const rt::Instance& inst = lastInstances_.instances[instance];
  const Json params = Json::parse(rt::io::instanceParamsJson(lastInstances_, inst), nullptr, false);
  const Eigen::Map<const Eigen::Matrix4d> t(inst.transform.data());
  const Eigen::Vector4d centre = t * Eigen::Vector4d(0.5, 0.5, 0.5, 1);
  // Lines and the surface are placed by no rule; the axiom's own I() by the axiom.
  const rt::InstanceOrigin origin =
      instance < lastInstances_.origins.size() ? lastInstances_.origins[instance] : rt::InstanceOrigin{};
  const Json rule = origin.rule < lastRules_.size() ? Json(lastRules_[origin.rule])
                    : origin.depth != UINT32_MAX    ? Json("the axiom")
                                                    : Json(nullptr);
  const Json depth = origin.depth == UINT32_MAX ? Json(nullptr) : Json(origin.depth);
  server_.sendText(page, Json{{"type", "picked"},
                             {"instance", instance},
                             {"rule", rule},
                             {"depth", depth},
                             {"symbol", inst.symbol < lastInstances_.symbols.size() ? lastInstances_.symbols[inst.symbol] : ""},
                             {"asset", inst.asset < lastInstances_.assets.size() ? lastInstances_.assets[inst.asset] : ""},
                             {"params", params.is_discarded() ? Json::array() : params},
                             {"colour", inst.color},
                             {"centre", {centre.x(), centre.y(), centre.z()}}}
                            .dump());
}

}  // namespace fgsg::cli
