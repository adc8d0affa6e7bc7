#include "runtime/cga/asset_geometry.h"

#include <map>
#include <numeric>
#include <utility>

namespace fgsg::rt::cga {

namespace {

uint32_t assetGeometryRoot(std::vector<uint32_t>& parent, uint32_t t) {
  while (parent[t] != t) t = parent[t] = parent[parent[t]];
  return t;
}

}  // namespace

LocalGeometry assetGeometry(const Mesh& asset, bool zUp) {
  LocalGeometry g;
  g.kind = GeomKind::Polyhedron;
  // Corners welded where they are the same point (a mesh splits them for normals, uvs).
  std::vector<Vec3> points;
  std::vector<uint32_t> corner(asset.vertexCount());
  std::map<std::array<double, 3>, uint32_t> idOf;
  for (size_t v = 0; v < asset.vertexCount(); ++v) {
    const Vec3 p(asset.positions[3 * v], asset.positions[3 * v + 1], asset.positions[3 * v + 2]);
    const Vec3 u = zUp ? Vec3(p.x(), p.z(), 1.0 - p.y()) : p;
    const auto [it, added] = idOf.emplace(std::array<double, 3>{u.x(), u.y(), u.z()}, uint32_t(points.size()));
    if (added) points.push_back(u);
    corner[v] = it->second;
  }
  struct Triangle {
    std::array<uint32_t, 3> c;
    Vec3 normal;
  };
  std::vector<Triangle> tris;
  for (size_t t = 0; t < asset.triangleCount(); ++t) {
    const std::array<uint32_t, 3> c = {corner[asset.indices[3 * t]], corner[asset.indices[3 * t + 1]],
                                       corner[asset.indices[3 * t + 2]]};
    const Vec3 n = (points[c[1]] - points[c[0]]).cross(points[c[2]] - points[c[0]]);
    if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2] || !(n.norm() > 1e-15)) continue;
    tris.push_back({c, n.normalized()});
  }
  // Neighbours in one plane join.
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> edgeOf;  // directed edge -> its triangle
  for (size_t t = 0; t < tris.size(); ++t)
    for (int k = 0; k < 3; ++k) edgeOf.emplace(std::make_pair(tris[t].c[k], tris[t].c[(k + 1) % 3]), uint32_t(t));
  std::vector<uint32_t> parent(tris.size());
  std::iota(parent.begin(), parent.end(), 0u);
  for (size_t t = 0; t < tris.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const auto other = edgeOf.find({tris[t].c[(k + 1) % 3], tris[t].c[k]});
      if (other == edgeOf.end() || tris[other->second].normal.dot(tris[t].normal) < 1.0 - 1e-9) continue;
      parent[assetGeometryRoot(parent, uint32_t(t))] = assetGeometryRoot(parent, other->second);
    }
  std::map<uint32_t, std::vector<uint32_t>> groups;  // by root; faces ordered by first triangle below
  std::vector<uint32_t> order;
  for (size_t t = 0; t < tris.size(); ++t) {
    std::vector<uint32_t>& members = groups[assetGeometryRoot(parent, uint32_t(t))];
    if (members.empty()) order.push_back(assetGeometryRoot(parent, uint32_t(t)));
    members.push_back(uint32_t(t));
  }
  auto triangleFaces = [&](const std::vector<uint32_t>& members) {
    for (uint32_t t : members) g.faces.push_back({points[tris[t].c[0]], points[tris[t].c[1]], points[tris[t].c[2]]});
  };
  for (uint32_t root : order) {
    const std::vector<uint32_t>& members = groups[root];
    if (members.size() == 1) {
      triangleFaces(members);
      continue;
    }
    // The outline: the members' edges no other member walks back, chained into one loop.
    std::map<std::pair<uint32_t, uint32_t>, int> inGroup;
    for (uint32_t t : members)
      for (int k = 0; k < 3; ++k) ++inGroup[{tris[t].c[k], tris[t].c[(k + 1) % 3]}];
    std::map<uint32_t, uint32_t> next;
    bool simple = true;
    size_t boundary = 0;
    for (const auto& [edge, uses] : inGroup) {
      if (inGroup.count({edge.second, edge.first})) continue;
      ++boundary;
      simple = simple && uses == 1 && next.emplace(edge.first, edge.second).second;
    }
    Polygon3 loop;
    if (simple && boundary >= 3) {
      const uint32_t first = next.begin()->first;
      uint32_t at = first;
      do {
        loop.push_back(points[at]);
        const auto step = next.find(at);
        if (step == next.end()) break;
        at = step->second;
      } while (at != first && loop.size() <= boundary);
      simple = at == first && loop.size() == boundary;
    }
    if (!simple) {
      triangleFaces(members);
      continue;
    }
    g.faces.push_back(std::move(loop));
  }
  return g;
}

}  // namespace fgsg::rt::cga
