// The cells of the output and the constraint edges between them. A regular grid gives each
// site one slot per direction (+x -x +y -y [+z -z]; slot d uses relation d, -1 = no
// neighbour, periodic axes wrap). Constraints between distant sites (symmetry, §3.5.2) are
// extra links with their own relation. The solver only sees sites, slots and links, so a
// different site graph (labels on the vertices and edges of a plane arrangement, as in
// continuous model synthesis) can reuse it unchanged.
#pragma once

#include "runtime/synthesis/label_grid.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace fgsg::rt::synthesis {

struct Link {
  int32_t from, to;
  int relation;  // the label at `to` must be in row(relation, label at `from`)
};

struct SiteGraph {
  int64_t siteCount = 0;
  int slots = 0;                    // grid neighbours per site
  std::vector<int32_t> neighbor;    // [site * slots + d]
  std::vector<uint32_t> linkStart;  // CSR over extra links; empty when there are none
  std::vector<int32_t> linkSite;
  std::vector<uint16_t> linkRelation;

  int32_t at(int64_t site, int d) const { return neighbor[size_t(site) * size_t(slots) + size_t(d)]; }
  bool hasLinks() const { return !linkStart.empty(); }
};

// 4 slots when nz == 1 (a planar model), else 6.
SiteGraph makeGridGraph(GridSize size, std::array<bool, 3> periodic);

// Adds links in both directions (to->from uses the reverse relation, `reverseOf(r)`).
void setLinks(SiteGraph& g, const std::vector<Link>& links, const std::vector<int>& reverseOf);

}  // namespace fgsg::rt::synthesis
