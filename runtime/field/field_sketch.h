// What `fgsg field` shows of a designed field, so it can be judged before anything grows
// on it (FGSG Fig. 7): its streamlines (a tensor field's major hyperstreamlines, and with
// `minor` its minor ones too) traced from seeds spread over the surface, and its
// singularities with their indices. As one mesh: the surface in grey, the streamlines as
// line segments (glTF LINES, OBJ `l`, PLY edges), each singularity a small octahedron
// coloured by its kind.
#pragma once

#include "runtime/field/tangent_field.h"
#include "runtime/mesh.h"

#include <vector>

namespace fgsg::rt::field {

struct FieldSketchOptions {
  int seeds = 150;        // streamline seeds, spread over the faces
  double length = 0;      // the most each streamline runs either way; 0: a tenth of the surface's diagonal
  double step = 0;        // distance between a streamline's points; 0: a 400th of the diagonal
  bool minor = false;     // a tensor field's minor hyperstreamlines as well
};

struct Singularity {
  Vec3 position;
  Degeneracy::Kind kind = Degeneracy::Other;
  int indexTimesTwo = 0;  // +1 wedge, -1 trisector; +2 node, centre, focus; -2 saddle
};

struct FieldSketch {
  std::vector<std::vector<Vec3>> majorLines, minorLines;  // polylines, world space
  std::vector<Singularity> singularities;
};

FieldSketch sketchField(const SurfaceMesh& mesh, const TangentField& field, const FieldSketchOptions& options);

// The sketch over `surface` (world space) as one coloured mesh; markers `markerSize` across.
Mesh sketchMesh(const Mesh& surface, const FieldSketch& sketch, double markerSize);

// A singularity kind's name ("wedge", "trisector", "node", ...).
const char* singularityName(Degeneracy::Kind kind);

}  // namespace fgsg::rt::field
