// The curvature tensor of a surface mesh as a tensor field (FGSG §4.3 (d): mincurv,
// maxcurv, meancurv, gausscurv; Fig. 11's glyphs). Per face, the second fundamental form
// II is fitted by least squares to the change of the vertex normals along the three edges
// (Rusinkiewicz 2004, "Estimating curvatures and their derivatives on triangle meshes"):
// II (e . u, e . v) = (dn . u, dn . v) for each edge e with normal change dn, in the face
// frame (u, v). Each face's II is transported into its corners' frames and averaged with
// the faces' areas as weights. With outward normals a convex surface has positive
// curvature (a sphere of radius r: 1/r, 1/r).
#pragma once

#include "runtime/field/tangent_field.h"

#include <memory>

namespace fgsg::rt::field {

// The curvature tensor at every vertex: eigenvalues are the principal curvatures
// (value1 = the maximum, value2 = the minimum), eigenvectors their directions.
TangentField curvatureTensor(std::shared_ptr<const TangentFrames> frames);

struct Curvatures {
  double min = 0, max = 0, mean = 0, gauss = 0;
};
// The FGSG queries from a curvature tensor field at p: mincurv = value2, maxcurv =
// value1, meancurv = their mean, gausscurv = their product.
Curvatures curvaturesAt(const TangentField& curvature, const SurfacePoint& p);

}  // namespace fgsg::rt::field
