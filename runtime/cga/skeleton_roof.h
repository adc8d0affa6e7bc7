// Roofs on any simple footprint polygon, holes allowed: hipped and gable roofs from the
// straight skeleton (CGAL's Straight_skeleton_2), pyramid, shed and ridge roofs from the
// footprint's edges and extent. The result is a closed solid, its faces as plain 3D polygons.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "runtime/cga/polygon_clip.h"
#include "runtime/deadline.h"

namespace fgsg::rt::cga {

using Vec2 = Eigen::Vector2d;

// Hipped: every footprint edge gets a face sloping up at the angle (the straight skeleton
// lifted by offset time * tan(angle)). Gable: hipped, with the ends of wings made vertical.
// Pyramid: one triangle per edge up to a single apex. Shed: one plane rising from edge 0.
// Ridge (CityEngine's roofRidge): one ridge along x, two planes.
enum class SkeletonRoofKind { Hipped, Gable, Pyramid, Shed, Ridge };

// CGAL's straight skeleton takes time as the cube of the corners and cannot be
// interrupted: up to this many corners (a few milliseconds at worst) it runs on the
// calling thread, past them on a worker abandoned at --max-seconds (runtime/abandonable.h).
constexpr int kInlineSkeletonCorners = 96;

// The footprint lies in the (x, z) plane, points given as (x, z); y is up. The outer ring
// should run counter-clockwise seen from above (+Y) and holes clockwise; a ring given the
// other way round is reversed, so either orientation is accepted. Consecutive points
// closer than 1e-9 times the footprint's extent are merged; "edge i" below counts the
// edges of the merged rings: the outer ring's edges (point i to point i + 1, in the order
// given, whichever the orientation) are 0 .. n-1, then each hole's edges follow.
//
// Output: the roof solid's faces in (x, y, z), y = 0 on the footprint, each face
// counter-clockwise seen from outside, together a closed 2-manifold: first the faces
// standing on the footprint edges in edge order, then the bottom face. Hipped, Gable and
// Pyramid give exactly one face per edge (sloped, or vertical for a gable end). Shed gives
// the sloped top for edge 0 and one vertical side face for each other edge, leaving out
// the sides of edges with no height (those lying on edge 0's line). With holes, the bottom
// (and a shed's top) is one polygon whose holes are joined to the outer ring by zero-width
// bridges: each bridge is an edge that the polygon runs along once in each direction.
// Ridge gives its two sloped faces first (the one over the greater z first),
// then one vertical side face for each edge with height, as a shed leaves out those on its
// eave lines.
// `faceEdges`, when given, receives the footprint edge of each face (-1 for the bottom,
// -2 for a ridge roof's slopes).
// `height` receives the roof's greatest height.
//
// Kinds on general footprints:
// * Hipped: every sloped face tilts by exactly `angleDeg`; concave corners give valleys,
//   holes give courtyards.
// * Gable: a skeleton face that is a triangle whose apex joins only it and its two
//   neighbouring faces (the end of a rectangle or of an L or T wing) becomes a vertical
//   gable: the apex moves along the ridge, where the neighbours' roof planes meet, onto
//   the vertical plane of the triangle's edge, so every face stays planar. Where the
//   neighbouring edges are parallel the ridge is level and the apex keeps its height;
//   where they converge or diverge the gable top is lower or higher. A quadrilateral whose
//   four triangles meet at one point (a square, a rhombus) is gabled on the opposite pair
//   giving the longer ridge; on a tie (a square) the ridge runs along x. Triangles sharing
//   their apex with other faces (a triangular or regular-polygon footprint, a wing end
//   that a concave corner's valley reaches exactly) stay hipped.
// * Pyramid: the apex stands over the area centroid at height d * tan(angle), d the
//   centroid's least distance to an edge line: the faces nearest the centroid tilt by the
//   angle, the others less. Fails with holes or when the centroid is not strictly inside
//   every edge's half-plane (the footprint is not star-shaped around it).
// * Shed: height = distance from edge 0's line * tan(angle). Holes are supported. Fails
//   when part of the footprint lies on the outer side of edge 0's line.
// * Ridge: the ridge is the line z = (zmin + zmax) / 2 across the footprint's extent in z
//   (the middle of its outer ring's); a point's height is tan(angle) times its distance
//   in z from zmin on the near side of the ridge, from zmax on the far side, so both
//   slopes tilt by exactly `angleDeg` and the ridge stands (zmax - zmin) / 2 * tan(angle)
//   high. Each slope is the footprint's part on its side; a concave footprint that the
//   ridge cuts into several pieces on one side gives one slope polygon whose pieces are
//   joined by zero-width bridges along the ridge. Edges crossing the ridge get a side
//   face with a corner on it (the gable triangle of a rectangle). Holes are supported.
//
// Errors (false, `error` starting with "Roof: "): the angle not strictly between 0 and 90
// degrees, non-finite coordinates, a ring with fewer than 3 distinct points or no area, a
// ring that intersects itself, a hole outside the outer ring or touching another ring,
// the kind's conditions above, CGAL failing to build the straight skeleton.
// `deadline` (--max-seconds): rt::TimeLimitReached when it passes while the skeleton is
// built.
//
// `overhang` (CityEngine's roofHip/roofGable overhangs; Hipped and Gable only, ignored by
// the others): every sloped face reaches past its eave by `eaves` metres measured on its
// own plane, perpendicular to the edge (its eave line moves out by eaves * cos(angle) and
// down by eaves * sin(angle)), and past a gable wall by `gables` metres measured
// horizontally, perpendicular to the gable's edge. Neighbouring faces keep meeting along
// their hips, valleys and ridges, extended. Gable walls and the bottom stay on the
// footprint, so such a roof is a sheet of sloped faces over them, no longer a closed solid.
// `ridgeEdge` (CityEngine's roofGable index; Gable only): the ridge runs along that edge of
// a convex quadrilateral without holes, the edges beside it made gable walls (-1: the
// skeleton's own choice).
struct RoofOverhang {
  double eaves = 0.0;
  double gables = 0.0;
  int ridgeEdge = -1;
};

bool skeletonRoof(const std::vector<Vec2>& outer, const std::vector<std::vector<Vec2>>& holes,
                  SkeletonRoofKind kind, double angleDeg, std::vector<Polygon3>& faces,
                  double& height, std::string& error, std::vector<int>* faceEdges = nullptr,
                  const Deadline* deadline = nullptr, const RoofOverhang& overhang = {});

// A footprint with holes (a courtyard) as one polygon, (x, z) points counter-clockwise
// seen from above: each hole joined to the outline by a zero-width bridge that the
// polygon runs along once each way, as the roof's bottom face is built. The rings are
// checked as skeletonRoof checks them; false with `error` (its "Roof: " replaced by
// `what`) when one is not sound.
bool joinHoles(const std::vector<Vec2>& outer, const std::vector<std::vector<Vec2>>& holes,
               const std::string& what, std::vector<Vec2>& joined, std::string& error);

// The same for an outline and holes in a polygon's plane (x, y counter-clockwise seen from
// +z, holes clockwise), whose y runs opposite to the ground's z: the rings are mirrored
// onto the ground, joined there, and the joined ring mirrored back (Offset, Setback).
bool joinHolesInPlane(const std::vector<Vec2>& outline, const std::vector<std::vector<Vec2>>& holes,
                      const std::string& what, std::vector<Vec2>& joined, std::string& error);

}  // namespace fgsg::rt::cga
