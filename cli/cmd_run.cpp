// fgsg run: compile a grammar, derive it, and write the mesh, preview and instances.
#include "backend/derive_messages.h"
#include "backend/engine.h"
#include "backend/native/code_loader.h"
#include "cli/command_line.h"
#include "cli/derive_flags.h"
#include "cli/commands.h"
#include "cli/compile_file.h"
#include "cli/derive_stats.h"
#include "cli/options.h"
#include "cli/preview_camera_flag.h"
#include "cli/progress_line.h"
#include "cli/scene_output.h"
#include "runtime/io/read_lots.h"
#include "runtime/io/seed_points.h"
#include "runtime/abandonable.h"
#include "runtime/assemble.h"
#include "runtime/io/cache_folder.h"
#include "runtime/io/read_input.h"
#include "runtime/io/write_instances.h"
#include "runtime/io/write_reports.h"
#include "runtime/memory_budget.h"
#include "runtime/io/write_mesh.h"
#include "runtime/output/time_budget.h"
#include "runtime/render/preview.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <new>
#include <optional>

namespace fgsg::cli {
namespace {

struct RunOptions {
  std::string file;
  std::string output;
  std::string preview;
  rt::render::PreviewCamera camera;  // --camera: where the preview is seen from
  bool cameraGiven = false;
  std::string instances;
  std::string lines;  // --lines: the line graph as JSON
  std::string report;  // --report: Report(key, value)'s collections per start shape, as JSON
  bool stats = false;
  bool quiet = false;
  size_t lotsSkipped = 0;  // --lots: geometries other than polygons, passed over
  backend::Engine engine = backend::Engine::Jit;
  std::string startRule;  // --start-rule: a .cga grammar's rule for the lots
  rt::DeriveOptions derive;
  SceneFlags scene;  // --instancing, --group-by
};

RunOptions parseRunOptions(const Args& args) {
  RunOptions o;
  CommandLine cl("run");
  cl.input(o.file, "grammar file");
  cl.text("-o,--output", o.output);
  cl.whole("--seed", o.derive.seed);
  engineFlag(cl, o.engine);
  cl.text("--preview", o.preview);
  cameraFlag(cl, o.camera, o.cameraGiven);
  cl.text("--instances", o.instances);
  cl.text("--lines", o.lines);
  cl.text("--report", o.report);
  cl.whole("--max-shapes", o.derive.maxShapes);
  cl.whole("--max-depth", o.derive.maxDepth);
  stepFlag(cl, o.derive);
  cl.option("--max-seconds", [&](const std::string& v) {
    o.derive.maxSeconds = CommandLine::parseNumber("--max-seconds", v);
    if (!(o.derive.maxSeconds > 0)) throw UsageError{"--max-seconds must be positive"};
  });
  cl.option("--max-memory", [&](const std::string& size) {
    const std::optional<uint64_t> bytes = rt::parseMemorySize(size);
    if (!bytes) throw UsageError{"--max-memory " + size + ": expected a size such as 512M or 2G"};
    o.derive.maxMemoryBytes = *bytes;
  });
  cl.flag("--collide-all", o.derive.collideAll);
  surfaceFlags(cl, o.derive);
  cl.repeated("--seed-points", [&](const std::string& v) {  // each flag adds its seeds
    std::string error;
    std::vector<rt::DeriveOptions::Seed> more;
    if (!rt::io::readSeedPoints(v, more, error)) throw UsageError{error};
    o.derive.seeds.insert(o.derive.seeds.end(), more.begin(), more.end());
  });
  cl.option("--lots", [&](const std::string& v) {
    o.derive.lotsName = v;
    std::string error;
    if (!rt::readLots(o.derive.lotsName, o.derive.lots, o.lotsSkipped, error)) throw UsageError{error};
  });
  cl.option("--seed-density", [&](const std::string& v) {
    if (v.empty()) throw UsageError{"--seed-density needs a texture name"};
    o.derive.seedDensity = v;
  });
  cl.whole("--seed-count", o.derive.seedCount, 1, 1'000'000);
  cl.whole("--march-candidates", o.derive.marchCandidates, 0, 64);
  cl.whole("--atlas-resolution", o.derive.atlasResolution, 16, 8192);
  cl.option("--march-units", [&](const std::string& unit) {
    if (unit != "surface" && unit != "texels")
      throw UsageError{"--march-units " + unit + ": use surface (3D distance, the default) or texels"};
    o.derive.marchInTexels = unit == "texels";
  });
  cl.option("--start", [&](const std::string& v) {
    CommandLine::parsePoint("--start", v, o.derive.start);
    o.derive.hasStart = true;
  });
  cl.flag("--stats", o.stats);
  cl.flag("-q,--quiet", o.quiet);
  setFlag(cl, o.derive);
  startRuleFlag(cl, o.startRule);
  sceneFlags(cl, o.scene);
  cl.parse(args);
  if (o.file.empty()) throw UsageError{"no grammar file given: fgsg run FILE [options]"};
  if (o.derive.seedDensity.empty() != (o.derive.seedCount == 0))
    throw UsageError{"--seed-density NAME and --seed-count N go together: N seeds drawn where texture NAME is bright"};
  // With --split-output alone, only the files per start shape are written.
  if (o.output.empty() && o.scene.splitOutput.empty())
    o.output = std::filesystem::path(o.file).stem().string() + ".glb";
  // Bad output names are usage errors, found before any work is done.
  checkOutput(o.scene, o.output, o.derive);
  if (!o.preview.empty() && lowerExtension(o.preview) != ".png")
    throw UsageError{"--preview " + o.preview + ": previews are PNG files (name it .png)"};
  if (o.cameraGiven && o.preview.empty()) throw UsageError{"--camera sets the preview's view: it needs --preview FILE.png"};
  if (!o.lines.empty() && lowerExtension(o.lines) != ".json")
    throw UsageError{"--lines " + o.lines + ": the line graph is written as JSON (name it .json)"};
  if (!o.report.empty() && lowerExtension(o.report) != ".json")
    throw UsageError{"--report " + o.report + ": reports are written as JSON (name it .json)"};
  return o;
}

// Seconds as a person writes them: "120", "38.4".
std::string secondsText(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", s == std::floor(s) ? 0 : 1, s);
  return buf;
}

double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// Prints derivation messages like compile diagnostics: location, source line, caret.
bool reportMessages(const rt::DeriveResult& result, const frontend::SourceFile& source) {
  frontend::Diagnostics diags(&source);
  backend::addDeriveMessages(result, diags);
  diags.print(std::cerr);
  return !diags.hasErrors();
}

// About how long writing a triangle of the mesh takes (measured on a loaded 2-core
// machine, with its vertices): the assembly keeps that much of --max-seconds for it.
double writeSecondsPerTriangle(const std::string& output) {
  std::string ext = std::filesystem::path(output).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".obj") return 0.8e-6;  // text
  if (ext == ".ply") return 0.2e-6;
  return 0.6e-6;                     // .glb: a buffer built, then written
}

// The whole command; `loader` is the caller's, so that it is destroyed (waiting for its
// background compile, within --max-seconds) before the process ends.
int run(const Args& args, backend::native::CodeLoader& loader) {
  RunOptions opt;
  try {
    opt = parseRunOptions(args);
  } catch (const UsageError& e) {
    std::cerr << "fgsg run: " << e.message << "\n";
    return 2;
  }
  if (!opt.derive.surfaceOverride.empty()) {
    // Relative to the working directory, not to the grammar's folder.
    std::error_code ec;
    const std::filesystem::path surface = std::filesystem::absolute(opt.derive.surfaceOverride, ec);
    std::string error;
    if (!rt::io::checkInputFile(opt.derive.surfaceOverride, "a mesh file", error)) {
      std::cerr << "fgsg run: --surface " << error << "\n";
      return 1;
    }
    opt.derive.surfaceOverride = surface.lexically_normal().string();
  }
  if (opt.lotsSkipped > 0 && !opt.quiet)
    std::cerr << "fgsg run: " << opt.derive.lotsName << ": " << opt.lotsSkipped
              << (opt.lotsSkipped == 1 ? " geometry that is not a polygon was" : " geometries that are not polygons were")
              << " passed over\n";
  auto compiled = compileFile(opt.file, !opt.quiet, opt.startRule);
  if (!compiled) return 1;
  if (!compiled->module.surface.present && opt.derive.surfaceOverride.empty() &&
      (opt.derive.hasStart || opt.derive.repairSurface || opt.derive.surfaceSize > 0 || !opt.derive.seeds.empty())) {
    std::cerr << "fgsg run: "
              << (opt.derive.hasStart         ? "--start"
                  : opt.derive.repairSurface  ? "--repair-surface"
                  : !opt.derive.seeds.empty() ? "--seed-points"
                                              : "--surface-size")
              << " needs a surface: " << opt.file
              << " declares none (it grows on the plane) and --surface is not given\n";
    return 2;
  }

  {
    std::string error, warning;
    if (!checkStepFlag(compiled->module, opt.file, opt.derive, error, warning)) {
      std::cerr << "fgsg run: " << error << "\n";
      return 2;
    }
    if (!warning.empty() && !opt.quiet) std::cerr << "fgsg run: warning: " << warning << "\n";
  }

  rt::AssetLibrary assets;
  for (const std::string& dir : grammarDataDirs(opt.file)) {
    assets.addSearchDir(dir);
    opt.derive.assetDirs.push_back(dir);  // data files such as synthesis examples
  }
  if (const std::string cache = rt::io::cacheFolder(); !cache.empty()) opt.derive.atlasCacheDir = cache + "/atlas";

  // The JIT's code loader lives until the command ends: on a grammar's first run its
  // compiler builds the optimised code for the cache while the output is written.
  auto t0 = std::chrono::steady_clock::now();
  // The cache's optimising compile is awaited only within --max-seconds of this start.
  loader.stopWaitingAt(t0 + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                std::chrono::duration<double>(std::min(opt.derive.maxSeconds, 1e9))));
  backend::EngineReport engineReport;
  ProgressLine progress("fgsg run", !opt.quiet);
  progress.phase("deriving");  // and compiling, building the surface and its fields
  rt::DeriveResult result = backend::derive(opt.engine, compiled->module, compiled->source.text,
                                            opt.derive, assets, &engineReport, &loader);
  progress.clear();
  const double deriveSeconds = since(t0) - engineReport.compileSeconds;
  // Print(value): a line each on stderr, as CityEngine's console shows them (also those
  // that ran before an error).
  for (const rt::PrintLine& p : result.prints)
    std::cerr << compiled->source.name << ":" << p.line << ":" << p.col << ": print: " << p.text << "\n";
  if (!reportMessages(result, compiled->source)) return 1;
  // --max-seconds bounds the assembly too: it ends 1.1 S after the derivation started
  // (the JIT's compile excluded), the tenth a limit may overshoot, but has at least 0.1 S
  // of its own, so that a derivation stopped at its limit still writes what it kept; and
  // it keeps time to write what it assembled (writeSecondsPerTriangle).
  const double assemblySeconds = std::max(1.1 * opt.derive.maxSeconds - deriveSeconds, 0.1 * opt.derive.maxSeconds);
  const rt::Deadline assemblyDeadline = rt::Deadline::after(assemblySeconds);

  t0 = std::chrono::steady_clock::now();
  std::vector<int> meshOf;
  std::string error;
  if (!rt::resolveAssets(result.instances, assets, meshOf, error)) {
    progress.clear();
    std::cerr << "fgsg run: " << error << "\n";
    return 1;
  }
  // Material(...)'s finishes (roughness, metallic, opacity, normal maps) are written by
  // the scene outputs alone: a flattened file keeps colours and images, and says so.
  if (!result.instances.finishes.empty() && !opt.output.empty() && !writesScene(opt.scene, opt.output)) {
    rt::DeriveResult dropped;
    dropped.messages.push_back({false, "R031", 0, 0,
                                "the materials' roughness, metallic, opacity and normal maps are not in the flattened " +
                                    opt.output + " (its colours and images are): a glTF scene (.glb, .gltf) or a "
                                    "grouped OBJ (--group-by symbol) has them"});
    progress.clear();
    reportMessages(dropped, compiled->source);
  }
  // CGA's uv sets 1..9 are the glTF scene's TEXCOORD_1..9 alone: an OBJ holds one set (vt)
  // and the flattened files keep set 0 too, and say so.
  rt::DeriveOptions layoutOnly;
  if (!opt.output.empty() && checkOutput(opt.scene, opt.output, layoutOnly) != OutputLayout::GltfScene &&
      std::any_of(result.instances.geometries.begin(), result.instances.geometries.end(),
                  [](const rt::Mesh& g) { return !g.uvSets.empty(); })) {
    rt::DeriveResult dropped;
    dropped.messages.push_back({false, "R033", 0, 0,
                                "the uv sets 1 to 9 are not in " + opt.output +
                                    " (it keeps uv set 0): a glTF scene (.glb, .gltf) has them as TEXCOORD_1 to 9"});
    progress.clear();
    reportMessages(dropped, compiled->source);
  }
  // CityEngine's texture layers each scene output has no place for (the glTF scene: bump
  // and dirt maps; the grouped OBJ's .mtl: dirt and occlusion maps), named once with R034.
  if (!result.instances.finishes.empty() && !opt.output.empty() && writesScene(opt.scene, opt.output)) {
    const bool gltf = checkOutput(opt.scene, opt.output, layoutOnly) == OutputLayout::GltfScene;
    static const std::pair<uint32_t, const char*> kLayerNames[] = {
        {rt::Finish::kBumpMap, "bumpmap"},         {rt::Finish::kDirtMap, "dirtmap"},
        {rt::Finish::kSpecularMap, "specularmap"}, {rt::Finish::kOpacityMap, "opacitymap"},
        {rt::Finish::kOcclusionMap, "occlusionmap"}};
    std::string dropped;
    for (const auto& [layer, word] : kLayerNames) {
      const bool kept = gltf ? layer == rt::Finish::kOcclusionMap || layer == rt::Finish::kOpacityMap ||
                                   layer == rt::Finish::kSpecularMap
                             : layer != rt::Finish::kDirtMap && layer != rt::Finish::kOcclusionMap;
      const bool used = std::any_of(result.instances.finishes.begin(), result.instances.finishes.end(),
                                    [&](const rt::Finish& f) { return f.maps[layer] != UINT32_MAX; });
      if (used && !kept) dropped += (dropped.empty() ? "" : ", ") + std::string("material.") + word;
    }
    if (!dropped.empty()) {
      rt::DeriveResult warned;
      warned.messages.push_back(
          {false, "R034", 0, 0,
           dropped + (gltf ? " not in " + opt.output +
                                 ": glTF 2.0 has no texture for bump or dirt maps (a grouped OBJ's .mtl has map_bump)"
                           : " not in " + opt.output + "'s .mtl: it has no statement for dirt or occlusion maps (a glTF "
                                                       "scene has occlusionTexture)")});
      progress.clear();
      reportMessages(warned, compiled->source);
    }
  }
  // The assembly cut short by --max-seconds keeps the first `kept` instances: said with
  // R004, and --instances, --lines, --report and the scene list only those.
  const auto keepAssembled = [&](size_t kept) {
    if (kept >= result.instances.instances.size()) return;
    rt::DeriveResult cut;
    cut.messages.push_back({false, "R004", 0, 0,
                            "assembly stopped after " + secondsText(deriveSeconds + since(t0)) +
                                " s (--max-seconds " + secondsText(opt.derive.maxSeconds) +
                                " keeps time to write what it holds): the first " + std::to_string(kept) + " of " +
                                std::to_string(result.instances.instances.size()) + " instances are written"});
    progress.clear();
    reportMessages(cut, compiled->source);
    result.instances.instances.resize(kept);
  };
  // The one flattened mesh, for a flattened -o (.obj, .ply, .glb with --instancing off
  // --group-by none), the preview and --stats (its triangles and line segments). A run
  // that writes only scenes assembles none (for a million cubes, nearly half of the
  // run): its instances are kept within --max-seconds by what they draw, as the assembly
  // would keep them (runtime/output/time_budget.h).
  const bool flattened =
      (!opt.output.empty() && !writesScene(opt.scene, opt.output)) || !opt.preview.empty() || opt.stats;
  rt::Mesh mesh;
  if (!flattened) {
    keepAssembled(rt::output::instancesWithinTime(result.instances, assets, meshOf, assemblyDeadline,
                                                  writeSecondsPerTriangle(opt.output)));
  } else {
    progress.phase("assembling");
    try {
      size_t assembled = 0;
      mesh = rt::assembleInstances(result.instances, assets, meshOf, &assemblyDeadline, &assembled,
                                   writeSecondsPerTriangle(opt.output));
      keepAssembled(assembled);
    } catch (const std::bad_alloc&) {
      rt::DeriveResult failed;
      failed.messages.push_back({true, "R020", 0, 0,
                                 "out of memory assembling " + std::to_string(result.instances.instances.size()) +
                                     " instances into one mesh; nothing was written (--max-memory stops the "
                                     "derivation earlier, keeping what fits)"});
      progress.clear();
      reportMessages(failed, compiled->source);
      return 1;
    }
  }
  const double assembleSeconds = since(t0);

  // One transaction: the mesh, the instances and the preview are all written to temps
  // first and replace their targets only when every one of them succeeded.
  progress.phase("writing");
  rt::io::OutputTransaction outputs;
  t0 = std::chrono::steady_clock::now();
  const SceneSource source{compiled->module, opt.derive, result, assets, meshOf};
  SceneDrawn drawn;  // what the scene draws, where no flattened mesh says it
  const bool staged =
      (opt.output.empty() ||
       (writesScene(opt.scene, opt.output) ? stageScene(opt.scene, source, opt.output, outputs, error, &drawn)
                                           : rt::io::stageMesh(mesh, opt.output, outputs, error))) &&
      (opt.scene.splitOutput.empty() ||
       stageSplitOutput(opt.scene, source, opt.output, outputs, error, opt.output.empty() ? &drawn : nullptr));
  if (flattened) drawn = {mesh.triangleCount(), mesh.lineCount()};
  if (!staged ||
      (!opt.instances.empty() && !rt::io::stageInstancesJson(result.instances, opt.instances, outputs, error)) ||
      (!opt.lines.empty() && !rt::io::stageLinesJson(result.instances, opt.lines, outputs, error)) ||
      (!opt.report.empty() && !rt::io::stageReportsJson(result, opt.derive.lots, opt.report, outputs, error))) {
    progress.clear();
    std::cerr << "fgsg run: " << error << "\n";
    return 1;
  }
  double writeSeconds = since(t0);

  t0 = std::chrono::steady_clock::now();
  if (!opt.preview.empty()) {
    progress.phase("drawing the preview");
    std::string warning;
    rt::render::PreviewOptions look;
    look.camera = opt.camera;
    if (!rt::render::stagePreview(mesh, look, opt.preview, outputs, error, &warning)) {
      progress.clear();
      std::cerr << "fgsg run: " << error << "\n";
      return 1;
    }
    if (!warning.empty() && !opt.quiet) {
      progress.clear();
      std::cerr << "fgsg run: warning: " << warning << "\n";
    }
  }
  const double previewSeconds = since(t0);

  progress.phase("writing");
  t0 = std::chrono::steady_clock::now();
  if (!outputs.commit(error)) {
    progress.clear();
    std::cerr << "fgsg run: " << error << "\n";
    return 1;
  }
  writeSeconds += since(t0);
  progress.done();

  if (!opt.quiet)
    std::cerr << "wrote " << (opt.output.empty() ? opt.scene.splitOutput + "/" : opt.output) << " ("
              << result.instances.instances.size()
              << " instances, " << drawn.triangles << " triangles"
              << (drawn.lines ? ", " + std::to_string(drawn.lines) + " line segments" : std::string()) << ")"
              << (opt.preview.empty() ? "" : ", preview " + opt.preview) << "\n";
  if (opt.stats) {
    const auto& s = result.stats;
    const auto& t = compiled->times;
    printDeriveStats(s, mesh.triangleCount(), mesh.lineCount());
    std::printf("time.parse %.6f\ntime.analyze %.6f\ntime.lower %.6f\ntime.compile %.6f\n"
                "time.derive %.6f\ntime.surface %.6f\ntime.rewrite %.6f\ntime.assemble %.6f\ntime.write %.6f\n"
                "time.preview %.6f\n",
                t.parseSeconds, t.analyzeSeconds, t.lowerSeconds, engineReport.compileSeconds,
                deriveSeconds, s.surfaceSeconds, s.rewriteSeconds, assembleSeconds, writeSeconds, previewSeconds);
    // Which engine ran, among the time.* lines: like timings, it varies between runs
    // of one grammar while the figures above may not.
    std::printf("time.engine %s\n", opt.engine == backend::Engine::Interpreter ? "interp"
                                     : engineReport.fromCache                  ? "jit-cached"
                                                                               : "jit");
  }
  return 0;
}

}  // namespace

int runCommand(const Args& args) {
  auto loader = std::make_unique<backend::native::CodeLoader>();
  const int code = run(args, *loader);
  loader.reset();
  if (backend::native::abandonedCompiles() > 0 || rt::abandonedWorkers() > 0) {
    // A background compile still runs LLVM, or a worker abandoned at --max-seconds still
    // runs CGAL (runtime/abandonable.h): end without destroying their static objects.
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    std::_Exit(code);
  }
  return code;
}

}  // namespace fgsg::cli
