// Fields stored in files (FGSG §4.2: "we additionally allow the loading of an arbitrary
// field from a file"). The format, plain text (also in docs/fields.md):
//
//   # anything after '#' on a line is a comment; blank lines are ignored
//   fgsg-field 1 <vector|tensor|asymmetric> <vertexCount> [world|frame]
//   <one line per vertex of the surface, in the surface's vertex order>
//
// The header names the format version (1), the field type, the number of vertices (must
// equal the surface's) and the coordinates of the values (world when omitted):
//
//   vector world   x y z               a world vector; its component along the vertex
//                                      normal is dropped (projected onto the tangent plane)
//   tensor world   xx xy xz yy yz zz   the upper triangle of a symmetric 3x3 world tensor
//                                      T, restricted to the tangent plane: E^T T E with
//                                      E = [e1 e2] (so normal components are dropped)
//   vector frame   u v                 u e1 + v e2 in the vertex's tangent frame
//   tensor frame   t11 t12 t22         [[t11, t12], [t12, t22]] in the vertex's frame
//   asymmetric world  xx xy xz yx yy yz zx zy zz
//                                      a whole 3x3 world tensor, row by row, restricted to
//                                      the tangent plane (E^T T E): its symmetric part and
//                                      its rotational part w (tangent_field.h)
//   asymmetric frame  t11 t12 t21 t22  [[t11, t12], [t21, t22]] in the vertex's frame
//
// The vertex frame (TangentFrames) is n = the angle-weighted vertex normal, e1 = the edge
// to the next vertex of the vertex's first face (SurfaceMesh::vertexFace) projected onto
// the tangent plane, e2 = n x e1; frame files are exact but tied to this convention, world
// files are portable. Numbers are decimal floating point (C syntax, e.g. 1, -0.5, 2e-3);
// NaN and infinities are rejected. Errors name the file and line:
//   field.txt:7: expected 3 numbers, got 2
//   field.txt:1: the field has 100 vertices, the surface 98
#pragma once

#include "runtime/field/scalar_field.h"
#include "runtime/field/tangent_field.h"

#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace fgsg::rt::field {

enum class FieldCoordinates { World, Frame };

// Parses `text` (named `name` in errors) as a field on the frames' surface.
bool parseField(std::string_view text, const std::string& name,
                std::shared_ptr<const TangentFrames> frames, std::optional<TangentField>& out,
                std::string& error);
bool loadField(const std::string& path, std::shared_ptr<const TangentFrames> frames,
               std::optional<TangentField>& out, std::string& error);

// A scalar field's file, `fgsg-field 1 scalar <vertexCount>` then one number per vertex
// line (runtime/field/scalar_field.h): parsed into `out`, errors named likewise.
bool parseScalarField(std::string_view text, const std::string& name, size_t vertexCount, ScalarField& out,
                      std::string& error);
bool loadScalarField(const std::string& path, size_t vertexCount, ScalarField& out, std::string& error);

// Writes every value with 17 significant digits: loading gives the same field back.
std::string formatField(const TangentField& field,
                        FieldCoordinates coordinates = FieldCoordinates::World);
bool saveField(const std::string& path, const TangentField& field, std::string& error,
               FieldCoordinates coordinates = FieldCoordinates::World);

}  // namespace fgsg::rt::field
