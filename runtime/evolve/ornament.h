// One tile's ornament: Chan & Hui 2013 §2.4 (Elber's Hermite blend, Eq. 1) and §5.2
// (Eqs. 7-11, the Coons-patch extension), on a flat tile.
//
// The ornament of an allele is its cross-section swept along its locus (orientation
// applied) between two rails, in the tile's unit square (x, y in [0,1]) with z up:
//
//   S(r, t) = A0(t) + D0(t) x_s(r) + n y_s(r) + T_{-d}(t) h10(r) + T_d(t) h11(r)   (Eq. 1)
//
// with (x_s, y_s) the cross-section at r in [0,1] (x_s(0) = -1, x_s(1) = 1, y_s = 0 at
// both ends), n = (0,0,1) scaled to `height`, h10(r) = r(r-1)^2 and h11(r) = r^2(r-1).
//
// Rails. C_{+-d}(t) = C(t) +- d W(t), W(t) a unit offset direction in the plane, so
// A0 = (C_d + C_{-d})/2 = C(t) and D0 = (C_d - C_{-d})/2 = d W(t). W is the locus's
// right-hand normal C'(t) x n / |C'(t)| (for a polyline, the bisector at its vertices),
// except near an end of the locus that lies on the tile's border:
//   - There W is the unit direction *along that border edge* (the side with positive
//     dot product with the normal), so the rails' end points C(0) +- d E lie on the
//     border line and so does the whole end cross-section: S(r, 0) = C(0) + (...) E +
//     (...) n. The end section then depends only on the end point, the border, d, the
//     height and the section, not on the locus's tangent, so the ornaments of two
//     neighbouring tiles whose loci share that end point (and run the same way through
//     it) meet exactly, without gap or overlap.
//   - In between, W blends linearly: W(t) = normalize(N(t) + (1-t)(E0 - N(0)) +
//     t(E1 - N(1))), N the normal and E0, E1 the end directions (E = N at an end that is
//     not on the border, which so keeps the plain normal offset). For a locus that meets
//     the border at right angles, as the paper's example does, E = N and W = N all along.
//   - An end at a tile corner lies on two border lines and no single one can hold the
//     section; it keeps the plain normal offset and its rails reach outside the tile by
//     up to d. A locus meeting the border at a grazing angle makes the ornament thin
//     there (its width across the locus is 2 d sin(angle)).
//   This is our reading of §5.2 on a flat tile: the Coons patch of Eq. 11 has the rails
//   and the two end curves M0, M1 as its four boundaries; on the flat tile M0 and M1 are
//   straight segments of the border, so the bilinear Coons terms cancel and Eq. 11 reduces
//   to Eq. 9 (= Eq. 1's S1) once the rails end on the border, which is what W ensures.
//
// Hermite tangents. T_{+-d} = C'_{+-d} x n, the in-plane directions across the rails (an
// offset curve's tangent is parallel to the locus's, so this is along W), taken with
// length d: T_{-d} = T_d = d W(t). The raw derivative's length depends on how the locus
// is parameterised (it would differ between neighbouring tiles and break the seams) and
// at tile scale is about ten times d, which folds the section. With these tangents the
// Hermite terms narrow the section towards the rails by d (h10 + h11)(r), which is 0 at
// both ends and at r = 1/2, so the ornament's edges and its middle stay put; they lie in
// the plane, so the ornament meets the base tangentially (G1) when the section is flat
// at its ends.
//
// So S(r, t) = C(t) + d (x_s(r) + h10(r) + h11(r)) W(t) + height y_s(r) (0,0,1).
// Its z is height * y_s: a section with y < 0 makes a groove below the plane.
//
// Sampling: `samplesAlong` evenly spaced locus parameters and `samplesAcross` section
// parameters, both ends included, plus the vertices of a polyline locus or section (so
// its corners and peaks are kept). Triangles: two per grid cell, counter-clockwise seen
// from +z (the side the section rises to), so they face outward.
#pragma once

#include "runtime/evolve/tiles.h"
#include "runtime/mesh.h"

#include <array>
#include <vector>

namespace fgsg::rt::evolve {

struct OrnamentOptions {
  double halfWidth = 0.08;  // d: the rails' offset from the locus, in tile units
  double height = 0.1;      // the cross-section's y = 1 rises this high (tile units)
  int samplesAlong = 24;    // points along the locus (plus a polyline locus's vertices)
  int samplesAcross = 12;   // points across the cross-section (plus a polyline's vertices)
};

// The sampled blend surface in double precision: point (i, j) is S(r[j], t[i]).
struct OrnamentGrid {
  std::vector<double> t;  // along the locus, ascending from 0 to 1
  std::vector<double> r;  // across the section, ascending from 0 to 1
  std::vector<std::array<double, 3>> points;  // t-major: points[i * r.size() + j]

  const std::array<double, 3>& at(size_t i, size_t j) const { return points[i * r.size() + j]; }
};

// The ornament of `section` along `locus` (in the tile's unit square, orientation already
// applied). Throws std::invalid_argument for options out of range (halfWidth and height
// finite, halfWidth > 0, height >= 0, 2 <= samples <= 4096) or an offset direction that
// vanishes (a locus whose end tangent is opposite to its blended normal).
OrnamentGrid ornamentGrid(const Curve& locus, const Curve& section, const OrnamentOptions& options = {});

// The same for an allele of a tile set: its locus turned by its orientation about (0.5, 0.5).
OrnamentGrid ornamentGrid(const TileSet& tiles, Allele allele, const OrnamentOptions& options = {});

// The grid as an indexed triangle mesh: positions rounded to float, area-weighted unit
// normals, texture coordinates u = r (across the section) and v = t (along the locus).
rt::Mesh ornamentMesh(const OrnamentGrid& grid);

// The ornament of one allele on a flat tile: the cross-section blended along the turned
// locus between its two rails (Eq. 1 with n = +Z on the plane z = 0), in the tile's unit
// square (x, y in [0,1]) with z up; indexed triangles with normals and texture
// coordinates (u across the section, v along the locus). ornamentMesh(ornamentGrid(...)).
rt::Mesh tileOrnament(const TileSet& tiles, Allele allele, const OrnamentOptions& options = {});

}  // namespace fgsg::rt::evolve
