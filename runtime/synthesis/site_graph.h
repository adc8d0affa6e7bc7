// The cells of the output and the constraint edges between them. A regular grid gives each
// site one slot per direction (+x -x +y -y [+z -z]; slot d uses relation d, -1 = no
// neighbour, periodic axes wrap). Constraints between distant sites (symmetry, §3.5.2) are
// extra links with their own relation. The solver only sees sites, slots and links, so a
// different site graph (labels on the vertices and edges of a plane arrangement, as in
// continuous model synthesis) can reuse it unchanged.
//
// Grid neighbours are computed, not stored: a site has its neighbour across slot d at
// site + step[d] unless it lies on the grid face that slot d points through (slot 0 = +x:
// x = nx - 1); there it has none, or wraps by wrap[d] on a periodic axis. One byte per
// site (its faces) replaces 24 bytes of neighbour indices, a third of the solver's working
// set on a 200x200x20 grid.
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
  int slots = 0;                    // grid neighbours per site (at(site, d) is -1 for d >= slots)
  std::array<int32_t, 6> step{};    // neighbour offset across slot d inside the grid
  std::array<int32_t, 6> wrap{};    // the same on the face slot d points through; 0 = none
  std::vector<uint8_t> face;        // per site: bit d set on the face slot d points through
  std::vector<uint32_t> linkStart;  // CSR over extra links; empty when there are none
  std::vector<int32_t> linkSite;
  std::vector<uint16_t> linkRelation;

  // The neighbour across slot d (0..5), -1 for none.
  int32_t at(int64_t site, int d) const { return neighbor(int32_t(site), face[size_t(site)], d); }
  // The same with the site's face bits already loaded.
  int32_t neighbor(int32_t site, uint8_t faces, int d) const {
    if (!((faces >> d) & 1)) return site + step[size_t(d)];
    return wrap[size_t(d)] ? site + wrap[size_t(d)] : -1;
  }
  bool hasLinks() const { return !linkStart.empty(); }
};

// 4 slots when nz == 1 (a planar model), else 6.
SiteGraph makeGridGraph(GridSize size, std::array<bool, 3> periodic);

// Adds links in both directions (to->from uses the reverse relation, `reverseOf(r)`).
void setLinks(SiteGraph& g, const std::vector<Link>& links, const std::vector<int>& reverseOf);

}  // namespace fgsg::rt::synthesis
