// A derived model as fgsg view sends it: the glTF scene `fgsg run -o FILE.glb` writes by
// default (runtime/output/: a node per start shape, grouped by symbol, PBR materials;
// --instancing auto: rigid repeats that make the file smaller as one
// EXT_mesh_gpu_instancing node per shared mesh, which three.js's GLTFLoader draws as an
// InstancedMesh, so that a result of a million instances stays interactive, the rest
// baked into a mesh per group and material, so that a city's facade pieces repeated twice
// are not 20 000 draw calls), and beside it what picking needs: which instances each
// placing node holds.
#pragma once

#include "ir/ir.h"
#include "runtime/assets.h"
#include "runtime/derivation.h"
#include "runtime/output/scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace fgsg::cli {

struct ViewScene {
  std::string glb;  // the scene as .glb
  // Per node that places shared meshes (an instanced node, a mirrored instance's node):
  // its index in the file's nodes and how many instances it places; `ids` holds their
  // numbers in the derivation's InstanceList, node after node.
  std::vector<std::pair<int, uint32_t>> placing;
  std::vector<uint32_t> ids;
  size_t triangles = 0;  // of the whole model, as fgsg run would write it
};

// Builds the scene of `result` (its assets resolved: meshOf from resolveAssets; `options`
// the derivation's, for the start shapes' names and attrs). False with a message when a
// vertex is not finite or an image cannot be embedded.
bool buildViewScene(const ir::Module& module, const rt::DeriveOptions& options, const rt::DeriveResult& result,
                    const rt::AssetLibrary& assets, const std::vector<int>& meshOf, ViewScene& out, std::string& error);
// The same for an instance list whose start shapes `starts` names (view_pieces.h: one seed's).
bool buildViewSceneOf(const rt::InstanceList& list, std::vector<rt::output::StartInfo> starts,
                      const rt::AssetLibrary& assets, const std::vector<int>& meshOf, ViewScene& out,
                      std::string& error);

}  // namespace fgsg::cli
