// Parameterisations of the base mesh's features (Legakis et al. 2001, §3): every edge
// and face maps its parameter space to a world coordinate frame (where a pattern
// generator places a cell) and projects world points back into parameter space (how the
// occupancy maps of neighbouring features are filled). Edges: lines and circular arcs
// in closed form, other chains by arc length along the polyline. Faces: planar regions
// (a 2D frame whose v axis is world up where the face is not horizontal, so brick
// courses run horizontally) and cylindrical regions ((radius * angle, height)).
// Corners are not parameterised (as in the paper).
#pragma once

#include "runtime/cells/feature_mesh.h"

namespace fgsg::rt::cells {

// A frame on an edge at arc length s: the point, the unit tangent (along the chain) and
// the unit outward normal (the mean of the adjacent faces' normals, perpendicular to
// the tangent; the face normal on the boundary).
struct EdgeFrame {
  Vec3 point, tangent, normal;
};
// s is clamped to [0, length] (wrapped for closed edges).
EdgeFrame edgeAt(const FeatureEdge& edge, double s);
// The arc length of the point of the edge nearest to p.
double projectOnEdge(const FeatureEdge& edge, const Vec3& p);

// A frame on a face at parameter (u, v): the point, unit dP/du, unit dP/dv, normal.
struct FaceFrame {
  Vec3 point, u, v, normal;
};
// Throw std::invalid_argument for a freeform face (no closed-form parameterisation).
FaceFrame faceAt(const FeatureFace& face, const Vec2& param);
// The parameter of p's projection onto the face's plane / cylinder.
Vec2 projectOnFace(const FeatureFace& face, const Vec3& p);

// Used by buildFeatureMesh: classify and fit the geometry of an edge (its points and
// segment normals set) or a face (its triangles set).
void fitEdge(FeatureEdge& edge, const FeatureOptions& options);
void fitFace(FeatureFace& face, const surface::SurfaceMesh& mesh, const FeatureOptions& options);

}  // namespace fgsg::rt::cells
