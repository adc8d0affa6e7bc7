// The base mesh of feature-based cellular texturing (Legakis, Dorsey & Gortler,
// SIGGRAPH 2001, §3 "Base mesh"): a two-level mesh. The low level (the *child*) is the
// triangle mesh that defines the shape: vertices, polygon edges, polygons. The high
// level (the *parent*) holds the features cells are placed on: corners, edges, faces.
//
//   SurfaceMesh m = ...;  m.buildTopology();
//   FeatureMesh fm = buildFeatureMesh(m);          // FeatureOptions: the thresholds
//   for (const FeatureEdge& e : fm.edges)
//     if (e.direction == EdgeDirection::Horizontal) ...
//   EdgeFrame f = edgeAt(fm.edges[0], 0.5 * fm.edges[0].length);   // feature_param.h
//
// Our reading of §3 and how the features are found (the paper leaves the segmentation
// to "automatic and interactive tools"; this is the automatic part):
//  - A *feature edge of the child mesh* is a mesh edge whose dihedral angle (the angle
//    between its two triangles' normals) exceeds FeatureOptions::creaseDegrees, or a
//    boundary edge (one triangle).
//  - A parent *face* is a connected set of triangles not separated by feature edges
//    ("a collection of connected child polygons"): coplanar or smoothly joined, and so
//    possibly concave and with holes (a wall with a window is one face with two loops).
//    It is *planar* when every triangle normal is within planarDegrees of the mean,
//    *cylindrical* when all normals are within planarDegrees of perpendicular to one
//    axis and the vertices lie on a circle around it (within fitTolerance), else
//    *freeform* (no closed-form parameterisation: the paper needs one to texture it).
//  - A parent *corner* is a child vertex where feature edges meet: one with other than
//    two incident feature edges, or with two that turn by more than cornerDegrees,
//    change from convex to concave, or separate different faces.
//  - A parent *edge* is a chain of feature mesh edges between corners ("a chain of child
//    polygon edges"), or a closed loop without corners (the rim of a cylinder). It is
//    oriented so that its left face (seen from outside) is `leftFace`. Its fold is
//    convex (the surface turns away from the outside, like a box's edge), concave (a
//    re-entrant edge, like the inner edge of an L-shaped block) or a boundary.
//  - Geometry of edges (the paper parameterises "linear and circular segments"): a chain
//    whose vertices lie on the line through its ends is a Line; one of at least three
//    segments whose vertices lie on a circle is an Arc (centre, radius, swept angle; a
//    closed loop is a full circle); anything else is a Polyline (parameterised by arc
//    length, no fit). Tolerances are fitTolerance times the chain's length.
//  - Classification (§5's pattern-generator criteria): edges by direction against the
//    world up axis (Horizontal within directionDegrees of perpendicular to up, Vertical
//    within directionDegrees of parallel, else Slanted; arcs and polylines are Curved);
//    corners by the folds of their edges (all convex, all concave, mixed, or on the
//    boundary) and valence (the number of edge ends at the corner).
//  - Labels are the designer's annotations (the paper: "window", "arch", ...): strings,
//    left empty by buildFeatureMesh, filled from mesh groups by applyGroupLabels.
// Output order is deterministic: faces by their smallest triangle, corners by vertex,
// edges in the order they are walked from corners (increasing vertex, then increasing
// neighbour vertex), then closed loops by their smallest vertex.
#pragma once

#include "runtime/surface/surface_mesh.h"

#include <string>
#include <vector>

namespace fgsg::rt::cells {

using Vec2 = Eigen::Vector2d;

struct FeatureOptions {
  double creaseDegrees = 30;     // dihedral angle above which a mesh edge is a feature
  double planarDegrees = 1;      // normal deviation still "planar" (and "cylindrical")
  double cornerDegrees = 40;     // a chain turning more than this at a vertex breaks there
  double directionDegrees = 10;  // tolerance of Horizontal / Vertical
  double fitTolerance = 1e-4;    // line / circle fits, relative to the feature's size
  Vec3 up = Vec3::UnitZ();       // world up: courses run perpendicular to it
};

enum class EdgeFold { Convex, Concave, Boundary };
enum class EdgeShape { Line, Arc, Polyline };
enum class EdgeDirection { Horizontal, Vertical, Slanted, Curved };
enum class CornerKind { Convex, Concave, Mixed, Boundary };
enum class FaceKind { Planar, Cylindrical, Freeform };

struct FeatureFace {
  std::vector<int> triangles;  // increasing
  std::vector<int> edges;      // the feature edges bounding it, increasing
  // Its boundary loops (chains of edges joined at corners): 1 for a disk, one more per
  // hole (a wall with a window has 2), 0 for a closed surface. Loops that touch at a
  // corner count as one.
  int loops = 0;
  Vec3 normal = Vec3::UnitZ(); // area-weighted mean, unit
  double area = 0;
  FaceKind kind = FaceKind::Freeform;
  bool planar() const { return kind == FaceKind::Planar; }
  // Planar: param (u, v) -> origin + u * uAxis + v * vAxis, (uAxis, vAxis, normal)
  // right-handed. A face more than directionDegrees from horizontal (a wall, a roof) has
  // vAxis = `up` projected into its plane, so uAxis is world-horizontal; a floor or
  // ceiling has uAxis = world X projected (Y when X is too steep). The whole face has
  // u, v >= 0 with its minimum at 0.
  Vec3 origin = Vec3::Zero(), uAxis = Vec3::UnitX(), vAxis = Vec3::UnitY();
  // Cylindrical: param (radius * angle, height) -> centre + height * axis +
  // radius * (cos(angle) * ref + sin(angle) * axis x ref); angle in [-pi, pi), measured
  // from `ref`. `outward`: the normals point away from the axis (a tower, not a vault).
  Vec3 centre = Vec3::Zero(), axis = Vec3::UnitZ(), ref = Vec3::UnitX();
  double radius = 0;
  bool outward = true;
  std::vector<std::string> labels;
};

struct FeatureEdge {
  std::vector<int> vertices;  // chain of mesh vertices; a closed loop repeats the first
  std::vector<Vec3> points;   // their positions
  bool closed = false;
  int leftFace = -1, rightFace = -1;  // rightFace -1: a boundary edge
  EdgeFold fold = EdgeFold::Convex;
  double dihedralDegrees = 0;  // mean over its mesh edges (0 on the boundary)
  EdgeShape shape = EdgeShape::Polyline;
  EdgeDirection direction = EdgeDirection::Curved;
  double length = 0;  // of the line / arc / polyline parameterisation
  // Per mesh segment: the mean normal of the triangles on either side.
  std::vector<Vec3> segmentNormals;
  // Arc: centre + radius * (cos(a) * ref + sin(a) * axis x ref), a = s / radius for arc
  // length s in [0, length]; axis is oriented so that the chain runs counter-clockwise.
  Vec3 centre = Vec3::Zero(), axis = Vec3::UnitZ(), ref = Vec3::UnitX();
  double radius = 0;
  int startCorner = -1, endCorner = -1;  // -1 for closed loops without corners
  std::vector<std::string> labels;
};

struct FeatureCorner {
  int vertex = -1;
  std::vector<int> edges;  // incident feature edges, increasing (a loop appears twice)
  std::vector<int> faces;  // the faces around it, increasing
  int valence = 0;         // edge ends at this corner
  CornerKind kind = CornerKind::Convex;
  std::vector<std::string> labels;
};

struct FeatureMesh {
  std::vector<FeatureFace> faces;
  std::vector<FeatureEdge> edges;
  std::vector<FeatureCorner> corners;
  std::vector<int> faceOfTriangle;  // per mesh triangle
  std::vector<int> cornerOfVertex;  // per mesh vertex, -1 for non-corners
};

// Builds the parent mesh over `mesh` (its topology built). Throws std::invalid_argument
// for an empty mesh, a mesh without topology, or options out of range.
// `triangleGroup` (one entry per triangle, e.g. the OBJ groups of base_mesh_file.h): a
// mesh edge between triangles of different groups is always a feature edge, even where
// they are coplanar (the designer's annotation separates faces the geometry does not);
// its fold is found as for any edge, a flat one counting as convex.
FeatureMesh buildFeatureMesh(const surface::SurfaceMesh& mesh, const FeatureOptions& options = {},
                             const std::vector<int>* triangleGroup = nullptr);

// Labels from groups: each face gets groups[g] for the groups g of its triangles (empty
// names skipped), each edge the union of its two faces' labels, each corner the union of
// its edges' labels; all sorted, without repeats, merged with labels already there.
// Throws std::invalid_argument when triangleGroup does not match the mesh or groups.
void applyGroupLabels(FeatureMesh& fm, const std::vector<std::string>& groups,
                      const std::vector<int>& triangleGroup);

const char* toString(EdgeFold);
const char* toString(EdgeShape);
const char* toString(EdgeDirection);
const char* toString(CornerKind);
const char* toString(FaceKind);

}  // namespace fgsg::rt::cells
