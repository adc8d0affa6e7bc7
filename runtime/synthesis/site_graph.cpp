#include "runtime/synthesis/site_graph.h"

namespace fgsg::rt::synthesis {

SiteGraph makeGridGraph(GridSize size, std::array<bool, 3> periodic) {
  SiteGraph g;
  g.siteCount = size.count();
  g.slots = size.nz > 1 ? 6 : 4;
  g.neighbor.assign(size_t(g.siteCount) * size_t(g.slots), -1);
  const int n[3] = {size.nx, size.ny, size.nz};
  int64_t i = 0;
  for (int z = 0; z < size.nz; ++z)
    for (int y = 0; y < size.ny; ++y)
      for (int x = 0; x < size.nx; ++x, ++i) {
        const int p[3] = {x, y, z};
        for (int d = 0; d < g.slots; ++d) {
          const int axis = d / 2, step = d % 2 == 0 ? 1 : -1;
          int q[3] = {p[0], p[1], p[2]};
          q[axis] += step;
          if (q[axis] < 0 || q[axis] >= n[axis]) {
            // A periodic axis of extent 1 would make a cell its own neighbour: skip it.
            if (!periodic[size_t(axis)] || n[axis] < 2) continue;
            q[axis] = (q[axis] + n[axis]) % n[axis];
          }
          g.neighbor[size_t(i) * size_t(g.slots) + size_t(d)] =
              int32_t(q[0] + int64_t(size.nx) * (q[1] + int64_t(size.ny) * q[2]));
        }
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
