#include "cli/view_scene.h"

#include "runtime/assemble.h"
#include "runtime/io/write_mesh.h"

#include <Eigen/Dense>

#include <algorithm>
#include <map>

namespace fgsg::cli {

namespace {

// Rigid: drawn as its asset's mesh under its transform, nothing more. The others need
// the assembler (bent along a curve, own geometry, a texture).
bool rigid(const rt::Instance& inst) {
  return inst.curve == UINT32_MAX && inst.geometry == UINT32_MAX && inst.texture == UINT32_MAX;
}

// A flattened axis (a quad's zero thickness) would make the shader's normal transform
// divide by zero: it becomes a sliver along the normal of the other two instead.
void packMatrix(const std::array<double, 16>& t, float* out) {
  Eigen::Matrix4d m = Eigen::Map<const Eigen::Matrix4d>(t.data());
  Eigen::Matrix3d a = m.block<3, 3>(0, 0);
  const double largest = std::max({a.col(0).norm(), a.col(1).norm(), a.col(2).norm()});
  if (largest > 0)
    for (int k = 0; k < 3; ++k) {
      if (a.col(k).norm() > 1e-6 * largest) continue;
      const Eigen::Vector3d n = a.col((k + 1) % 3).cross(a.col((k + 2) % 3));
      const double len = n.norm();
      a.col(k) = len > 0 ? Eigen::Vector3d(n / len * 1e-4 * largest) : Eigen::Vector3d::Zero();
    }
  m.block<3, 3>(0, 0) = a;
  for (int i = 0; i < 16; ++i) out[i] = static_cast<float>(m.data()[i]);
}

}  // namespace

bool buildViewScene(const rt::InstanceList& list, const rt::AssetLibrary& assets, const std::vector<int>& meshOf,
                    ViewScene& out, std::string& error) {
  out = ViewScene{};
  rt::InstanceList rest = list;
  rest.instances.clear();
  std::map<uint32_t, size_t> groupOf;  // asset -> index in out.groups
  for (size_t i = 0; i < list.instances.size(); ++i) {
    const rt::Instance& inst = list.instances[i];
    if (!rigid(inst)) {
      rest.instances.push_back(inst);
      continue;
    }
    auto [it, fresh] = groupOf.try_emplace(inst.asset, out.groups.size());
    if (fresh) {
      InstanceGroup g;
      g.asset = list.assets[inst.asset];
      if (!rt::io::encodeMesh(assets.mesh(meshOf[inst.asset]), ".glb", g.meshGlb, error)) return false;
      out.groups.push_back(std::move(g));
    }
    InstanceGroup& g = out.groups[it->second];
    g.matrices.resize(g.matrices.size() + 16);
    packMatrix(inst.transform, g.matrices.data() + g.matrices.size() - 16);
    g.colours.insert(g.colours.end(), inst.color.begin(), inst.color.end());
    g.ids.push_back(static_cast<uint32_t>(i));
    out.triangles += assets.mesh(meshOf[inst.asset]).triangleCount();
  }
  const rt::Mesh mesh = rt::assembleInstances(rest, assets, meshOf);
  out.triangles += mesh.triangleCount();
  return rt::io::encodeMesh(mesh, ".glb", out.restGlb, error);
}

}  // namespace fgsg::cli
