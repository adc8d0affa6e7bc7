// Degenerate points of a field (FGSG §4.2, Zhang et al. 2007 §5): found per face from
// the index of the interpolated field around the face's boundary. Inside a face the field
// is the barycentric blend of the transported corner values, an affine function of
// position; its winding along the boundary is the sum of the principal angle changes
// between successive corners:
//   vector field: the winding of the vector, index = winding (+1 node/centre/focus,
//     -1 saddle);
//   tensor field: the winding of the deviatoric part (t11 - t22) / 2 + i t12, whose angle
//     is twice the major eigenvector's, so the line field's index = winding / 2 (+1/2
//     wedge, -1/2 trisector).
// The degenerate point is where the affine vector / deviatoric part vanishes (clamped to
// the face). A vertex whose value is exactly zero (a design element placed on it, a file)
// is degenerate itself: its index is the winding around its one-ring, measured in its own
// frame; it is reported in its SurfaceMesh::vertexFace, and faces touching it report none.
// Boundary vertices are never degenerate (an index needs a closed loop).
#pragma once

#include "runtime/field/tangent_field.h"

#include <vector>

namespace fgsg::rt::field {

// Every degenerate point of the field, ordered by face.
std::vector<Degeneracy> findDegeneracies(const TangentField& field);

// The doubled index of the degenerate points the field reports in face f (cached).
int faceIndexTimesTwo(const TangentField& field, int face);

// Sum of indexTimesTwo: 2 chi on a closed surface of Euler characteristic chi for a
// smooth field (Poincare-Hopf; line fields too).
int indexSumTimesTwo(const std::vector<Degeneracy>& degeneracies);

}  // namespace fgsg::rt::field
