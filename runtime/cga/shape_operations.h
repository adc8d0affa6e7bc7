// CityEngine's scope operations and footprint shaping (issue #44) on a shape's scope and
// geometry, as pure functions like the rest of runtime/cga (errors come back as text).
//
// Scope operations keep the geometry where it is in the world and give the shape a new
// scope fitted to it (the geometry's bounding box in the new axes), as CityEngine does.
// A polygon's scope keeps fgsg's polygon frame: Z is the polygon's normal (CityEngine's y
// on a lot; docs/cga.md), so an axis that a scope operation turns onto the normal is
// renamed Z, the frame kept right-handed.
#pragma once

#include "runtime/cga/cga.h"
#include "runtime/cga/skeleton_roof.h"

#include <string>
#include <vector>

namespace fgsg::rt::cga {

// rotateScope(ax, ay, az): the scope's axes turned about its own x, then y, then z (as R).
bool rotateScope(const Scope& scope, const GeomRef& geom, GeometryArena& arena, const Vec3& degrees, Part& out,
                 std::string& error);

// alignScopeToAxes() (axis 7): the world's axes; alignScopeToAxes(x|y|z) (axis 0..2): that
// axis the world's, the scope's z (for x) or x (for y, z) projected onto the plane across
// it (op_alignScopeToAxes), the third axis completing the frame.
bool alignScopeToAxes(const Scope& scope, const GeomRef& geom, GeometryArena& arena, int axis, Part& out,
                      std::string& error);

// alignScopeToGeometry(upAxis, face, edge): the up axis (1 y, 2 z) along face `face`'s normal
// (-1: the largest face; negative indices count from the end), x along its edge `edge`
// (-1: the longest; negative indices count from the end), the third axis completing a
// right-handed frame.
bool alignScopeToGeometry(const Scope& scope, const GeomRef& geom, GeometryArena& arena, int upAxis, int face,
                          int edge, Part& out, std::string& error);

// mirrorScope(x, y, z): each flipped axis reversed and the origin moved to the far side of
// the scope; the geometry keeps its place (the scope is left-handed after an odd number
// of flips). mirror(x, y, z): the geometry mirrored within its scope; faces keep facing out.
bool mirrorScope(const Scope& scope, const GeomRef& geom, GeometryArena& arena, const bool flip[3], Part& out,
                 std::string& error);
bool mirrorGeometry(const Scope& scope, const GeomRef& geom, GeometryArena& arena, const bool flip[3], Part& out,
                    std::string& error);

// setPivot(axisMap, corner) (op_setPivot; set_pivot.cpp): the pivot at scope corner `corner`
// (0..3 around the bottom from the origin along x first, 4..7 above them), its axes the
// scope's in the order axisMap names (0 xyz, 1 yzx: x along the scope's z, y along x;
// 2 zxy: x along y, y along z) at corner 0, elsewhere turned to point into the scope (y
// along the same line, right-handed). `out` is the shape with the pivot's frame as scope
// around the same box, its geometry where it was; `pivot` the frame (P and axes).
bool setPivot(const Scope& scope, const GeomRef& geom, GeometryArena& arena, int axisMap, int corner, Part& out,
              Scope& pivot, std::string& error);

// reverseNormals(): every face's corners in the opposite order. deleteHoles(): each face's
// outline alone. resetGeometry(): the geometry becomes the scope box.
// cleanupGeometry(what, tolerance), tolerance from 0 to 1 (op_cleanupGeometry: 1 m, 10 degrees,
// 1 m2 at 1; 0 exact matches): corners that close merged (what & 1), corners where the
// outline turns by that angle or less dropped (what & 2), faces with that area or less and
// second copies of a face dropped (what & 4), neighbouring faces whose normals differ by
// that angle or less joined across their shared edges (what & 8).
bool reverseNormals(const Scope& scope, const GeomRef& geom, GeometryArena& arena, Part& out, std::string& error);
bool deleteHoles(const Scope& scope, const GeomRef& geom, GeometryArena& arena, Part& out, std::string& error);
bool cleanupGeometry(const Scope& scope, const GeomRef& geom, GeometryArena& arena, int what, double tolerance,
                     Part& out, std::string& error);

// The scope `base` with axes `axes` (orthonormal, mirrored too) fitted around faces given in
// world points (their bounding box in those axes; a side thinner than 1e-9 of the largest
// is 0), and the faces in its unit box, counter-clockwise in a mirrored frame too. What is
// not geometry (the colour, the projection) is kept from `base`.
std::vector<Polygon3> fitScopeAroundWorldFaces(const Scope& base, const Mat3& axes,
                                               const std::vector<Polygon3>& worldFaces, Scope& out);

// CityEngine's initial shape in the `.cga` dialect is a ground face: a one-face
// Polyhedron lying in its scope's XZ plane (y = 0, y its normal). The footprint
// operations take it as they take fgsg's polygon and give their parts back as ground faces.
bool lyingOnGround(const GeomRef& geom, const GeometryArena& arena);
// The polygon part as a ground face: y its normal, x along `xAxis` laid onto its plane.
void asGroundFace(Part& part, const Vec3& xAxis, GeometryArena& arena);

// ---- footprints: a polygon (or a flat footprint box, or a ground face) seen in its own plane

// The polygon's outline in metres in its scope's XY plane, counter-clockwise; no holes.
struct FlatPolygon {
  Scope scope;
  std::vector<Vec2> ring;
  bool groundFace = false;  // it was a ground face: its parts become ground faces (x along xAxis)
  Vec3 xAxis = Vec3::UnitX();
  std::vector<std::vector<Vec2>> holes;  // its courtyards, clockwise (only with takeHoles)
};
// A polygon with holes is an error unless takeHoles (then they are out.holes).
bool flatPolygon(const Scope& scope, const GeomRef& geom, GeometryArena& arena, const char* what, FlatPolygon& out,
                 std::string& error, bool takeHoles = false);

// Which selectors take each edge (the edge from corner i to i + 1): its outward normal
// classified into the scope's quadrants (front: -Y, the side of a lot's first edge; back
// +Y; left -X; right +X; a diagonal goes to front or back) and the world's (north -Z,
// south +Z, east +X, west -X; a diagonal to north or south); street.* from the lot's street
// widths where `streets` has them (runtime/cga/street_edges.h), else the edge facing the
// front most squarely is street.front and street.back / left / right are back / left / right.
struct StreetEdges;
enum EdgeSelector : unsigned {
  kEdgeFront = 1, kEdgeBack = 2, kEdgeLeft = 4, kEdgeRight = 8, kEdgeStreetFront = 16,
  kEdgeNorth = 32, kEdgeSouth = 64, kEdgeEast = 128, kEdgeWest = 256,
  kEdgeStreetBack = 512, kEdgeStreetLeft = 1024, kEdgeStreetRight = 2048,
};
std::vector<unsigned> edgeSelectors(const FlatPolygon& polygon, const StreetEdges* streets = nullptr);
// The selector bits a setback label takes ("front", "side", "streetFront", "all" ...; 0: none).
// Index selectors ("#2"): runtime/cga/edge_index_label.h.
unsigned edgeSelectorMask(const std::string& label);

// setback: edge i set back by distance[i] (0: not set back) and given to group[i] (-1: none).
// Each set-back edge's band (the edge, the offset edge, and the lines between their ends
// where neighbouring bands meet) is one piece; with merged[group] the bands of consecutive
// edges of a group are one piece (all of them around the polygon: a ring with the
// remainder as its hole). `remainder` gets the polygon left inside (one piece). Every
// piece keeps the polygon's axes, its scope fitted to it. Negative distances move the edges
// outward (CGA's offset(+d)): the remainder is then the grown polygon and the bands lie
// around the polygon. Fails when a distance makes an edge vanish (the band of a neighbour
// swallows it), the remainder cross itself, or distances have both signs.
bool setback(const FlatPolygon& polygon, const std::vector<double>& distance, const std::vector<int>& group,
             const std::vector<bool>& merged, GeometryArena& arena, std::vector<Part>& pieces,
             std::vector<int>& pieceGroup, std::vector<Part>& remainder, std::string& error);

// setbackToArea(area): the one distance by which the `selected` edges are set back so that
// the remainder has `area` (bisection to within 1e-6 of it). Fails for an area not between 0
// and the polygon's, or one an edge would vanish before reaching.
bool setbackDistanceForArea(const FlatPolygon& polygon, const std::vector<bool>& selected, double area,
                            double& distance, std::string& error);

// splitArea(axis){ area : A | ... }: the lengths along `axis` (0 x, 1 y, 2 z) that cut a flat
// shape into parts of the areas asked for, laid out as a `.cga` split lays out its sizes
// (cityEngineSizes on the shape's area: `derived` says which parts are generated; relative
// areas are shares of the whole). Fails for a solid, an edge or a shape without area.
bool splitAreaSizes(const Scope& scope, const GeomRef& geom, const GeometryArena& arena, int axis, bool repeat,
                    const std::vector<SizeValue>& areas, std::vector<SizeValue>& lengths, std::vector<bool>& derived,
                    std::string& error);

// convexify(maxLength): a concave polygon cut along diagonals into convex pieces, one face
// each, the shape keeping its scope (maxLength infinite: every cut; else only cuts shorter
// than it). A convex polygon is left as it is; one with holes is cut around them
// (convexify.cpp). Fails for a polygon that crosses itself.
bool convexify(const Scope& scope, const GeomRef& geom, GeometryArena& arena, double maxLength, Part& out,
               std::string& error);

// taper(height): a pyramid over the polygon (a lot, a Footprint, a face), its apex `height`
// along the normal above the polygon's centre of gravity; its faces the sides (one
// triangle per edge, in the polygon's edge order), then the base. The scope is extrude's.
bool taper(const Scope& scope, const GeomRef& geom, double height, GeometryArena& arena, Part& out,
           std::string& error);

// envelope(direction, maxHeight, ...) (op_envelope): over a convex polygon (a lot, a
// Footprint, a face), the solid below every edge's plane and below maxHeight. Edge i's plane
// stands on the edge at edges[i].baseHeight and rises inward at edges[i].angleDeg from the
// polygon's plane (0 flat, 90 a wall up to maxHeight: no plane). Along the polygon's normal,
// or the world's up (worldUp: the polygon must face up). Faces: one wall per edge that has
// height (edge order), one top face per plane where it is the lowest (sloped planes in edge
// order, then the flat cap at maxHeight), the bottom; a closed solid. The scope is
// extrude's (x kept, y the normal) to the envelope's greatest height. Fails for a concave
// polygon, a base height below 0, an angle outside [0, 90], maxHeight not above 0, or no
// height at all.
struct EnvelopeEdge {
  double baseHeight = 0.0;
  double angleDeg = 90.0;
};
bool envelope(const Scope& scope, const GeomRef& geom, const FlatPolygon& polygon, bool worldUp, double maxHeight,
              const std::vector<EnvelopeEdge>& edges, GeometryArena& arena, Part& out, std::string& error);
// envelope's side forms: `values` holds `count` numbers, pairs (base height, angle) for
// street.front, then street.back, then street.side (one pair) or street.right and
// street.left (two pairs), given to the edges edgeSelectors classes that way; an edge no
// pair names keeps (0, 90), as op_envelope's defaults.
std::vector<EnvelopeEdge> envelopeEdgesBySide(const std::vector<unsigned>& classes, const double* values,
                                              size_t count);

// innerRectangle(scope | edge): the largest rectangle inside the polygon with sides along
// the scope's x and y (alongEdge: along the edge that gives the largest), its scope fitted
// to it (x along its sides). Exact where the polygon's sides run along the rectangle's
// axes; otherwise found on a grid of 1/256 of the polygon's extent.
bool innerRectangle(const FlatPolygon& polygon, bool alongEdge, GeometryArena& arena, Part& out, std::string& error);

// The primitives: the geometry replaced, in the scope (CityEngine's primitive* operations).
// Without sizes: fit the scope (a zero size replaced by the mean of the others, as i()
// does); with sizes: centred on the scope's xz, standing on y = 0. The quad and the disk
// lie in the plane of the two other sizes when exactly one is zero, else in the xz plane.
// args as CityEngine's: Sphere(sides around, divisions pole to pole, radius), 16 and 16.
bool primitive(const Scope& scope, const std::string& kind, const std::vector<double>& args, GeometryArena& arena,
               Part& out, std::string& error);

}  // namespace fgsg::rt::cga
