// A derived model as fgsg view sends it: instances placed rigidly (an asset mapped by
// its 4x4 transform) grouped by asset, so that the page draws each group as one
// three.js InstancedMesh and a result of a million instances stays interactive; and
// everything else (bent terminals, CGA shapes' own geometry, textured instances, lines)
// assembled into one mesh as fgsg run writes it.
#pragma once

#include "runtime/assets.h"
#include "runtime/instances.h"

#include <cstdint>
#include <string>
#include <vector>

namespace fgsg::cli {

struct InstanceGroup {
  std::string asset;            // its name, as written in the grammar
  std::string meshGlb;          // the asset's mesh in its unit box, as .glb
  std::vector<float> matrices;  // 16 per instance, column-major (three.js Matrix4 order)
  std::vector<float> colours;   // r g b per instance
  std::vector<uint32_t> ids;    // each instance's index in the derivation's InstanceList
};

struct ViewScene {
  std::string restGlb;  // the assembled rest (may hold no triangles)
  std::vector<InstanceGroup> groups;
  size_t triangles = 0;  // of the whole model, as fgsg run would write it
};

// Builds the scene of `list` (its assets resolved: meshOf from resolveAssets). False with
// a message when a mesh cannot be encoded.
bool buildViewScene(const rt::InstanceList& list, const rt::AssetLibrary& assets, const std::vector<int>& meshOf,
                    ViewScene& out, std::string& error);

}  // namespace fgsg::cli
