// A scalar field on a surface (FGSG §4.1: "our system can also make use of a scalar
// field"): a number per vertex, linear in each triangle — heights painted in a modeller,
// a density map, a picture's brightness. It answers its value and its gradient
// (constant in a triangle), and as a grammar's first field T follows its gradient.
//
// File format (docs/language.md), plain text like the vector and tensor field files:
//   fgsg-field 1 scalar <vertexCount>
//   <one number per line, in the surface's vertex order>
#pragma once

#include "runtime/field/image_field.h"
#include "runtime/field/tangent_field.h"

#include <memory>
#include <vector>

namespace fgsg::rt::field {

struct ScalarField {
  std::vector<double> values;  // per vertex

  // Interpolated at p (barycentric).
  double at(const SurfaceMesh& mesh, const surface::SurfacePoint& p) const;
  // The gradient in face f's plane (world), exact for a field linear over the face.
  Vec3 gradient(const SurfaceMesh& mesh, int face) const;
  // The gradient as a vector field at the vertices (the faces' gradients around each,
  // weighted by area), for tracing and the direction queries.
  TangentField gradientField(std::shared_ptr<const TangentFrames> frames) const;
};

// Its file is read by runtime/field/field_file.h (parseScalarField, loadScalarField).

// A picture's brightness under each vertex (laid over the surface seen from above).
ScalarField scalarFromPicture(const SurfaceMesh& mesh, const Picture& picture);

}  // namespace fgsg::rt::field
