// The C API of libfgsg.so (backend/aot/fgsg_api.h): a compiled grammar library's
// program run by the engine, with the options and outputs of `fgsg run`. Every entry
// point catches everything: no C++ exception crosses into C. Generators share no
// mutable state, so several can derive at once in different threads.
#include "backend/aot/fgsg_api.h"

#include "backend/derive_messages.h"
#include "backend/interp/eval.h"
#include "backend/interp/interpreter.h"
#include "backend/scene_starts.h"
#include "frontend/diagnostics.h"
#include "ir/pipeline.h"
#include "runtime/io/cache_folder.h"
#include "runtime/io/read_input.h"
#include "runtime/io/read_lots.h"
#include "runtime/io/seed_points.h"
#include "runtime/abi.h"
#include "runtime/assemble.h"
#include "runtime/io/write_mesh.h"
#include "runtime/io/write_reports.h"
#include "runtime/memory_budget.h"
#include "runtime/out_of_resources.h"
#include "runtime/output/scene_nodes.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <limits>
#include <memory>
#include <mutex>
#include <new>
#include <optional>
#include <string>
#include <vector>

namespace {

// Every runtime entry point generated code may call (runtime/abi.def), referenced once
// so that the linker takes them all from the static libraries into libfgsg.so, where
// the version script exports them to compiled grammar libraries.
#define FGSG_RT_FN(name, ret, ...) reinterpret_cast<const void*>(&name),
[[maybe_unused]] __attribute__((used)) const void* const kRuntimeEntryPoints[] = {
#include "runtime/abi.def"
};

}  // namespace

using namespace fgsg;

struct fgsg_generator {
  const FgsgProgram* program = nullptr;
  std::string unusable;  // why the program cannot be used; empty when it can
  std::string lastError;
  std::string compileWarnings;
  std::string warnings;  // compileWarnings + those of the last generate

  frontend::SourceFile source;
  ir::Module module;
  rt::DeriveOptions options;
  std::vector<std::string> extraAssetDirs;  // "asset-dir" options, in order
  // fgsg_attr_*: per attr its name, kind, default and annotations JSON, made at compile.
  struct AttrTexts {
    std::string name, kind, value, annotations;
  };
  std::vector<AttrTexts> attrTexts;

  // The last generation.
  std::unique_ptr<rt::AssetLibrary> assets;
  bool hasResult = false;
  rt::DeriveResult result;
  rt::Mesh mesh;
  std::vector<double> transforms;
  std::vector<uint32_t> instanceAssets;
  std::string reportsJson;  // fgsg_reports_json
  // fgsg_scene_node_*: the scene is built from these on the first call after a generation.
  std::vector<int> meshOf;
  std::vector<fgsg::rt::output::StartInfo> starts;
  mutable std::optional<std::vector<fgsg::rt::output::SceneNodeInfo>> sceneNodes;
  std::string prints;       // fgsg_prints: also after a failed generation
};

namespace {

const char* const kNullGenerator = "fgsg: no generator (NULL)";

std::string jsonString(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (u < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", u);
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string numberText(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  // The shortest text that reads back as v.
  for (int digits = 1; digits <= 17; ++digits) {
    char shorter[32];
    std::snprintf(shorter, sizeof shorter, "%.*g", digits, v);
    if (std::strtod(shorter, nullptr) == v) return shorter;
  }
  return buf;
}

// An attr as fgsg_attr_* give it: name, kind, default as fgsg_set_attribute reads it,
// and its annotations as JSON.
fgsg_generator::AttrTexts attrTexts(const ir::Module& m, const ir::Attr& a) {
  fgsg_generator::AttrTexts t;
  t.name = a.name;
  t.kind = ir::typeName(a.type);
  switch (a.type) {
    case ir::Type::Num: t.value = numberText(a.value.num); break;
    case ir::Type::Bool: t.value = a.value.num != 0 ? "true" : "false"; break;
    case ir::Type::Str: {
      const auto id = static_cast<size_t>(a.value.num);
      t.value = id < m.strings.size() ? m.strings[id] : std::string();
      break;
    }
    case ir::Type::Vec3:
      t.value = numberText(a.value.vec[0]) + "," + numberText(a.value.vec[1]) + "," + numberText(a.value.vec[2]);
      break;
  }
  t.annotations = "[";
  for (size_t i = 0; i < a.annotations.size(); ++i) {
    const ir::AttrAnnotation& note = a.annotations[i];
    std::string args, named;
    for (const auto& [key, value] : note.args) {
      if (key.empty())
        args += (args.empty() ? "" : ", ") + jsonString(value);
      else
        named += (named.empty() ? "" : ", ") + jsonString(key) + ": " + jsonString(value);
    }
    t.annotations += std::string(i ? ", " : "") + "{\"name\": " + jsonString(note.name) + ", \"args\": [" + args +
                     "], \"named\": {" + named + "}}";
  }
  t.annotations += "]";
  return t;
}

// Compiles the program's grammar text into g->module; false with the diagnostics in
// g->unusable. The ANTLR runtime's parser caches (ATN, DFA, prediction contexts) are
// static members shared by every parser and the 4.9 runtime does not promise that they
// may be updated from two threads at once, so compilations take turns; derivations,
// the expensive part, run concurrently.
bool compileProgramSource(fgsg_generator* g) {
  const FgsgProgram* p = g->program;
  const std::string name = p->sourceName && *p->sourceName ? p->sourceName : "<compiled grammar>";
  g->source = frontend::SourceFile::make(name, p->source);
  g->source.startRule = p->startRule ? p->startRule : "";  // the rule and style it was compiled for
  frontend::Diagnostics diags(&g->source);
  bool ok;
  {
    static std::mutex frontendMutex;
    std::lock_guard<std::mutex> lock(frontendMutex);
    ok = ir::compileSource(g->source, g->module, diags);
  }
  std::string errors;
  std::string* to = &errors;  // a note goes with the diagnostic before it
  for (const auto& d : diags.all()) {
    if (d.severity != frontend::Severity::Note)
      to = d.severity == frontend::Severity::Warning ? &g->compileWarnings : &errors;
    *to += diags.format(d) + "\n";
  }
  if (!ok) {
    g->unusable = errors.empty() ? name + ": the grammar does not compile\n" : errors;
    g->unusable += std::to_string(diags.errorCount()) + " error" + (diags.errorCount() == 1 ? "" : "s") +
                   " in " + name;
    return false;
  }
  g->warnings = g->compileWarnings;
  g->attrTexts.clear();
  for (const ir::Attr& a : g->module.attrs) g->attrTexts.push_back(attrTexts(g->module, a));
  return true;
}

// Runs `body` for a usable generator: sets lastError from its outcome and turns every
// exception into a failure.
template <class F>
int guarded(fgsg_generator* g, F&& body) noexcept {
  if (!g) return 1;
  const char* failure = nullptr;
  std::string what;
  try {
    if (!g->unusable.empty()) {
      g->lastError = g->unusable;
      return 1;
    }
    std::string error;
    if (!body(error)) {
      g->lastError = error.empty() ? "fgsg: failed" : error;
      return 1;
    }
    g->lastError.clear();
    return 0;
  } catch (const std::bad_alloc&) {
    failure = "fgsg: out of memory";
  } catch (const std::exception& e) {
    failure = "fgsg: internal error: ";
    try {
      what = rt::outOfResources(e);
      if (!what.empty())
        failure = "fgsg: out of memory: ";
      else
        what = e.what();
    } catch (...) {
    }
  } catch (...) {
    failure = "fgsg: internal error";
  }
  try {
    g->lastError = failure + what;
  } catch (...) {
    g->lastError.clear();  // no memory left even for the message
  }
  return 1;
}

bool parseUnsigned(const std::string& v, uint64_t& out) {
  char* end = nullptr;
  errno = 0;
  const unsigned long long n = std::strtoull(v.c_str(), &end, 10);
  if (v.empty() || v[0] == '-' || v[0] == '+' || std::isspace(static_cast<unsigned char>(v[0])) ||
      *end != '\0' || errno == ERANGE)
    return false;
  out = n;
  return true;
}

bool parseNumber(const std::string& v, double& out) {
  char* end = nullptr;
  const double d = std::strtod(v.c_str(), &end);
  if (v.empty() || *end != '\0' || !std::isfinite(d)) return false;
  out = d;
  return true;
}

// "x,y,z": three finite numbers separated by commas, spaces allowed (as --start).
bool parsePoint(const std::string& v, double out[3]) {
  size_t from = 0;
  double p[3];
  for (int k = 0; k < 3; ++k) {
    const size_t comma = v.find(',', from);
    if ((k < 2) != (comma != std::string::npos)) return false;
    std::string part = v.substr(from, k < 2 ? comma - from : std::string::npos);
    const size_t first = part.find_first_not_of(" \t");
    const size_t last = part.find_last_not_of(" \t");
    if (first == std::string::npos) return false;
    part = part.substr(first, last - first + 1);
    if (!parseNumber(part, p[k])) return false;
    from = comma + 1;
  }
  for (int k = 0; k < 3; ++k) out[k] = p[k];
  return true;
}

bool parseSwitch(const char* value, bool& out) {
  if (!value || !*value || std::strcmp(value, "1") == 0) {
    out = true;
    return true;
  }
  if (std::strcmp(value, "0") == 0) {
    out = false;
    return true;
  }
  return false;
}

void clearResult(fgsg_generator* g) {
  g->hasResult = false;
  g->result = rt::DeriveResult{};
  g->mesh = rt::Mesh{};
  g->transforms.clear();
  g->instanceAssets.clear();
  g->reportsJson.clear();
  g->meshOf.clear();
  g->starts.clear();
  g->sceneNodes.reset();
  g->assets.reset();
  g->warnings = g->compileWarnings;
}

bool generate(fgsg_generator* g, std::string& error) {
  clearResult(g);
  rt::DeriveOptions opt = g->options;
  if (!g->module.surface.present && opt.surfaceOverride.empty() &&
      (opt.hasStart || opt.repairSurface || opt.surfaceSize > 0)) {
    error = std::string("fgsg: option ") +
            (opt.hasStart ? "start" : opt.repairSurface ? "repair-surface" : "surface-size") +
            " needs a surface: " + g->source.name +
            " declares none (it grows on the plane) and no surface is set";
    return false;
  }

  // As fgsg run: the grammar's folder and its assets/ folder, then the added folders.
  const auto grammarDir = std::filesystem::path(g->source.name).parent_path();
  auto assets = std::make_unique<rt::AssetLibrary>();
  std::vector<std::string> dirs = {(grammarDir.empty() ? std::filesystem::path(".") : grammarDir).string(),
                                   (grammarDir / "assets").string()};
  dirs.insert(dirs.end(), g->extraAssetDirs.begin(), g->extraAssetDirs.end());
  for (const auto& dir : dirs) {
    assets->addSearchDir(dir);
    opt.assetDirs.push_back(dir);
  }

  if (const std::string cache = rt::io::cacheFolder(); !cache.empty()) opt.atlasCacheDir = cache + "/atlas";
  rt::DeriveResult result = backend::deriveCompiled(g->module, *g->program, opt, *assets);
  g->prints.clear();
  for (const rt::PrintLine& p : result.prints)
    g->prints += g->source.name + ":" + std::to_string(p.line) + ":" + std::to_string(p.col) + ": print: " + p.text + "\n";
  frontend::Diagnostics diags(&g->source);
  std::string warnings;
  backend::addDeriveMessages(result, diags);
  for (const auto& d : diags.all()) {
    if (d.severity == frontend::Severity::Warning) warnings += diags.format(d) + "\n";
  }
  g->warnings += warnings;
  if (diags.hasErrors() || !result.ok) {
    // Every message, errors and warnings in the order reported, as fgsg run prints them.
    for (const auto& d : diags.all()) error += (error.empty() ? "" : "\n") + diags.format(d);
    if (error.empty()) error = "fgsg: the derivation failed";
    return false;
  }

  std::vector<int> meshOf;
  if (!rt::resolveAssets(result.instances, *assets, meshOf, error)) {
    error = "fgsg: " + error;
    return false;
  }
  g->mesh = rt::assembleInstances(result.instances, *assets, meshOf);
  const auto& list = result.instances.instances;
  g->transforms.reserve(16 * list.size());
  g->instanceAssets.reserve(list.size());
  for (const auto& inst : list) {
    g->transforms.insert(g->transforms.end(), inst.transform.begin(), inst.transform.end());
    g->instanceAssets.push_back(inst.asset);
  }
  g->reportsJson = rt::io::encodeReportsJson(result, opt.lots);
  g->starts = backend::sceneStarts(g->module, opt, result);
  g->meshOf = std::move(meshOf);
  g->result = std::move(result);
  g->assets = std::move(assets);
  g->hasResult = true;
  return true;
}

template <class V>
const typename V::value_type* dataOrNull(const V& v) {
  return v.empty() ? nullptr : v.data();
}

}  // namespace

extern "C" {

FGSG_API fgsg_generator* fgsg_generator_create(const struct FgsgProgram* program) {
  fgsg_generator* g = nullptr;
  try {
    g = new fgsg_generator;
    g->program = program;
    if (!program) {
      g->unusable = "fgsg: no program (NULL)";
    } else if (program->abiVersion != FGSG_ABI_VERSION) {
      g->unusable = "fgsg: the program was compiled for ABI version " +
                    std::to_string(program->abiVersion) + ", this libfgsg runs version " +
                    std::to_string(FGSG_ABI_VERSION) + ": compile the grammar again with this fgsg";
    } else if (!program->source) {
      g->unusable = "fgsg: the program carries no grammar text (not built by fgsg compile?)";
    } else {
      compileProgramSource(g);
    }
    g->lastError = g->unusable;
    return g;
  } catch (...) {
    // Out of memory (or worse): without a generator there is nowhere to say why.
    delete g;
    return nullptr;
  }
}

FGSG_API void fgsg_generator_free(fgsg_generator* g) {
  try {
    delete g;
  } catch (...) {
  }
}

FGSG_API const char* fgsg_last_error(const fgsg_generator* g) {
  return g ? g->lastError.c_str() : kNullGenerator;
}

FGSG_API const char* fgsg_warnings(const fgsg_generator* g) { return g ? g->warnings.c_str() : ""; }

FGSG_API int fgsg_set_seed(fgsg_generator* g, uint64_t seed) {
  return guarded(g, [&](std::string&) {
    g->options.seed = seed;
    return true;
  });
}

FGSG_API int fgsg_set_attribute(fgsg_generator* g, const char* name, const char* value) {
  return guarded(g, [&](std::string& error) {
    if (!name || !*name) {
      error = "fgsg_set_attribute: no attribute name given";
      return false;
    }
    if (!value) {
      error = std::string("fgsg_set_attribute ") + name + ": no value given (NULL)";
      return false;
    }
    // Checked now, not at the next fgsg_generate: a bad one kept would fail every later
    // generation with no way to take it back. Kept in order like repeated --set flags.
    const std::string problem = backend::attributeOverrideProblem(g->module, name, value);
    if (!problem.empty()) {
      error = "error[R010]: fgsg_set_attribute " + problem;  // R010 as for fgsg run --set
      return false;
    }
    g->options.attrOverrides.push_back({name, value});
    return true;
  });
}

FGSG_API int fgsg_set_surface(fgsg_generator* g, const char* mesh_path) {
  return guarded(g, [&](std::string& error) {
    if (!mesh_path || !*mesh_path) {
      g->options.surfaceOverride.clear();
      return true;
    }
    // Relative to the working directory, not to the grammar's folder (as fgsg run).
    std::error_code ec;
    const std::filesystem::path surface = std::filesystem::absolute(mesh_path, ec);
    std::string refused;
    if (!rt::io::checkInputFile(mesh_path, "a mesh file", refused)) {
      error = "fgsg_set_surface " + refused;
      return false;
    }
    g->options.surfaceOverride = surface.lexically_normal().string();
    return true;
  });
}

FGSG_API int fgsg_set_option(fgsg_generator* g, const char* name, const char* value) {
  return guarded(g, [&](std::string& error) {
    const std::string n = name ? name : "";
    const std::string v = value ? value : "";
    auto bad = [&](const std::string& expected) {
      error = "fgsg_set_option " + n + ": expected " + expected + ", got " +
              (value ? "'" + v + "'" : std::string("NULL"));
      return false;
    };
    rt::DeriveOptions& o = g->options;
    if (n == "collide-all" || n == "repair-surface") {
      bool on;
      if (!parseSwitch(value, on)) return bad("NULL, \"\", \"1\" or \"0\"");
      (n == "collide-all" ? o.collideAll : o.repairSurface) = on;
    } else if (n == "surface-size") {
      double s;
      if (!parseNumber(v, s) || !(s > 0)) return bad("a positive number");
      o.surfaceSize = s;
    } else if (n == "start") {
      if (!parsePoint(v, o.start)) return bad("a point x,y,z (three numbers separated by commas)");
      o.hasStart = true;
    } else if (n == "max-shapes") {
      uint64_t m;
      if (!parseUnsigned(v, m)) return bad("a whole number >= 0");
      o.maxShapes = m;
    } else if (n == "max-depth") {
      uint64_t m;
      if (!parseUnsigned(v, m) || m > std::numeric_limits<uint32_t>::max())
        return bad("a whole number from 0 to 4294967295");
      o.maxDepth = static_cast<uint32_t>(m);
    } else if (n == "step") {  // fgsg run --step: past the derivation's length, the length
      uint64_t m;
      if (!parseUnsigned(v, m) || m > 2147483647) return bad("a whole number from 0 to 2147483647");
      o.parallelStep = static_cast<int32_t>(m);
    } else if (n == "max-seconds") {
      double s;
      if (!parseNumber(v, s) || !(s > 0)) return bad("a positive number of seconds");
      o.maxSeconds = s;
    } else if (n == "max-memory") {
      const std::optional<uint64_t> bytes = fgsg::rt::parseMemorySize(v);
      if (!bytes) return bad("a size such as 512M or 2G");
      o.maxMemoryBytes = *bytes;
    } else if (n == "seed-points") {
      std::vector<rt::DeriveOptions::Seed> more;
      std::string why;
      if (!rt::io::readSeedPoints(v, more, why)) return bad("seeds x,y,z[:dx,dy,dz] (" + why + ")");
      o.seeds.insert(o.seeds.end(), more.begin(), more.end());
    } else if (n == "lots") {
      std::vector<rt::Lot> lots;
      size_t skipped = 0;
      std::string why;
      if (!rt::readLots(v, lots, skipped, why)) return bad("a file of lots, GeoJSON or a mesh's faces (" + why + ")");
      o.lots = std::move(lots);
      o.lotsName = v;
    } else if (n == "seed-density") {
      if (v.empty()) return bad("a texture name");
      o.seedDensity = v;
    } else if (n == "seed-count" || n == "march-candidates" || n == "atlas-resolution") {
      uint64_t m;
      const uint64_t lo = n == "atlas-resolution" ? 16 : n == "seed-count" ? 1 : 0;
      const uint64_t hi = n == "atlas-resolution" ? 8192 : n == "seed-count" ? 1'000'000 : 64;
      if (!parseUnsigned(v, m) || m < lo || m > hi)
        return bad("a whole number from " + std::to_string(lo) + " to " + std::to_string(hi));
      if (n == "seed-count") o.seedCount = static_cast<uint32_t>(m);
      else if (n == "march-candidates") o.marchCandidates = static_cast<int>(m);
      else o.atlasResolution = static_cast<int>(m);
    } else if (n == "march-units") {
      if (v != "surface" && v != "texels") return bad("surface or texels");
      o.marchInTexels = v == "texels";
    } else if (n == "asset-dir") {
      if (v.empty()) return bad("a folder name");
      g->extraAssetDirs.push_back(v);
    } else {
      error = "fgsg_set_option: unknown option " + (name ? "'" + n + "'" : std::string("NULL")) +
              " (collide-all, repair-surface, surface-size, start, max-shapes, max-depth, "
              "max-seconds, max-memory, asset-dir, seed-points, seed-density, seed-count, "
              "march-candidates, atlas-resolution, march-units, lots)";
      return false;
    }
    return true;
  });
}

FGSG_API int fgsg_generate(fgsg_generator* g) {
  const int rc = guarded(g, [&](std::string& error) { return generate(g, error); });
  if (rc != 0 && g && g->unusable.empty()) {
    try {
      const std::string warnings = g->warnings;
      clearResult(g);
      g->warnings = warnings;
    } catch (...) {
    }
  }
  return rc;
}

FGSG_API size_t fgsg_vertex_count(const fgsg_generator* g) { return g ? g->mesh.vertexCount() : 0; }
FGSG_API const float* fgsg_positions(const fgsg_generator* g) {
  return g ? dataOrNull(g->mesh.positions) : nullptr;
}
FGSG_API const float* fgsg_normals(const fgsg_generator* g) {
  return g ? dataOrNull(g->mesh.normals) : nullptr;
}
FGSG_API const float* fgsg_colors(const fgsg_generator* g) {
  return g ? dataOrNull(g->mesh.colors) : nullptr;
}
FGSG_API size_t fgsg_index_count(const fgsg_generator* g) { return g ? g->mesh.indices.size() : 0; }
FGSG_API const uint32_t* fgsg_indices(const fgsg_generator* g) {
  return g ? dataOrNull(g->mesh.indices) : nullptr;
}

FGSG_API size_t fgsg_line_index_count(const fgsg_generator* g) { return g ? g->mesh.lines.size() : 0; }

FGSG_API const uint32_t* fgsg_line_indices(const fgsg_generator* g) {
  return g ? dataOrNull(g->mesh.lines) : nullptr;
}

FGSG_API size_t fgsg_instance_count(const fgsg_generator* g) {
  return g ? g->instanceAssets.size() : 0;
}
FGSG_API const double* fgsg_instance_transforms(const fgsg_generator* g) {
  return g ? dataOrNull(g->transforms) : nullptr;
}
FGSG_API const uint32_t* fgsg_instance_assets(const fgsg_generator* g) {
  return g ? dataOrNull(g->instanceAssets) : nullptr;
}
FGSG_API const char* fgsg_asset_name(const fgsg_generator* g, uint32_t asset) {
  if (!g || !g->hasResult || asset >= g->result.instances.assets.size()) return nullptr;
  return g->result.instances.assets[asset].c_str();
}

FGSG_API const char* fgsg_reports_json(const fgsg_generator* g) { return g ? g->reportsJson.c_str() : ""; }

FGSG_API size_t fgsg_report_count(const fgsg_generator* g) {
  return g && g->hasResult ? g->result.reports.size() : 0;
}

FGSG_API int fgsg_report(const fgsg_generator* g, size_t i, uint32_t* start, const char** key, int* kind,
                         double* number, const char** text) {
  if (!g || !g->hasResult || i >= g->result.reports.size()) return 1;
  const rt::Report& r = g->result.reports[i];
  if (start) *start = r.start;
  if (key) *key = r.key.c_str();
  if (kind) *kind = static_cast<int>(r.value.kind);
  if (number) *number = r.value.number;
  if (text) *text = r.value.text.c_str();
  return 0;
}

namespace {

// The scene's nodes (--instancing auto --group-by symbol), built on first use; NULL before
// a generation, or when building it runs out of memory.
const fgsg::rt::output::SceneNodeInfo* sceneNode(const fgsg_generator* g, size_t i) {
  if (!g || !g->hasResult) return nullptr;
  if (!g->sceneNodes) {
    try {
      fgsg::rt::output::SceneInput in;
      in.list = &g->result.instances;
      in.library = g->assets.get();
      in.meshOf = &g->meshOf;
      in.starts = g->starts;
      g->sceneNodes = fgsg::rt::output::sceneNodes(fgsg::rt::output::buildScene(in));
    } catch (...) {
      return nullptr;
    }
  }
  return i < g->sceneNodes->size() ? &(*g->sceneNodes)[i] : nullptr;
}

}  // namespace

FGSG_API size_t fgsg_scene_node_count(const fgsg_generator* g) {
  return sceneNode(g, 0) ? g->sceneNodes->size() : 0;
}
FGSG_API const char* fgsg_scene_node_name(const fgsg_generator* g, size_t i) {
  const auto* n = sceneNode(g, i);
  return n ? n->name.c_str() : nullptr;
}
FGSG_API int64_t fgsg_scene_node_parent(const fgsg_generator* g, size_t i) {
  const auto* n = sceneNode(g, i);
  return n ? n->parent : -1;
}
FGSG_API const double* fgsg_scene_node_transform(const fgsg_generator* g, size_t i) {
  const auto* n = sceneNode(g, i);
  return n ? n->transform.data() : nullptr;
}
FGSG_API const char* fgsg_scene_node_extras_json(const fgsg_generator* g, size_t i) {
  const auto* n = sceneNode(g, i);
  return n ? n->extras.c_str() : nullptr;
}
FGSG_API size_t fgsg_scene_node_meshes(const fgsg_generator* g, size_t i) {
  const auto* n = sceneNode(g, i);
  return n ? n->meshes : 0;
}
FGSG_API size_t fgsg_scene_node_instances(const fgsg_generator* g, size_t i) {
  const auto* n = sceneNode(g, i);
  return n ? n->instances : 0;
}

FGSG_API const char* fgsg_prints(const fgsg_generator* g) { return g ? g->prints.c_str() : ""; }

FGSG_API int fgsg_write(fgsg_generator* g, const char* path) {
  return guarded(g, [&](std::string& error) {
    if (!path || !*path) {
      error = "fgsg_write: no file name given";
      return false;
    }
    if (!g->hasResult) {
      error = std::string("fgsg_write ") + path + ": nothing generated yet (call fgsg_generate first)";
      return false;
    }
    if (!rt::io::writeMesh(g->mesh, path, error)) {
      error = "fgsg_write: " + error;
      return false;
    }
    return true;
  });
}

FGSG_API size_t fgsg_attr_count(const fgsg_generator* g) { return g ? g->attrTexts.size() : 0; }

FGSG_API const char* fgsg_attr_name(const fgsg_generator* g, size_t index) {
  return g && index < g->attrTexts.size() ? g->attrTexts[index].name.c_str() : nullptr;
}

FGSG_API const char* fgsg_attr_kind(const fgsg_generator* g, size_t index) {
  return g && index < g->attrTexts.size() ? g->attrTexts[index].kind.c_str() : nullptr;
}

FGSG_API const char* fgsg_attr_default(const fgsg_generator* g, size_t index) {
  return g && index < g->attrTexts.size() ? g->attrTexts[index].value.c_str() : nullptr;
}

FGSG_API const char* fgsg_attr_annotations_json(const fgsg_generator* g, size_t index) {
  return g && index < g->attrTexts.size() ? g->attrTexts[index].annotations.c_str() : nullptr;
}

}  // extern "C"
