#include "runtime/output/scene_nodes.h"

#include "runtime/output/start_extras.h"

#include <nlohmann/json.hpp>

namespace fgsg::rt::output {

namespace {

using nlohmann::json;

struct Lister {
  const Scene& scene;
  std::vector<SceneNodeInfo> nodes;

  int64_t add(SceneNodeInfo node) {
    nodes.push_back(std::move(node));
    return int64_t(nodes.size() - 1);
  }

  void instanceNodes(const InstancedPart& p, int64_t parent) {
    for (size_t k = 0; k < p.trs.size(); ++k) {
      SceneNodeInfo n;
      n.name = scene.meshes[p.mesh].name;
      n.parent = parent;
      n.transform = composeTrs(p.trs[k]);
      n.extras = json{{"asset", scene.meshes[p.mesh].asset}}.dump();
      n.meshes = 1;
      n.instances = 1;
      add(std::move(n));
    }
  }

  // The group's contents under `at` (its own node, or the start's under GroupBy::None),
  // whose extras get the baked assets' counts as the writer gives them.
  void contents(const GroupNode& g, int64_t at, json extras) {
    nodes[size_t(at)].meshes = g.baked.size();
    nodes[size_t(at)].instances = g.instanceCount;
    if (!g.bakedAssets.empty()) {
      json counts = json::object();
      for (const auto& [asset, count] : g.bakedAssets) counts[asset] = count;
      extras["baked"] = std::move(counts);
    }
    nodes[size_t(at)].extras = extras.dump();
    for (const InstancedPart& p : g.instanced) {
      if (scene.instancing == Instancing::Nodes) {
        instanceNodes(p, at);
        continue;
      }
      SceneNodeInfo n;
      n.name = scene.meshes[p.mesh].name;
      n.parent = at;
      n.extras = json{{"asset", scene.meshes[p.mesh].asset}, {"instances", p.instances.size()}}.dump();
      n.meshes = 1;
      n.instances = p.instances.size();
      add(std::move(n));
    }
    for (const InstancedPart& p : g.mirrored) instanceNodes(p, at);
  }

  void start(const StartNode& s) {
    SceneNodeInfo node;
    node.name = s.info.name;
    node.instances = s.instanceCount;
    const int64_t at = add(std::move(node));
    json extras = startExtras(s);
    if (scene.groupBy == GroupBy::None) {
      if (s.groups.empty())
        nodes[size_t(at)].extras = extras.dump();
      else
        contents(s.groups.front(), at, std::move(extras));
      return;
    }
    nodes[size_t(at)].extras = extras.dump();
    for (const GroupNode& g : s.groups) {
      SceneNodeInfo group;
      group.name = g.name;
      group.parent = at;
      const int64_t gat = add(std::move(group));
      contents(g, gat, json{{"instances", g.instanceCount}});
    }
  }
};

}  // namespace

std::vector<SceneNodeInfo> sceneNodes(const Scene& scene) {
  Lister l{scene, {}};
  for (const StartNode& s : scene.starts) l.start(s);
  return std::move(l.nodes);
}

std::string sceneNodesJson(const std::vector<SceneNodeInfo>& nodes) {
  json out = json::array();
  for (const SceneNodeInfo& n : nodes)
    out.push_back({{"name", n.name},
                   {"parent", n.parent},
                   {"transform", n.transform},
                   {"extras", json::parse(n.extras)},
                   {"meshes", n.meshes},
                   {"instances", n.instances}});
  return out.dump();
}

}  // namespace fgsg::rt::output
