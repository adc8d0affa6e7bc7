#include "cli/scene_output.h"

#include "cli/options.h"
#include "backend/scene_starts.h"
#include "runtime/io/write_instances.h"
#include "runtime/io/write_mesh.h"
#include "runtime/output/gltf_writer.h"
#include "runtime/output/obj_scene_writer.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <set>

namespace fgsg::cli {

namespace {

// The group of each rule: its label for --group-by rule; for --group-by label the label
// the grammar gave it, or its predecessor for an unlabelled rule (`Pred#n`), so that
// the rules of one symbol without labels are one group.
std::vector<std::string> ruleGroups(const ir::Module& m, rt::output::GroupBy by) {
  std::vector<std::string> names;
  for (const ir::Rule& r : m.rules) {
    std::string name = r.label;
    if (by == rt::output::GroupBy::Label && r.symbol < m.symbols.size()) {
      const std::string& pred = m.symbols[r.symbol].name;
      const bool numbered = name.size() > pred.size() + 1 && name.compare(0, pred.size() + 1, pred + "#") == 0 &&
                            name.find_first_not_of("0123456789", pred.size() + 1) == std::string::npos;
      if (numbered) name = pred;
    }
    names.push_back(std::move(name));
  }
  return names;
}

// The scene of the run as `layout` lays it out (OBJ: no instances).
rt::output::Scene buildScene(const SceneFlags& flags, const SceneSource& run, OutputLayout layout) {
  const rt::DeriveResult& result = run.result;
  rt::output::SceneInput in;
  in.list = &result.instances;
  in.library = &run.assets;
  in.meshOf = &run.meshOf;
  in.groupBy = flags.groupBy;
  in.instancing = layout == OutputLayout::ObjScene ? rt::output::Instancing::Off : flags.instancing;
  if (layout == OutputLayout::Flattened)  // a flattened -o split into files: each start alone, flattened
    in.groupBy = rt::output::GroupBy::None, in.instancing = rt::output::Instancing::Off;
  if (in.groupBy == rt::output::GroupBy::Rule || in.groupBy == rt::output::GroupBy::Label)
    in.ruleGroups = ruleGroups(run.module, in.groupBy);
  in.starts = backend::sceneStarts(run.module, run.derive, result);
  return rt::output::buildScene(in);
}

// Calls f on every asset name the scene's glTF file writes.
template <class F>
void forEachAssetName(rt::output::Scene& scene, F f) {
  for (rt::output::SharedMesh& mesh : scene.meshes) f(mesh.asset);
  for (rt::output::StartNode& start : scene.starts)
    for (rt::output::GroupNode& g : start.groups)
      for (auto& counted : g.bakedAssets) f(counted.first);
}

bool stageAs(rt::output::Scene& scene, OutputLayout layout, const std::string& path,
             rt::io::OutputTransaction& outputs, std::string& error, const rt::output::GltfEncoding& encoding) {
  if (layout == OutputLayout::ObjScene) {
    if (rt::output::stageObjScene(scene, path, outputs, error)) return true;
    error = path + ": " + error;
    return false;
  }
  // The file names an asset found by path (extras.asset, a group's extras.baked) relative
  // to its folder, as --instances does (io::assetNameFrom), so that the folder moves with
  // its assets; the scene keeps the absolute path for the runtime (the next file of
  // --split-output). Stdout: a path without a folder, as it is.
  std::vector<std::string> found;
  if (!path.empty()) {
    std::error_code ec;
    const std::string folder = std::filesystem::absolute(path, ec).parent_path().string();
    forEachAssetName(scene, [&](std::string& name) {
      found.push_back(name);
      name = rt::io::assetNameFrom(name, folder);
    });
  }
  const bool staged = rt::output::stageGltf(scene, path, outputs, error, encoding);
  size_t k = 0;
  if (!found.empty()) forEachAssetName(scene, [&](std::string& name) { name = std::move(found[k++]); });
  return staged;
}

// What `scene` draws (SceneDrawn): baked parts as assembled, instanced and mirrored
// parts their shared mesh once per instance (shared meshes have no line segments).
SceneDrawn sceneDrawnCounts(const rt::output::Scene& scene) {
  SceneDrawn drawn;
  for (const rt::output::StartNode& start : scene.starts)
    for (const rt::output::GroupNode& g : start.groups) {
      for (const rt::output::BakedPart& p : g.baked)
        drawn.triangles += p.mesh.triangleCount(), drawn.lines += p.mesh.lineCount();
      for (const auto* parts : {&g.instanced, &g.mirrored})
        for (const rt::output::InstancedPart& p : *parts)
          drawn.triangles += scene.meshes[p.mesh].mesh->triangleCount() * p.trs.size();
    }
  return drawn;
}

// A start shape's name as a file name.
std::string fileStem(const std::string& name) {
  std::string stem;
  for (char c : name) stem += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.' ? c : '_';
  if (stem.empty() || stem[0] == '.') stem = "start" + stem;
  return stem;
}

}  // namespace

OutputLayout checkOutput(const SceneFlags& flags, const std::string& path, rt::DeriveOptions& derive) {
  using rt::output::GroupBy;
  using rt::output::Instancing;
  OutputLayout layout = OutputLayout::Flattened;
  const std::string ext = lowerExtension(path);
  const auto& known = rt::io::supportedMeshExtensions();
  if (path.empty()) {
    layout = OutputLayout::GltfScene;
  } else if (ext == ".gltf" || (ext == ".glb" && (flags.instancing != Instancing::Off || flags.groupBy != GroupBy::None))) {
    layout = OutputLayout::GltfScene;
  } else if (ext == ".obj") {
    if (flags.instancingGiven && flags.instancing != Instancing::Off)
      throw UsageError{"-o " + path + ": OBJ has no instances; --instancing lays out a glTF scene (name it .glb or .gltf)"};
    if (flags.groupByGiven && flags.groupBy != GroupBy::None) layout = OutputLayout::ObjScene;
  } else if (ext == ".ply") {
    if ((flags.instancingGiven && flags.instancing != Instancing::Off) ||
        (flags.groupByGiven && flags.groupBy != GroupBy::None) || !flags.splitOutput.empty())
      throw UsageError{"-o " + path + ": PLY is one flattened mesh; --instancing, --group-by and --split-output lay out a glTF scene (.glb, .gltf) or a grouped OBJ"};
  } else if (std::find(known.begin(), known.end(), ext) == known.end()) {
    std::string list;
    for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
    throw UsageError{"-o " + path + ": unknown output format (use " + list + " or .gltf)"};
  }
  // --quantize encodes the glTF scene writer's files: not the flattened .glb of before.
  const bool gltfFiles = path.empty() || ext == ".gltf" || ext == ".glb";
  if (flags.quantize && (!gltfFiles || (layout == OutputLayout::Flattened && flags.splitOutput.empty())))
    throw UsageError{"--quantize encodes a glTF scene (-o FILE.glb or .gltf); `--instancing off --group-by none` "
                     "is the flattened mesh of before, which it leaves as it is"};
  // Rule and label groups need to know which rule placed each instance.
  if ((layout != OutputLayout::Flattened || !flags.splitOutput.empty()) &&
      (flags.groupBy == GroupBy::Rule || flags.groupBy == GroupBy::Label))
    derive.recordOrigins = true;
  return layout;
}

bool writesScene(const SceneFlags& flags, const std::string& path) {
  rt::DeriveOptions unused;
  return !path.empty() && checkOutput(flags, path, unused) != OutputLayout::Flattened;
}

bool stageScene(const SceneFlags& flags, const SceneSource& run, const std::string& path,
                rt::io::OutputTransaction& outputs, std::string& error, SceneDrawn* drawn) {
  rt::DeriveOptions unused;
  const OutputLayout layout = checkOutput(flags, path, unused);
  rt::output::Scene scene = buildScene(flags, run, layout);
  if (drawn) *drawn = sceneDrawnCounts(scene);
  return stageAs(scene, layout, path, outputs, error, {flags.quantize});
}

bool stageSplitOutput(const SceneFlags& flags, const SceneSource& run, const std::string& path,
                      rt::io::OutputTransaction& outputs, std::string& error, SceneDrawn* drawn) {
  namespace fs = std::filesystem;
  rt::DeriveOptions unused;
  OutputLayout layout = checkOutput(flags, path, unused);
  std::string ext = path.empty() ? ".glb" : fs::path(path).extension().string();
  SceneFlags split = flags;
  if (lowerExtension(path) == ".obj") {
    layout = OutputLayout::ObjScene;
    if (!flags.groupByGiven) split.groupBy = rt::output::GroupBy::None;  // as the flattened OBJ: no g lines
  }
  const fs::path dir(flags.splitOutput);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) return error = "--split-output " + flags.splitOutput + ": " + ec.message(), false;
  rt::output::Scene scene = buildScene(split, run, layout);
  if (drawn) *drawn = sceneDrawnCounts(scene);
  // Each start shape alone in a scene sharing the whole one's meshes and materials (the
  // writers take only what it uses).
  rt::output::Scene one;
  one.meshes = scene.meshes;
  one.materials = scene.materials;
  one.images = scene.images;
  one.groupBy = scene.groupBy;
  nlohmann::json files = nlohmann::json::array();
  std::set<std::string> taken = {"manifest"};
  for (rt::output::StartNode& start : scene.starts) {
    std::string stem = fileStem(start.info.name);
    if (!taken.insert(stem).second) taken.insert(stem += "_" + std::to_string(start.index));
    const std::string name = stem + ext;
    const rt::output::StartSummary sum = rt::output::summarizeStart(scene, start);
    nlohmann::json entry = {{"file", name},
                            {"start", start.index},
                            {"name", start.info.name},
                            {"instances", start.instanceCount},
                            {"triangles", sum.triangles}};
    if (sum.lo[0] <= sum.hi[0])
      entry["bounds"] = {{"min", sum.lo}, {"max", sum.hi}};
    else
      entry["bounds"] = nullptr;
    files.push_back(std::move(entry));
    one.starts.assign(1, std::move(start));
    const bool staged = stageAs(one, layout, (dir / name).string(), outputs, error, {flags.quantize});
    start = std::move(one.starts.front());
    if (!staged) return false;
  }
  const nlohmann::json manifest = {{"format", "fgsg-split-output"}, {"version", 1}, {"files", std::move(files)}};
  return outputs.stage((dir / "manifest.json").string(), manifest.dump(1) + "\n", error);
}

}  // namespace fgsg::cli
