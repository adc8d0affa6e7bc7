// The annotated base mesh of feature-based cellular texturing (Legakis et al. 2001 §3:
// the designer marks faces "window", "arch", ...), read from a Wavefront OBJ whose
// groups are the annotations:
//
//   LabelledMesh lm = readBaseMeshObj("examples/assets/brick_building.obj");
//   FeatureMesh fm = buildLabelledFeatureMesh(lm);   // groups split faces, label them
//
// What is read: `v x y z` (a w is ignored); `f` with three or more corners written i,
// i/t, i//n or i/t/n (negative indices count back from the last vertex), polygons
// fan-triangulated from their first corner; `g NAME...`, `o NAME` and `usemtl NAME`
// start a group (its name is the rest of the line, trimmed). Comments, blank lines, `vt`,
// `vn`, `s` and `mtllib` are skipped; any other statement is an error. Vertices at
// exactly equal positions are welded so that separately written pieces join; vertices no
// face uses are dropped. The result must pass surface::validateSurface.
#pragma once

#include "runtime/cells/feature_mesh.h"
#include "runtime/surface/surface_mesh.h"

#include <string>
#include <string_view>
#include <vector>

namespace fgsg::rt::cells {

struct LabelledMesh {
  surface::SurfaceMesh mesh;        // topology built
  std::vector<std::string> groups;  // in order of first use; "" for faces before any group
  std::vector<int> triangleGroup;   // per mesh triangle, an index into groups
};

// Throw std::runtime_error "NAME:LINE: what is wrong", or "NAME: ..." for problems of the
// whole file (unreadable, no faces, not a valid surface).
LabelledMesh readBaseMeshObj(const std::string& path);
LabelledMesh parseBaseMeshObj(std::string_view text, const std::string& nameForMessages);

// buildFeatureMesh with group boundaries as feature edges, then applyGroupLabels.
FeatureMesh buildLabelledFeatureMesh(const LabelledMesh& mesh, const FeatureOptions& options = {});

}  // namespace fgsg::rt::cells
