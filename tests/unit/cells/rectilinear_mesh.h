// Test meshes for cellular texturing: the outer boundary of a union of boxes of a
// rectilinear grid (box (i, j, k) spans [xs[i], xs[i+1]] x [ys[j], ys[j+1]] x
// [zs[k], zs[k+1]]), each grid square two triangles, counter-clockwise from outside,
// vertices shared by grid index. `openBottom`: no faces looking down at z = zs[0] (a
// building standing on the ground).
#pragma once

#include "runtime/surface/surface_mesh.h"

#include <array>
#include <map>
#include <set>
#include <vector>

namespace fgsg::test {

inline rt::surface::SurfaceMesh rectilinearMesh(const std::array<std::vector<double>, 3>& coords,
                                                const std::set<std::array<int, 3>>& boxes, bool openBottom) {
  rt::surface::SurfaceMesh m;
  std::map<std::array<int, 3>, int> index;
  auto vid = [&](const std::array<int, 3>& key) {
    auto [it, fresh] = index.emplace(key, int(m.vertices.size()));
    if (fresh) m.vertices.emplace_back(coords[0][key[0]], coords[1][key[1]], coords[2][key[2]]);
    return it->second;
  };
  for (const auto& c : boxes)
    for (int axis = 0; axis < 3; ++axis)
      for (int sign : {-1, 1}) {
        auto nb = c;
        nb[axis] += sign;
        if (boxes.count(nb)) continue;
        if (openBottom && axis == 2 && sign < 0 && c[2] == 0) continue;
        int ua = (axis + 1) % 3, va = (axis + 2) % 3;
        if (sign < 0) std::swap(ua, va);
        std::array<int, 3> base = c;
        if (sign > 0) base[axis] += 1;
        auto corner = [&](int a, int b) {
          auto k = base;
          k[ua] += a;
          k[va] += b;
          return vid(k);
        };
        const int c00 = corner(0, 0), c10 = corner(1, 0), c01 = corner(0, 1), c11 = corner(1, 1);
        m.faces.push_back({c00, c10, c11});
        m.faces.push_back({c00, c11, c01});
      }
  m.buildTopology();
  return m;
}

// A 1.5 x 1.5 plinth 0.45 high under a 0.9 x 0.9 column up to 3.0 (the paper's stepped
// square column), standing on the ground.
inline rt::surface::SurfaceMesh steppedColumn() {
  std::set<std::array<int, 3>> boxes;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) boxes.insert({i, j, 0});
  boxes.insert({1, 1, 1});
  return rectilinearMesh({{{0, 0.3, 1.2, 1.5}, {0, 0.3, 1.2, 1.5}, {0, 0.45, 3.0}}}, boxes, true);
}

}  // namespace fgsg::test
