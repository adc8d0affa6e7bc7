// A scene's nodes as the glTF writer lays them out (runtime/output/gltf_writer.h), for
// Python and the C API: per start shape its node, under it a node per group (none under
// GroupBy::None: the group's contents are the start node's), under a group a node per
// instanced part (its instances placed by EXT_mesh_gpu_instancing) or, with
// Instancing::Nodes and for mirrored instances, a node per instance. Listed in pre-order
// (a node before its children; start shapes in order).
#pragma once

#include "runtime/output/scene.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace fgsg::rt::output {

struct SceneNodeInfo {
  std::string name;
  int64_t parent = -1;  // index in the list; -1 for a start shape's node
  // Column-major, relative to the parent: the identity but for a node per instance.
  std::array<double, 16> transform{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  std::string extras;  // the glTF node's extras as JSON text (start_extras.h for a start shape)
  size_t meshes = 0;     // what the node draws itself: baked parts, or the one shared mesh
  size_t instances = 0;  // instances drawn by the node and its descendants
};

std::vector<SceneNodeInfo> sceneNodes(const Scene& scene);

// The list as a JSON array of {"name", "parent", "transform" (16 numbers), "extras" (the
// object), "meshes", "instances"}.
std::string sceneNodesJson(const std::vector<SceneNodeInfo>& nodes);

}  // namespace fgsg::rt::output
