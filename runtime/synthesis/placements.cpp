#include "runtime/synthesis/placements.h"

#include <cmath>

namespace fgsg::rt::synthesis {

namespace {
using M4 = std::array<double, 16>;  // column-major

M4 mul(const M4& a, const M4& b) {
  M4 r{};
  for (int c = 0; c < 4; ++c)
    for (int rr = 0; rr < 4; ++rr) {
      double s = 0;
      for (int i = 0; i < 4; ++i) s += a[size_t(i * 4 + rr)] * b[size_t(c * 4 + i)];
      r[size_t(c * 4 + rr)] = s;
    }
  return r;
}
M4 identity() { M4 m{}; m[0] = m[5] = m[10] = m[15] = 1; return m; }
M4 translate(double x, double y, double z) { M4 m = identity(); m[12] = x; m[13] = y; m[14] = z; return m; }
M4 scale(double x, double y, double z) { M4 m{}; m[0] = x; m[5] = y; m[10] = z; m[15] = 1; return m; }

// Assets are y-up (glTF, OBJ, and CGA's I in a scope whose y is up), the grid is z-up: an
// asset stands in its cell with its y along the grid's z, so a `cylinder` (a tower, a
// trunk) stands on its cap. The unit box's (x, y, z) goes to (x, 1 - z, y): in the y-up
// world (PlacementFrame::yUp) the asset keeps its own axes. The flat built-ins `quad` and
// `disc` (in their xy plane, facing +z) are floor tiles: they keep lying on the cell's
// floor, facing up.
M4 upright(const std::string& asset) {
  if (asset == "quad" || asset == "disc") return identity();
  return M4{1, 0, 0, 0,  0, 0, 1, 0,  0, -1, 0, 0,  0, 1, 0, 1};
}
}  // namespace

std::vector<PiecePlacement> piecePlacements(const LabelGrid& labels, const Example& ex,
                                            const PlacementFrame& frame) {
  std::vector<PiecePlacement> out;
  // Grid -> world axes: yUp maps grid (x, y, z) to world (x, z, -y), a proper rotation.
  M4 toWorld = identity();
  if (frame.yUp) {
    toWorld = M4{1, 0, 0, 0,  0, 0, -1, 0,  0, 1, 0, 0,  0, 0, 0, 1};
  }
  const auto& cs = frame.cellSize;
  for (int64_t i = 0; i < labels.cellCount(); ++i) {
    const int32_t l = labels[i];
    if (l < 0 || l >= ex.labelCount()) continue;
    const Piece& p = ex.labels[size_t(l)];
    if (p.asset.empty()) continue;
    PiecePlacement pl;
    pl.cell = i;
    pl.at = labels.cell(i);
    pl.label = l;
    pl.asset = p.asset;
    pl.rotation = p.rotation;
    pl.mirrored = p.mirrored;
    if (p.hasColor) pl.color = p.color;
    // In grid space: unit box -> centred, mirrored, turned about z, back, scaled, moved.
    const double c = std::cos(p.rotation * M_PI / 2), s = std::sin(p.rotation * M_PI / 2);
    M4 rot = identity();
    rot[0] = std::round(c); rot[1] = std::round(s); rot[4] = -std::round(s); rot[5] = std::round(c);
    M4 local = mul(rot, mul(scale(p.mirrored ? -1 : 1, 1, 1), mul(translate(-0.5, -0.5, 0), upright(p.asset))));
    local = mul(translate(0.5, 0.5, 0), local);
    const double ox = pl.at.x * cs[0], oy = pl.at.y * cs[1], oz = pl.at.z * cs[2];
    M4 grid = mul(translate(ox, oy, oz), mul(scale(cs[0], cs[1], cs[2]), local));
    M4 world = mul(translate(frame.origin[0], frame.origin[1], frame.origin[2]), mul(toWorld, grid));
    pl.transform = world;
    // World box of the cell.
    double lo[3], hi[3];
    for (int a = 0; a < 3; ++a) { lo[a] = 1e300; hi[a] = -1e300; }
    for (int corner = 0; corner < 8; ++corner) {
      const double gp[4] = {ox + ((corner & 1) ? cs[0] : 0), oy + ((corner & 2) ? cs[1] : 0), oz + ((corner & 4) ? cs[2] : 0), 1};
      for (int a = 0; a < 3; ++a) {
        double v = frame.origin[size_t(a)];
        for (int j = 0; j < 4; ++j) v += toWorld[size_t(j * 4 + a)] * gp[j] * (j < 3 ? 1 : 0);
        lo[a] = std::min(lo[a], v);
        hi[a] = std::max(hi[a], v);
      }
    }
    for (int a = 0; a < 3; ++a) { pl.boxMin[size_t(a)] = lo[a]; pl.boxMax[size_t(a)] = hi[a]; }
    out.push_back(std::move(pl));
  }
  return out;
}

void appendInstances(const std::vector<PiecePlacement>& placements, const std::string& symbol,
                     InstanceList& out) {
  auto intern = [](std::vector<std::string>& v, const std::string& s) {
    for (size_t i = 0; i < v.size(); ++i)
      if (v[i] == s) return uint32_t(i);
    v.push_back(s);
    return uint32_t(v.size() - 1);
  };
  const uint32_t sym = intern(out.symbols, symbol);
  for (const auto& p : placements) {
    Instance inst;
    inst.asset = intern(out.assets, p.asset);
    inst.symbol = sym;
    inst.transform = p.transform;
    inst.color = p.color;
    inst.firstParam = uint32_t(out.params.size());
    inst.paramCount = 0;
    out.instances.push_back(inst);
  }
}

}  // namespace fgsg::rt::synthesis
