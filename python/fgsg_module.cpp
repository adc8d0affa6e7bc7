// fgsg's Python module, `fgsg._fgsg` (pybind11): compiles grammars and derives them in
// process with the same engines as `fgsg run`, and hands the results to numpy without
// copies. The Python face (GrammarError, Grammar.from_file ...) is python/fgsg/__init__.py.
#include "backend/derive_messages.h"
#include "backend/engine.h"
#include "backend/interp/eval.h"
#include "backend/interp/interpreter.h"
#include "backend/scene_starts.h"
#include "runtime/abi.h"
#include "cli/derive_stats.h"
#include "ir/pipeline.h"
#include "runtime/assemble.h"
#include "runtime/io/png_encode.h"
#include "runtime/io/read_lots.h"
#include "runtime/io/write_instances.h"
#include "runtime/io/write_mesh.h"
#include "runtime/io/write_reports.h"
#include "runtime/out_of_resources.h"
#include "runtime/output/scene_nodes.h"
#include "runtime/render/preview.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <dlfcn.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace py = pybind11;
using namespace fgsg;

namespace {

// Memory ran out outside the derivation (which reports R020 as a diagnostic itself):
// raised as MemoryError with the CLI's R020 message and the limit that was met, not
// pybind's bare "std::bad_alloc".
struct OutOfMemory {
  std::string message;
};

OutOfMemory outOfMemory(const std::string& what) {
  return {"R020: out of memory " + what + " (" + rt::memoryLimitInForce() + "); nothing was kept"};
}

// A grammar's diagnostics, raised as fgsg._fgsg.CompileError(list of dicts); the package
// turns it into fgsg.GrammarError.
struct CompileError {
  py::list diagnostics;
};

py::list diagnosticList(const frontend::Diagnostics& diags, const std::string& file) {
  py::list out;
  for (const auto& d : diags.all()) {
    if (d.severity != frontend::Severity::Error) continue;
    py::dict e;
    e["file"] = file;
    e["line"] = d.range.begin.line;
    e["column"] = d.range.begin.col;
    e["code"] = d.code;
    e["message"] = d.message;
    e["text"] = diags.format(d);
    out.append(e);
  }
  return out;
}

// A derived model: the mesh fgsg run writes, the instances and the figures.
struct Result {
  rt::Mesh mesh;
  rt::InstanceList instances;
  rt::DeriveStats stats;
  std::string reportsJson;            // Report(key, value): what fgsg run --report writes
  std::vector<rt::PrintLine> prints;  // Print(value)
  // What Result.scene builds the scene from (with `instances`).
  std::shared_ptr<const rt::AssetLibrary> assets;
  std::vector<int> meshOf;
  std::vector<rt::output::StartInfo> starts;
};

// A view of `size` elements of `data` as a numpy array of `shape`, kept alive by `owner`.
template <typename T>
py::array view(const T* data, std::vector<py::ssize_t> shape, py::object owner) {
  return py::array_t<T>(shape, data, owner);
}

struct Grammar {
  frontend::SourceFile source;
  ir::Module module;
  std::vector<std::string> dataDirs;  // the grammar's folder and its assets/ (as fgsg run)
  // A library built by `fgsg compile`: its code runs instead of the JIT's (same results).
  const FgsgProgram* program = nullptr;
  std::shared_ptr<void> library;  // dlclose'd with the last Grammar using it

  static std::shared_ptr<Grammar> fromLibrary(const std::string& path, std::string name) {
    if (name.empty()) {  // libNAME.so
      name = std::filesystem::path(path).stem().string();
      if (name.rfind("lib", 0) == 0) name = name.substr(3);
    }
    void* handle = dlopen(std::filesystem::absolute(path).c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) throw std::runtime_error(path + ": cannot load the library: " + dlerror());
    std::shared_ptr<void> library(handle, [](void* h) { dlclose(h); });
    const std::string symbol = "fgsg_program_" + name;
    const auto* program = static_cast<const FgsgProgram*>(dlsym(handle, symbol.c_str()));
    if (!program)
      throw std::runtime_error(path + ": no " + symbol + " in it (not built by fgsg compile, or another NAME: pass name=)");
    if (program->abiVersion != FGSG_ABI_VERSION)
      throw std::runtime_error(path + ": compiled for ABI version " + std::to_string(program->abiVersion) +
                               ", this fgsg runs " + std::to_string(FGSG_ABI_VERSION) + ": compile it again");
    if (!program->source) throw std::runtime_error(path + ": the program carries no grammar text");
    auto g = compile(program->source, program->sourceName && *program->sourceName ? program->sourceName : path,
                     program->startRule ? program->startRule : "");  // fgsg compile --start-rule's
    g->program = program;
    g->library = std::move(library);
    return g;
  }

  // `startRule`: a .cga grammar's rule for its start shapes instead of its @StartRule (as
  // fgsg run --start-rule); "" its own.
  static std::shared_ptr<Grammar> compile(const std::string& text, const std::string& name,
                                          const std::string& startRule) {
    auto g = std::make_shared<Grammar>();
    g->source = frontend::SourceFile::make(name, text);
    g->source.startRule = startRule;
    frontend::Diagnostics diags(&g->source);
    if (!ir::compileSource(g->source, g->module, diags)) throw CompileError{diagnosticList(diags, name)};
    const std::filesystem::path dir = std::filesystem::path(name).parent_path();
    g->dataDirs = {(dir.empty() ? std::filesystem::path(".") : dir).string(), ((dir.empty() ? "." : dir) / "assets").string()};
    return g;
  }

  static std::shared_ptr<Grammar> fromFile(const std::string& path, const std::string& startRule) {
    frontend::SourceFile file;
    std::string error;
    if (!ir::readSourceFile(path, file, error)) throw std::runtime_error(error);
    return compile(file.text, path, startRule);
  }

  // `attrs`: (name, value as text) pairs, their Python types already checked against the
  // attributes' kinds by the package (python/fgsg/__init__.py); `seed` a whole number from
  // 0 to 2^64 - 1 (checked there too); `step` fgsg run's --step (0 to 2^31 - 1, checked there).
  std::shared_ptr<Result> generate(uint64_t seed, const std::vector<std::pair<std::string, std::string>>& attrs,
                                   const std::optional<std::string>& surface,
                                   std::optional<uint64_t> maxShapes, const std::string& engineName,
                                   const std::optional<std::string>& lots, std::optional<uint32_t> maxDepth,
                                   std::optional<double> maxSeconds, std::optional<int32_t> step) {
    const auto engine = backend::parseEngine(engineName);
    if (!engine) throw py::value_error("engine must be 'jit' or 'interp', got '" + engineName + "'");
    rt::DeriveOptions options;
    options.seed = seed;
    if (maxShapes) options.maxShapes = *maxShapes;
    if (maxDepth) options.maxDepth = *maxDepth;
    if (maxSeconds) options.maxSeconds = *maxSeconds;  // positive and finite (checked by the package)
    if (surface) options.surfaceOverride = std::filesystem::absolute(*surface).string();
    if (lots) {  // as fgsg run --lots: the axiom once per lot, its footprint and properties
      size_t skipped = 0;
      std::string error;
      if (!rt::readLots(*lots, options.lots, skipped, error)) throw std::runtime_error(error);
      options.lotsName = *lots;
    }
    checkAttrs(attrs);
    options.attrOverrides = attrs;
    options.parallelStep = step.value_or(-1);
    auto result = std::make_shared<Result>();
    std::string error;
    frontend::Diagnostics diags(&source);
    {
      py::gil_scoped_release release;  // other Python threads derive meanwhile
      auto library = std::make_shared<rt::AssetLibrary>();
      rt::AssetLibrary& assets = *library;
      for (const std::string& d : dataDirs) {
        assets.addSearchDir(d);
        options.assetDirs.push_back(d);
      }
      rt::DeriveResult derived = program ? backend::deriveCompiled(module, *program, options, assets)
                                         : backend::derive(*engine, module, source.text, options, assets);
      backend::addDeriveMessages(derived, diags);
      if (!diags.hasErrors()) {
        std::vector<int> meshOf;
        if (!rt::resolveAssets(derived.instances, assets, meshOf, error)) {
          error = source.name + ": " + error;
        } else {
          try {
            result->mesh = rt::assembleInstances(derived.instances, assets, meshOf);
          } catch (const std::bad_alloc&) {
            throw outOfMemory("assembling " + std::to_string(derived.instances.instances.size()) +
                              " instances into one mesh");
          }
          result->reportsJson = rt::io::encodeReportsJson(derived, options.lots);
          result->prints = std::move(derived.prints);
          result->starts = backend::sceneStarts(module, options, derived);
          result->assets = std::move(library);
          result->meshOf = std::move(meshOf);
          result->instances = std::move(derived.instances);
          result->stats = derived.stats;
        }
      }
    }
    if (diags.hasErrors()) throw CompileError{diagnosticList(diags, source.name)};
    if (!error.empty()) throw std::runtime_error(error);
    return result;
  }

  // An attribute the grammar does not declare, or a value it cannot take (a count that is
  // not whole, ...): a GrammarError (R010) worded for Python, located at the attribute's
  // declaration when there is one. The engine would say the same of `--set`.
  void checkAttrs(const std::vector<std::pair<std::string, std::string>>& attrs) const {
    for (const auto& [name, text] : attrs) {
      std::string problem = backend::attributeOverrideProblem(module, name, text);
      if (problem.empty()) continue;
      const int a = module.findAttr(name);
      // The problem begins "name: " (unknown) or "name=text: " (a bad value).
      const std::string prefix = a < 0 ? name + ": " : name + "=" + text + ": ";
      if (problem.rfind(prefix, 0) == 0) problem = problem.substr(prefix.size());
      const std::string key = "attrs['" + name + "']";
      frontend::Diagnostics diags(&source);
      frontend::SourceRange at{};
      if (a >= 0) {
        const ir::Loc loc = module.attrs[a].value.loc;
        at = {{loc.line, loc.col}, {loc.line, loc.col}};
      }
      diags.error("R010", at, a < 0 ? key + ": " + problem : key + " = " + text + ": " + problem);
      throw CompileError{diagnosticList(diags, source.name)};
    }
  }

  // How many steps this L-system derives with these attribute values (N of `derive parallel
  // N;`, or its attr's value), -1 for a grammar that is no L-system: what the package
  // checks step= against. A bad attribute value is a GrammarError (R010), as in generate.
  int derivationLength(const std::vector<std::pair<std::string, std::string>>& attrs) const {
    checkAttrs(attrs);
    return backend::parallelDerivationLength(module, attrs);
  }

  // name -> (kind, default): "num" (a float), "bool", "str" or "vec3" (3 floats).
  py::list attrs() const {
    py::list out;
    for (const ir::Attr& a : module.attrs) {
      py::object value;
      switch (a.type) {
        case ir::Type::Num: value = py::float_(a.value.num); break;
        case ir::Type::Bool: value = py::bool_(a.value.num != 0); break;
        case ir::Type::Str: {
          const auto id = static_cast<size_t>(a.value.num);
          value = py::str(id < module.strings.size() ? module.strings[id] : std::string());
          break;
        }
        case ir::Type::Vec3: value = py::make_tuple(a.value.vec[0], a.value.vec[1], a.value.vec[2]); break;
      }
      out.append(py::make_tuple(a.name, ir::typeName(a.type), value));
    }
    return out;
  }

  // (name, [(annotation, [positional texts], {key: text})]) per attr, in declaration order:
  // a .cga attr's @Range, @Enum, @Hidden ... (metadata only).
  py::list attrAnnotations() const {
    py::list out;
    for (const ir::Attr& a : module.attrs) {
      py::list notes;
      for (const ir::AttrAnnotation& note : a.annotations) {
        py::list args;
        py::dict named;
        for (const auto& [key, value] : note.args) {
          if (key.empty()) args.append(py::str(value));
          else named[py::str(key)] = py::str(value);
        }
        notes.append(py::make_tuple(note.name, args, named));
      }
      out.append(py::make_tuple(a.name, notes));
    }
    return out;
  }
};

py::array instanceArray(const std::shared_ptr<Result>& r) {
  // asset, symbol, transform (4x4, row-major as numpy reads it), color, params slice.
  struct Row {
    uint32_t asset, symbol;
    double transform[4][4];
    float color[3];
    uint32_t paramOffset, paramCount;
  };
  py::dtype dt = py::dtype::from_args(py::list(py::make_tuple(
      py::make_tuple("asset", "<u4"), py::make_tuple("symbol", "<u4"),
      py::make_tuple("transform", "<f8", py::make_tuple(4, 4)), py::make_tuple("color", "<f4", py::make_tuple(3)),
      py::make_tuple("param_offset", "<u4"), py::make_tuple("param_count", "<u4"))));
  const auto& list = r->instances.instances;
  py::array out(dt, std::vector<py::ssize_t>{static_cast<py::ssize_t>(list.size())});
  auto* rows = static_cast<char*>(out.mutable_data());
  const size_t stride = static_cast<size_t>(dt.itemsize());
  for (size_t i = 0; i < list.size(); ++i) {
    const rt::Instance& inst = list[i];
    char* row = rows + i * stride;
    std::memcpy(row + 0, &inst.asset, 4);
    std::memcpy(row + 4, &inst.symbol, 4);
    double m[16];
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) m[4 * a + b] = inst.transform[4 * b + a];  // column-major to rows
    std::memcpy(row + 8, m, sizeof m);
    std::memcpy(row + 8 + sizeof m, inst.color.data(), 12);
    std::memcpy(row + 8 + sizeof m + 12, &inst.firstParam, 4);
    std::memcpy(row + 8 + sizeof m + 16, &inst.paramCount, 4);
  }
  return out;
}

}  // namespace

PYBIND11_MODULE(_fgsg, m) {
  m.doc() = "fgsg's engine: compile .fgsg grammars and derive them (see the fgsg package)";
  static py::exception<CompileError> compileError(m, "CompileError");
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const CompileError& e) {
      PyErr_SetObject(compileError.ptr(), e.diagnostics.ptr());
    } catch (const OutOfMemory& e) {
      PyErr_SetString(PyExc_MemoryError, e.message.c_str());
    }
  });

  py::class_<Result, std::shared_ptr<Result>>(m, "Result")
      .def_property_readonly("positions", [](const std::shared_ptr<Result>& r) {
        return view(r->mesh.positions.data(), {py::ssize_t(r->mesh.vertexCount()), 3}, py::cast(r));
      })
      .def_property_readonly("normals", [](const std::shared_ptr<Result>& r) {
        return view(r->mesh.normals.data(), {py::ssize_t(r->mesh.vertexCount()), 3}, py::cast(r));
      })
      .def_property_readonly("colors", [](const std::shared_ptr<Result>& r) {
        return view(r->mesh.colors.data(), {py::ssize_t(r->mesh.colors.size() / 3), 3}, py::cast(r));
      })
      .def_property_readonly("indices", [](const std::shared_ptr<Result>& r) {
        return view(r->mesh.indices.data(), {py::ssize_t(r->mesh.triangleCount()), 3}, py::cast(r));
      })
      .def_property_readonly("instances", &instanceArray)
      .def_property_readonly("params", [](const std::shared_ptr<Result>& r) {
        return view(r->instances.params.data(), {py::ssize_t(r->instances.params.size())}, py::cast(r));
      })
      .def("instance_params_json", [](const Result& r, size_t i) {
        if (i >= r.instances.instances.size()) throw py::index_error("no instance " + std::to_string(i));
        return rt::io::instanceParamsJson(r.instances, r.instances.instances[i]);
      })
      .def("reports_json", [](const Result& r) { return r.reportsJson; })
      // The scene's nodes as fgsg run's glTF lays them out (runtime/output/scene_nodes.h);
      // the package checks the names of `instancing` and `group_by`.
      .def("scene_nodes_json", [](const Result& r, const std::string& instancing, const std::string& groupBy) {
        rt::output::SceneInput in;
        if (!rt::output::parseInstancing(instancing, in.instancing) || !rt::output::parseGroupBy(groupBy, in.groupBy))
          throw py::value_error("instancing or group_by unknown");
        in.list = &r.instances;
        in.library = r.assets.get();
        in.meshOf = &r.meshOf;
        in.starts = r.starts;
        py::gil_scoped_release release;
        try {
          return rt::output::sceneNodesJson(rt::output::sceneNodes(rt::output::buildScene(in)));
        } catch (const std::bad_alloc&) {
          throw outOfMemory("building the scene");
        }
      })
      .def_property_readonly("prints", [](const Result& r) {
        py::list out;
        for (const rt::PrintLine& p : r.prints) out.append(py::make_tuple(p.line, p.col, p.text));
        return out;
      })
      .def_property_readonly("assets", [](const Result& r) { return r.instances.assets; })
      .def_property_readonly("symbols", [](const Result& r) { return r.instances.symbols; })
      .def_property_readonly("stats", [](const Result& r) {
        py::dict d;
        for (const auto& [name, value] : cli::deriveStatFigures(r.stats, r.mesh.triangleCount(), r.mesh.lineCount()))
          d[py::str(name)] = value;
        return d;
      })
      // fgsg run --preview's picture as PNG bytes (Result._repr_html_ shows it in Jupyter).
      .def("preview_png", [](const Result& r, int width, int height) {
        if (width < 1 || height < 1 || width > 8192 || height > 8192)
          throw py::value_error("preview width and height must be from 1 to 8192, got " + std::to_string(width) +
                                " x " + std::to_string(height));
        std::string png;
        {
          py::gil_scoped_release unlocked;  // the ray casting may take a while; other threads go on
          rt::render::PreviewOptions options;
          options.width = width;
          options.height = height;
          const rt::render::Image image = rt::render::renderImage(r.mesh, options);
          if (!rt::io::encodePng(image.width, image.height, 3, image.rgb.data(), png)) png.clear();
        }
        if (png.empty()) throw std::runtime_error("the preview could not be encoded as PNG");
        return py::bytes(png);
      }, py::arg("width"), py::arg("height"))
      .def("write", [](const Result& r, const std::string& path) {
        std::string error;
        try {
          if (!rt::io::writeMesh(r.mesh, path, error)) throw std::runtime_error(error);
        } catch (const std::bad_alloc&) {
          throw outOfMemory("writing " + path);
        }
      });

  py::class_<Grammar, std::shared_ptr<Grammar>>(m, "Grammar")
      .def_static("compile", &Grammar::compile, py::arg("text"), py::arg("name"), py::arg("start_rule") = "")
      .def_static("from_file", &Grammar::fromFile, py::arg("path"), py::arg("start_rule") = "")
      .def_static("from_library", &Grammar::fromLibrary, py::arg("path"), py::arg("name"))
      .def("generate", &Grammar::generate, py::arg("seed"), py::arg("attrs"), py::arg("surface"),
           py::arg("max_shapes"), py::arg("engine"), py::arg("lots"), py::arg("max_depth"), py::arg("max_seconds"),
           py::arg("step"))
      .def("derivation_length", &Grammar::derivationLength, py::arg("attrs"))
      .def_property_readonly("attrs", &Grammar::attrs)
      .def_property_readonly("attr_annotations", &Grammar::attrAnnotations)
      .def_property_readonly("name", [](const Grammar& g) { return g.source.name; })
      // The grammar's text, then each imported module's (what a compiled library embeds).
      .def_property_readonly("source", [](const Grammar& g) { return py::bytes(g.source.text); })
      .def_property_readonly("is_library", [](const Grammar& g) { return g.program != nullptr; });
  m.attr("__version__") = FGSG_VERSION;
}
