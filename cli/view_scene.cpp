#include "cli/view_scene.h"

#include "backend/scene_starts.h"
#include "runtime/output/gltf_writer.h"
#include "runtime/output/scene.h"

namespace fgsg::cli {

bool buildViewScene(const ir::Module& module, const rt::DeriveOptions& options, const rt::DeriveResult& result,
                    const rt::AssetLibrary& assets, const std::vector<int>& meshOf, ViewScene& out, std::string& error) {
  return buildViewSceneOf(result.instances, backend::sceneStarts(module, options, result), assets, meshOf, out, error);
}

bool buildViewSceneOf(const rt::InstanceList& list, std::vector<rt::output::StartInfo> starts,
                      const rt::AssetLibrary& assets, const std::vector<int>& meshOf, ViewScene& out,
                      std::string& error) {
  out = ViewScene{};
  rt::output::SceneInput in;
  in.list = &list;
  in.library = &assets;
  in.meshOf = &meshOf;
  in.groupBy = rt::output::GroupBy::Symbol;
  in.instancing = rt::output::Instancing::Auto;
  in.starts = std::move(starts);
  const rt::output::Scene scene = rt::output::buildScene(in);
  for (const rt::output::StartNode& s : scene.starts)
    for (const rt::output::GroupNode& g : s.groups) {
      for (const rt::output::BakedPart& p : g.baked) out.triangles += p.mesh.triangleCount();
      for (const auto* parts : {&g.instanced, &g.mirrored})
        for (const rt::output::InstancedPart& p : *parts)
          out.triangles += scene.meshes[p.mesh].mesh->triangleCount() * p.instances.size();
    }
  std::vector<rt::output::PlacedNode> placed;
  if (!rt::output::encodeGltf(scene, true, out.glb, error, &placed)) return false;
  for (const rt::output::PlacedNode& p : placed) {
    out.placing.emplace_back(p.node, static_cast<uint32_t>(p.count));
    out.ids.insert(out.ids.end(), p.instances, p.instances + p.count);
  }
  return true;
}

}  // namespace fgsg::cli
