#include "runtime/synthesis/site_graph.h"

namespace fgsg::rt::synthesis {

SiteGraph makeGridGraph(GridSize size, std::array<bool, 3> periodic) {
  SiteGraph g;
  g.siteCount = size.count();
  g.slots = size.nz > 1 ? 6 : 4;
  const int n[3] = {size.nx, size.ny, size.nz};
  const int64_t stride[3] = {1, int64_t(size.nx), int64_t(size.nx) * size.ny};
  for (int d = 0; d < 6; ++d) {
    const int axis = d / 2;
    const int64_t sign = d % 2 == 0 ? 1 : -1;
    g.step[size_t(d)] = int32_t(sign * stride[axis]);
    // A periodic axis of extent 1 would make a cell its own neighbour: no wrap.
    if (periodic[size_t(axis)] && n[axis] >= 2) g.wrap[size_t(d)] = int32_t(-sign * (n[axis] - 1) * stride[axis]);
  }
  g.face.resize(size_t(g.siteCount));
  uint8_t* f = g.face.data();
  for (int z = 0; z < size.nz; ++z)
    for (int y = 0; y < size.ny; ++y) {
      const uint8_t yz = uint8_t((y == size.ny - 1 ? 4 : 0) | (y == 0 ? 8 : 0) | (z == size.nz - 1 ? 16 : 0) |
                                 (z == 0 ? 32 : 0));
      for (int x = 0; x < size.nx; ++x)
        *f++ = uint8_t(yz | (x == size.nx - 1 ? 1 : 0) | (x == 0 ? 2 : 0));
    }
  return g;
}

void setLinks(SiteGraph& g, const std::vector<Link>& links, const std::vector<int>& reverseOf) {
  g.linkStart.assign(size_t(g.siteCount) + 1, 0);
  for (const auto& l : links) {
    ++g.linkStart[size_t(l.from) + 1];
    ++g.linkStart[size_t(l.to) + 1];
  }
  for (size_t i = 1; i < g.linkStart.size(); ++i) g.linkStart[i] += g.linkStart[i - 1];
  g.linkSite.assign(g.linkStart.back(), 0);
  g.linkRelation.assign(g.linkStart.back(), 0);
  std::vector<uint32_t> fill(g.linkStart.begin(), g.linkStart.end() - 1);
  for (const auto& l : links) {
    g.linkSite[fill[size_t(l.from)]] = l.to;
    g.linkRelation[fill[size_t(l.from)]++] = uint16_t(l.relation);
    g.linkSite[fill[size_t(l.to)]] = l.from;
    g.linkRelation[fill[size_t(l.to)]++] = uint16_t(reverseOf[size_t(l.relation)]);
  }
}

}  // namespace fgsg::rt::synthesis
