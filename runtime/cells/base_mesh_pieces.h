// A labelled base mesh from pieces: the flat faces a grammar's splits and component
// splits leave (Legakis et al. 2001 §3 take the designer's annotated mesh; here a facade
// grammar's `window` pieces become `window` features). Pieces written separately meet
// edge to edge only after three repairs, done here:
//  * welding: corners closer than a tolerance (1e-9 of the pieces' extent) are one vertex,
//    since split arithmetic reaches a shared corner along different sums;
//  * T-junctions: a split cuts one side of an edge and not the other (a window column
//    beside a full-height wall piece), so every corner lying on another piece's side is
//    inserted there;
//  * orientation: each connected part is made to agree with its largest piece, so the
//    inside faces of a recess (a window's reveals, written as a box's faces) look out
//    of the opening.
// Polygons are then ear-clipped into triangles (corners in a row on a side are kept).
#pragma once

#include "runtime/cells/base_mesh_file.h"

#include <string>
#include <vector>

namespace fgsg::rt::cells {

struct LabelledPolygon {
  std::string label;        // the feature label ("" for none)
  std::vector<Vec3> points;  // planar, counter-clockwise seen from outside
};

// Throws std::runtime_error naming the trouble (no pieces, pieces meeting three at an
// edge, a part that cannot be oriented, a piece that is not a simple planar polygon, or
// a result that is not a valid surface).
LabelledMesh labelledMeshFromPolygons(const std::vector<LabelledPolygon>& pieces);

}  // namespace fgsg::rt::cells
