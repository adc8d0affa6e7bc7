// CGA shape operations (Müller et al. 2006) on a shape's scope and geometry: splits,
// repeats, component splits, extrusion and roofs. Pure functions: they read a scope and
// a geometry reference and write the parts a successor body receives. Errors (a split
// that cannot fit, an unknown selector) come back as text in `error`, never thrown.
#pragma once

#include "runtime/deadline.h"
#include "runtime/geometry.h"
#include "runtime/mesh.h"
#include "runtime/scope.h"

#include <cstddef>
#include <string>
#include <vector>

namespace fgsg::rt::cga {

// A size argument after evaluation: absolute (h), relative share of what absolute and
// floating sizes leave (1r), or floating (~h: an absolute size that stretches so the
// floating parts fill the scope when there are no relative parts).
struct SizeValue {
  enum Kind { Absolute, Relative, Floating } kind = Absolute;
  double value = 0.0;
};

struct Part {
  Scope scope;
  GeomRef geom;
  bool empty = false;  // a part whose geometry clipped away entirely (it is skipped)
  // A Comp face: which face it is (faceSelectorMask's bits); a Comp edge: its roof class
  // (componentSelectorMask's bits for an edge component; 64 bits: street.* lie past bit 31).
  uint64_t faceClass = 0;
};

// The faces a Comp face selector ("front", "sidefaces", "faces" ...) or the name of a
// labelled part (`Comp("f"){ front: A | side: B | all: C }`: also "side" and "all")
// takes, as a mask to test against Part::faceClass; 0 for any other name.
unsigned faceSelectorMask(const std::string& name);

// The same for a labelled part of a Comp of `component`: for fgsg's edges ("edges" ...) the
// roof classes `eave ridge hip valley gable` (also `eaves ridges hips valleys rake rakes`)
// and `all` (~0u: every edge, those of no roof class too). CityEngine's comp(e) and comp(v)
// ("e", "v") also take the scope's sides and slopes (`front ... bottom`, `vertical aslant
// horizontal nutant` by the mean of the faces' normals; `side` all but horizontal), and
// every component `border`, `inside` and the world's and the object's sides (`worldUp
// worldDown worldNorth worldSouth worldEast worldWest worldSide`, `objectTop ... objectSide`);
// faces anything else as faceSelectorMask(name). CityEngine's street.* (`streetFront
// streetBack streetLeft streetRight streetSide`) for all three: the quadrant of the
// component's level outward direction in the object system (components.cpp). A merged
// part's label ("all=") takes what its name takes. 0 for any other name.
uint64_t componentSelectorMask(const std::string& component, const std::string& name);

// Subdiv("X", s1, s2, ...): cuts the scope along `axis` (0 X, 1 Y, 2 Z) into one part
// per size, in order. Relative sizes share the length left by the others in proportion
// to their values; floating sizes stretch when no relative size is present. Polygon and
// polyhedron geometry is clipped to each slab. Fails if absolute sizes exceed the length
// and nothing relative or floating can absorb the difference (that is CGA's semantics:
// parts must add up to the scope).
bool subdivide(const Scope& scope, const GeomRef& geom, int axis,
               const std::vector<SizeValue>& sizes, GeometryArena& arena,
               std::vector<Part>& out, std::string& error);

// CGA's repeat split `Subdiv("X"){ ~1: Wall | 1.4: Window }*` on a scope `length` long:
// the sizes Subdiv cuts by, the pattern written out `*repeats` times. With a floating
// size the pattern repeats round(length / its nominal length) times (at least once) and
// the floating parts stretch or shrink to fill the scope; with absolute sizes alone it
// repeats as often as it fits whole, and a last absolute size holds what is left (the
// caller derives no part there). False and a message for a size that is not a finite
// non-negative number, or a pattern of no length.
bool repeatPattern(const std::vector<SizeValue>& pattern, double length, int axis, std::vector<SizeValue>& sizes,
                   size_t& repeats, std::string& error);

// A split of a CityEngine `.cga` file (`split(x){ 3 : A | ~1 : B }`, `{ ... }*`) laid out as
// CityEngine does, on a scope `length` long: absolute sizes as given, floating sizes
// scaled by one factor so that they fill what the absolute ones leave (nothing left: they
// are not generated), relative sizes (a nested repeat's share here; `'0.3` is absolute
// by then) sharing what both leave. Parts are laid end to end and the one crossing the
// end is cut there; parts after it, and parts of size <= 0, are not generated. A repeated
// pattern (`repeat`) is written out round(L / its length) times (at least once) when it
// has a floating size, else as often as needed to cover the scope (the last one cut).
// `sizes` gets one absolute size per part (the pattern written out) plus, when the parts
// leave some of the scope, a last one for that rest; `derived[k]` says whether part k is
// generated (the rest never is). False and a message for a size that is not finite, or a
// repeated pattern of no length.
bool cityEngineSizes(const std::vector<SizeValue>& parts, double length, int axis, bool repeat,
                     std::vector<SizeValue>& sizes, std::vector<bool>& derived, size_t& patternLength,
                     std::string& error);

// Repeat("X", s) / Repeat("XY", sx, sy): tiles the scope with n = max(1, floor(L / s))
// equal tiles per axis (each L / n long), axes given as a mask (1 X, 2 Y, 4 Z) with one
// size per set bit, low bit first. Tiles are ordered X fastest, then Y, then Z. Tiles
// whose clipped geometry is empty are marked `empty`.
bool repeat(const Scope& scope, const GeomRef& geom, unsigned axesMask,
            const std::vector<double>& sizes, GeometryArena& arena, std::vector<Part>& out,
            std::string& error);

// Comp("selector"): the components of a box or polyhedron. Face selectors: "faces" ("f"),
// "sidefaces", "top", "bottom", "front" (+Z), "back" (-Z), "left" (-X), "right" (+X)
// (top is +Y: buildings stand on the XZ plane, CGA's convention). Each face becomes a
// Polygon part whose scope has X along the face's lowest horizontal edge (or its first
// edge), Z the outward normal and Y = Z x X, its origin at the face's bounding-box
// corner so the polygon lies in [0,1]^2 of the new scope. Edge selectors: "edges",
// "sideedges", "topedges", "bottomedges": an edge is top when both ends are at the
// solid's maximum height, bottom when both are at its minimum, side otherwise; each
// becomes an Edge part whose scope has Y along the edge (sy = its length), Z the mean
// of the adjacent face normals, sx = sz = 0. "e" and "v" are CityEngine's comp(e) and
// comp(v): every edge with x along it (sx its length, sy = sz = 0), every vertex with a
// scope of no size at it, z its normal (components.cpp). Each part's faceClass holds the
// classes componentSelectorMask tests, the world.* / object.* ones in the world's axes
// and `objectAxes` (the start shape's). Those and border / inside only where
// `wantedClasses` (the labels' masks together) asks for them: border takes a pass over
// every edge, and comp(f) runs on every lot. street.* by the lot's street widths where
// `streets` is given (runtime/cga/street_edges.h), else in the object system.
struct StreetEdges;
bool components(const Scope& scope, const GeomRef& geom, const std::string& selector,
                GeometryArena& arena, std::vector<Part>& out, std::string& error,
                const Mat3& objectAxes = Mat3::Identity(), uint64_t wantedClasses = ~uint64_t{0},
                const StreetEdges* streets = nullptr);

// comp(e)'s and comp(v)'s merged part (`all = A`): the edges or vertices `parts` (at least
// one) as one shape, an Edge part with the first one's axes and its scope fitted to them all
// (the box around their ends in those axes).
Part mergedComponents(const std::vector<Part>& parts);

// comp(f)'s merged part (`side = A`): the faces `parts` (at least one) as one shape, its
// geometry all their faces (one Polygon stays one), its scope the first face's axes fitted
// around them all (the box around their corners in those axes).
Part mergedFaces(const std::vector<Part>& parts, GeometryArena& arena);

// Extrude(h): a Polygon becomes a prism of height h along the scope's Z; a flat Box with
// sy == 0 (a CGA footprint on the XZ plane) grows to height h along Y. The result's
// scope spans the solid.
bool extrude(const Scope& scope, const GeomRef& geom, double height, GeometryArena& arena,
             Part& out, std::string& error);

// Footprint(x1, z1, x2, z2, ...): the shape becomes the polygon with these corners in its
// scope's XZ plane (scope units from its origin; either orientation; a closing corner that
// repeats the first is dropped), a Polygon facing up along the scope's Y: its scope has X
// kept, Z = the old Y and Y = Z x X, spanning the polygon's bounding box, so Extrude and
// Roof stand on it. `holes` (courtyards; a GeoJSON lot's) are joined to the outline by
// zero-width bridges. Fails for fewer than three corners, no area, a self-crossing edge,
// a hole not strictly inside the outline or overlapping another.
bool footprint(const Scope& scope, const std::vector<Eigen::Vector2d>& outer,
               const std::vector<std::vector<Eigen::Vector2d>>& holes, GeometryArena& arena, Part& out,
               std::string& error);

// Offset(d){ inside: A | border: B } (CGA's setback): the polygon (a Footprint, a lot,
// a Comp face; a flat footprint box as its rectangle) shrunk by `distance` from every edge
// by its straight skeleton — one inside piece per part it falls into, none when it
// vanishes — and, `wantBorder`, the band between: the polygon with the inside pieces as
// holes (joined by bridges) and, around a courtyard, the band between each inside
// piece's hole and the polygon's holes within it. Every part keeps the polygon's scope.
// `deadline` (--max-seconds): rt::TimeLimitReached when it passes while the skeleton is
// built (CGAL's, which takes time as the cube of the corners and cannot be interrupted).
bool offset(const Scope& scope, const GeomRef& geom, double distance, bool wantBorder, GeometryArena& arena,
            std::vector<Part>& inside, std::vector<Part>& border, std::string& error,
            const Deadline* deadline = nullptr);

// Roof("hipped" | "gable" | "pyramid" | "shed", angle): a roof solid on the footprint the
// scope stands on: a box's XZ rectangle at its base (the ridge along the longer side, the
// slopes over the longer sides at `angle` degrees), a polygon (rising along its normal)
// or a solid's flat bottom face, roofed by the straight skeleton so every sloped face of
// a hipped roof tilts by `angle` (runtime/cga/skeleton_roof.h). The result's scope spans
// the roof (sy = its height) and its geometry is a Polyhedron whose sloped faces are side
// faces for Comp, whose ridge is a top edge and whose hips are side edges. `deadline`
// as for offset.
//
// `options` (CityEngine's roofHip(angle, overhang), roofGable(angle, overhangX, overhangY),
// roofShed(angle, index)): overhangs in metres, 0 or more, for hipped and gable roofs
// (skeleton_roof.h's RoofOverhang: the sloped faces reach past the eaves and the gable
// walls; the scope then spans the whole roof, below the footprint's plane too), and the
// footprint edge a shed rises from or a gable's ridge runs along (a convex quadrilateral's;
// its outline's edge index, taken modulo the number of edges; -1: the first edge, the
// skeleton's own ridge).
struct RoofOptions {
  double overhang = 0.0;       // past the eaves, measured on the roof planes
  double gableOverhang = 0.0;  // past the gable walls, measured horizontally
  int edgeIndex = -1;
};
bool roof(const Scope& scope, const GeomRef& geom, const std::string& kind, double angleDeg,
          GeometryArena& arena, Part& out, std::string& error, const Deadline* deadline = nullptr,
          const RoofOptions& options = {});

// CityEngine's roofs by height (roofHip(byHeight, h) ...): the roof(kind, angle) whose
// highest point stands `height` above the footprint, angle = atan(height / t_max) with t_max
// the largest horizontal distance the kind's planes rise over (the straight skeleton's
// largest offset for hipped and gable roofs, a shed's depth from its edge, a ridge roof's
// half depth, a pyramid's apex distance). Overhangs do not change the slope or the ridge:
// their eaves hang below the footprint's plane. Errors as roof()'s, and `height` not a
// number more than 0.
bool roofByHeight(const Scope& scope, const GeomRef& geom, const std::string& kind, double height,
                  GeometryArena& arena, Part& out, std::string& error, const Deadline* deadline = nullptr,
                  const RoofOptions& options = {});

// A shape's own surface as world polygons, each counter-clockwise seen from outside: a
// flat shape (a Polygon, or a Box with no depth) is its one face, looking along the scope
// axis it has no size in (a facade piece along Z, a footprint up Y); a solid (a Box or a
// Polyhedron) is every face but its bottom ones, since it stands on something. Edges
// have no surface. How a Cells base part's pieces become a base mesh.
std::vector<std::vector<Vec3>> surfacePolygons(const Scope& scope, const GeomRef& geom, const GeometryArena& arena);

// The mesh a leaf shape outputs as its own geometry (CGA), in its scope's unit box (placed
// by the scope's unitBoxToWorld): every face of a box or polyhedron, a polygon's one face,
// the one face of a flat box (a footprint, a facade piece) looking along the axis it has
// no size in; flat shaded, with normals. Empty for an edge or a box with two zero sizes.
Mesh ownGeometryMesh(const Scope& scope, const GeomRef& geom, const GeometryArena& arena);

// Triangulates a shape's own geometry (box, polygon or polyhedron) into world-space
// triangles, appended as x y z floats: used when a grammar instances a shape's geometry.
void triangulate(const Scope& scope, const GeomRef& geom, const GeometryArena& arena,
                 std::vector<float>& positions, std::vector<unsigned>& indices);

}  // namespace fgsg::rt::cga
