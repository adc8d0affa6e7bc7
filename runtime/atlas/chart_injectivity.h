// Whether a chart's flat layout covers no place twice. A layout of a disk in which every
// triangle keeps its orientation, the triangles around each vertex turn once (not twice)
// and the boundary does not cross or touch itself is one-to-one (a locally injective map
// of a disk whose boundary is a simple curve is injective), so only the vertices' fans and
// the boundary edges are examined, not every pair of triangles: a few hundred boundary
// edges instead of thousands of triangles per chart.
#pragma once

#include "runtime/atlas/atlas.h"
#include "runtime/atlas/chart_mesh.h"

#include <vector>

namespace fgsg::rt::atlas {

// `uv` per chart vertex; every triangle must already run counter-clockwise in it.
bool layoutIsInjective(const ChartMesh& chart, const std::vector<Vec2>& uv);

}  // namespace fgsg::rt::atlas
