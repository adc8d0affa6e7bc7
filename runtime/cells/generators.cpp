// The pattern generators of generators.h.
#include "runtime/cells/generators.h"

#include "runtime/cells/feature_param.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace fgsg::rt::cells {

namespace {

// An edge within 10° of `up` is vertical (FeatureOptions::directionDegrees' default).
const double kVerticalCos = std::cos(10 * 3.14159265358979323846 / 180);
// Two faces at an edge closer than this to coplanar share no corner region.
constexpr double kCoplanarSine = 0.05;

Cell makeCell(const Vec3& origin, const Vec3& x, const Vec3& y, const Vec3& z, const Vec3& size) {
  Cell c;
  c.origin = origin;
  c.axes.col(0) = x, c.axes.col(1) = y, c.axes.col(2) = z;
  c.size = size;
  return c;
}

// The extent, along side i's `away`, of the region both faces' cell layers (depth d)
// share at an edge: {p : 0 <= n_A.p <= d, 0 <= n_B.p <= d} in the plane across the edge.
struct Region {
  double lo = 0, hi = 0;
  bool ok = false;
};
Region regionAlong(const EdgeSides& sd, int i, double d) {
  if (!sd.twoSided) return {};
  const int o = 1 - i;
  const double na = sd.normal[o].dot(sd.away[i]), nn = sd.normal[o].dot(sd.normal[i]);
  if (std::abs(na) < kCoplanarSine) return {};
  Region r{INFINITY, -INFINITY, true};
  for (double alpha : {0.0, d})
    for (double beta : {0.0, d}) {
      const double x = (beta - alpha * nn) / na;
      r.lo = std::min(r.lo, x), r.hi = std::max(r.hi, x);
    }
  return r;
}

// The face on side i of sides `sd` of edge e.
int sideFace(const FeatureEdge& e, const EdgeSides& sd, int i) {
  const bool left = (i == 0) != sd.swapped;
  return left ? e.leftFace : e.rightFace;
}

// How far (at most `most`) a cell of a vertical edge's layer may reach into planar face
// `f`, measured along `away` (in the face's plane, perpendicular to the edge) from the
// edge's segment [base, top]: the largest A such that the level-topped band
// {base..top + a * w, 0 <= a <= A} (w: level, in the face, w . away = 1; for a leaning
// edge not the face's u axis) is all free. Infinite where the face is not planar; 0 where
// it is claimed right at the edge. The band's free part is exact convex pieces
// (FaceOccupancy::freePieces), so the answer is one of their corners' distances from the
// edge: the largest such that the band up to it is covered.
double reachInto(const CellularTexture& tex, int f, const Vec3& base, const Vec3& top, const Vec3& away,
                 const Vec3& w, double most) {
  const FeatureFace& face = tex.features().faces[f];
  if (face.kind != FaceKind::Planar) return INFINITY;
  const FaceOccupancy& map = tex.faceMap(f);
  const Vec2 b = projectOnFace(face, base), t = projectOnFace(face, top);
  const Vec2 along(away.dot(face.uAxis), away.dot(face.vAxis)), level(w.dot(face.uAxis), w.dot(face.vAxis));
  auto band = [&](double a) {
    Polygon2 q{b, b + a * level, t + a * level, t};
    if (signedArea(q) < 0) std::swap(q[1], q[3]);
    return q;
  };
  const double tol = 1e3 * map.tolerance();
  const double minArea = tol * (t - b).norm();
  const std::vector<Polygon2> pieces = map.freePieces(band(most), minArea);
  std::vector<double> ends{most};  // candidate reaches: the pieces' corners' distances
  for (const Polygon2& p : pieces)
    for (const Vec2& q : p)
      if (const double a = (q - b).dot(along); a > tol) ends.push_back(a);
  std::sort(ends.begin(), ends.end());
  const double slack = minArea * double(pieces.size() + 1);
  auto freeUpTo = [&](double a) {  // the band up to a lies in the pieces
    double covered = 0;
    for (const Polygon2& p : pieces) covered += signedArea(clipHalfPlane(p, along, along.dot(b) + a));
    return covered >= signedArea(band(a)) - slack;
  };
  // The band up to a is free up to some reach and not beyond: the last candidate that is.
  size_t lo = 0, hi = ends.size();  // ends[< lo] free, ends[>= hi] not
  while (lo < hi) {
    const size_t mid = (lo + hi) / 2;
    if (freeUpTo(ends[mid])) lo = mid + 1;
    else hi = mid;
  }
  return lo > 0 ? ends[lo - 1] : 0;
}

bool isVertical(const CellularTexture& tex, const FeatureEdge& e) {
  return e.shape == EdgeShape::Line &&
         std::abs((e.points.back() - e.points.front()).normalized().dot(tex.up())) > kVerticalCos;
}

// A whole number of courses of height `course` (at least one) closest to `extent`.
double inCourses(double extent, double course) { return course * std::max(1.0, std::round(extent / course)); }

// A corner where exactly three planar faces meet square: a cube of side d in the region
// all three cell layers share. Where walls rise from the corner (the foot of a column on
// its plinth), its height is whole courses instead, so the walls' courses start level.
// Anywhere else corners get no cell (their edges' cells meet there).
int cornerBlock(CellularTexture& tex, int c, double d, double course) {
  const FeatureMesh& fm = tex.features();
  const FeatureCorner& corner = fm.corners[c];
  if (corner.faces.size() != 3) return 0;
  Vec3 n[3];
  for (int k = 0; k < 3; ++k) {
    const FeatureFace& f = fm.faces[corner.faces[k]];
    if (f.kind != FaceKind::Planar) return 0;
    n[k] = f.normal;
  }
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      if (std::abs(n[i].dot(n[j])) > 0.1) return 0;
  int upright = 0;  // the normal nearest `up` becomes the cell's height axis
  for (int k = 1; k < 3; ++k)
    if (std::abs(n[k].dot(tex.up())) > std::abs(n[upright].dot(tex.up()))) upright = k;
  const int a = (upright + 1) % 3, b = (upright + 2) % 3;
  const Vec3 p = tex.mesh().vertices[corner.vertex];
  double height = d;
  if (n[upright].dot(tex.up()) > 0.9)
    for (int e : corner.edges) {
      const FeatureEdge& edge = fm.edges[e];
      const Vec3 far = edge.points.front() == p ? edge.points.back() : edge.points.front();
      if (isVertical(tex, edge) && (far - p).dot(tex.up()) > 0) height = inCourses(d, course);
    }
  return tex.add(makeCell(p, n[a], n[upright], n[b], Vec3(d, height, d)), {FeatureKind::Corner, c}) ? 1 : 0;
}

// The point of straight edge e at height z (along up).
Vec3 atHeight(const CellularTexture& tex, const FeatureEdge& e, double z) {
  const Vec3 a = e.points.front(), b = e.points.back();
  const double za = a.dot(tex.up()), zb = b.dot(tex.up());
  return a + (b - a) * ((z - za) / (zb - za));
}

// Outward mitres (docs/cells.md "Corners that are not square"): at a convex straight edge
// whose two planar faces meet at other than a right angle (a hexagonal tower, a wedge),
// boxes cannot turn the corner — one face's box either leaves a gap in the other's layer
// or stands out of it. Instead every course gets a brick on each face, both running to
// the plane through the edge that halves the dihedral angle: each is its face's layer
// from that plane on, the plane's cut keeping the side of the face's own interior, so
// the two meet on the plane with no gap and no overlap. Plumb edges only (a leaning
// edge's level courses are parallelograms, verticalCourses' general case).
struct OutwardMitre {
  bool ok = false;
  MitreCut cut[2];  // the side each face keeps, through the edge
  double start[2] = {0, 0};  // where each face's cell starts along its `away`: the mitre's
                             // farthest point in the layer (where both outer faces meet)
};
// Normals closer than this to square keep the corner bond of boxes.
constexpr double kSquareCos = 1e-6;
OutwardMitre outwardMitreAt(const CellularTexture& tex, const FeatureEdge& edge, const EdgeSides& sd, double d) {
  OutwardMitre m;
  const FeatureMesh& fm = tex.features();
  if (edge.fold != EdgeFold::Convex || edge.shape != EdgeShape::Line || !sd.twoSided) return m;
  if (fm.faces[edge.leftFace].kind != FaceKind::Planar || fm.faces[edge.rightFace].kind != FaceKind::Planar) return m;
  if (std::abs(sd.normal[0].dot(sd.normal[1])) <= kSquareCos) return m;
  if ((sd.normal[0] - sd.normal[1]).norm() < kCoplanarSine) return m;
  for (int i = 0; i < 2; ++i)
    if (std::abs(sd.away[i].dot(tex.up())) > 1e-9) return m;  // leaning
  for (int i = 0; i < 2; ++i) {
    const int o = 1 - i;
    Vec3 n = (sd.normal[i] - sd.normal[o]).normalized();
    if (n.dot(sd.away[i]) > 0) n = -n;
    m.cut[i] = {n, n.dot(sd.point)};
    // Both outer faces (n_i . p = n_o . p = d) meet at x away_i + d n_i: n_o . (x away_i + d n_i) = d.
    const double na = sd.normal[o].dot(sd.away[i]);
    if (std::abs(na) < kCoplanarSine) return OutwardMitre{};
    m.start[i] = std::min(0.0, d * (1 - sd.normal[o].dot(sd.normal[i])) / na);
  }
  m.ok = true;
  return m;
}

// Cells up a vertical edge, in layers [z, z + height(k)) from course base upwards, each
// along the left or right face in turn: length(k) long from where the two faces' layers
// meet, depth d, cut at the end of the face's free run. Where the faces do not meet
// square, each layer gets a mitred cell on both faces instead (OutwardMitre).
int verticalCourses(CellularTexture& tex, int e, double d, bool flip, const std::function<double(int)>& height,
                    const std::function<double(int)>& length, double firstLine) {
  const FeatureEdge& edge = tex.features().edges[e];
  const EdgeSides sd = tex.sidesAt(e, 0.5 * edge.length);
  const double za = edge.points.front().dot(tex.up()), zb = edge.points.back().dot(tex.up());
  const double zlo = std::min(za, zb), zhi = std::max(za, zb);
  auto sAt = [&](double z) { return (z - za) / (zb - za) * edge.length; };
  const double tol = 1e3 * tex.tolerance();
  const OutwardMitre mitre = outwardMitreAt(tex, edge, sd, d);
  int placed = 0;
  double z = firstLine;
  for (int k = 0; z < zhi - tol; ++k) {
    const double h = height(k), z1 = z + h;
    if (z1 > zlo + tol) {
      double s0 = sAt(std::max(z, zlo)), s1 = sAt(std::min(z1, zhi));
      if (s0 > s1) std::swap(s0, s1);
      for (const Interval& gap : tex.edgeMap(e).gaps(s0, s1, tol)) {
        // Back to heights: the gap's bottom and top.
        double g0 = za + (zb - za) * gap.lo / edge.length, g1 = za + (zb - za) * gap.hi / edge.length;
        if (g0 > g1) std::swap(g0, g1);
        const int i = (k + (flip ? 1 : 0)) & 1;
        if (mitre.ok) {
          // Both faces, the course's face a whole length(k) from the edge, the other half
          // of it, so the faces' joints change sides from course to course.
          const Vec3 base = atHeight(tex, edge, g0), top = atHeight(tex, edge, g1);
          for (int side : {i, 1 - i}) {
            const Vec3& away = sd.away[side];
            const double most = side == i ? length(k) : 0.5 * length(k);
            const double far = std::min(most, reachInto(tex, sideFace(edge, sd, side), base, top, away, away, most));
            Cell c = makeCell(base + away * mitre.start[side], away, sd.tangent, sd.normal[side],
                              Vec3(far - mitre.start[side], g1 - g0, d));
            c.profile = c.outline();
            c.cuts.push_back(mitre.cut[side]);
            placed += tex.add(c, {FeatureKind::Edge, e});
          }
          continue;
        }
        const Region r = regionAlong(sd, i, d);
        if (!r.ok) continue;
        const Vec3 base = atHeight(tex, edge, g0), top = atHeight(tex, edge, g1);
        const Vec3& away = sd.away[i];
        // A leaning edge's cells meet the faces' level courses: in their face they are
        // parallelograms with level tops and bottoms, `tall` along the edge; `slope` is
        // how far the bottom drops along the edge per unit along `away`, `level` the
        // level direction in the face with level . away = 1.
        const double rise = sd.tangent.dot(tex.up()), slope = away.dot(tex.up()) / rise;
        const double tall = std::abs(rise - 1) < 1e-12 ? g1 - g0 : (g1 - g0) / rise;
        const Vec3 level = away - slope * sd.tangent;
        const double most = r.lo + length(k);
        const double reach = reachInto(tex, sideFace(edge, sd, i), base, top, away, level, most);
        const double far = std::min(most, std::max(r.hi, reach));
        Cell c = makeCell(base + away * r.lo, away, sd.tangent, sd.normal[i], Vec3(far - r.lo, tall, d));
        if (std::abs(slope) * (far - r.lo) > tol) {
          // Over the edge, in the other face's layer, the course's bounds are square to
          // the edge instead (that face's cells are swept along its tilted normal): the
          // part of the parallelogram there is cut by the square line it crosses, which
          // keeps the cell convex.
          const Polygon2 band{Vec2(0, -slope * r.lo), Vec2(far - r.lo, -slope * far),
                              Vec2(far - r.lo, -slope * far + tall), Vec2(0, -slope * r.lo + tall)};
          c.profile = slope > 0 ? clipHalfPlane(band, Vec2(0, 1), tall) : clipHalfPlane(band, Vec2(0, -1), 0);
          fitToProfile(c);
        }
        placed += tex.add(c, {FeatureKind::Edge, e});
      }
    }
    z = z1;
  }
  return placed;
}

// An outward mitre at a corner for the cells of straight edge e that end there: where e
// (faces F and G) meets another convex straight edge e2 of face F (faces F and H), laid
// the same way (not vertical), at a corner of three edges, and G and H meet at other than
// a right angle (a hexagonal tower's top rim: F the cap, G and H two walls), both edges'
// rows of cells reach past the corner, and they meet on the plane through the corner
// halving the angle between G and H (the third edge's own mitre, OutwardMitre). Where two
// such partners meet e (a hipped roof's apex) there is no one plane: nothing. `into`: e's
// direction from the corner. Returns the cut that e's cells keep, or nothing.
std::optional<MitreCut> cornerMitre(const CellularTexture& tex, int e, int cornerVertex, const Vec3& into) {
  const FeatureMesh& fm = tex.features();
  const FeatureEdge& edge = fm.edges[e];
  const auto it = std::find_if(fm.corners.begin(), fm.corners.end(),
                               [&](const FeatureCorner& c) { return c.vertex == cornerVertex; });
  if (it == fm.corners.end() || it->valence != 3 || edge.fold != EdgeFold::Convex || edge.shape != EdgeShape::Line)
    return {};
  const Vec3 at = tex.mesh().vertices[cornerVertex];
  std::optional<MitreCut> found;
  for (int e2 : it->edges) {
    const FeatureEdge& other = fm.edges[e2];
    if (e2 == e || other.fold != EdgeFold::Convex || other.shape != EdgeShape::Line || other.rightFace < 0 ||
        isVertical(tex, other))
      continue;
    for (int shared : {edge.leftFace, edge.rightFace}) {
      if (shared != other.leftFace && shared != other.rightFace) continue;
      const int g = shared == edge.leftFace ? edge.rightFace : edge.leftFace;
      const int h = shared == other.leftFace ? other.rightFace : other.leftFace;
      if (g == h || fm.faces[g].kind != FaceKind::Planar || fm.faces[h].kind != FaceKind::Planar) continue;
      const Vec3 ng = fm.faces[g].normal, nh = fm.faces[h].normal;
      if (std::abs(ng.dot(nh)) <= kSquareCos || (ng - nh).norm() < kCoplanarSine) continue;
      Vec3 m = (ng - nh).normalized();
      if (m.dot(into) > 0) m = -m;
      if (m.dot(into) > -kCoplanarSine) continue;  // the plane runs along e
      if (found) return {};
      found = MitreCut{m, m.dot(at)};
    }
  }
  return found;
}

// Cell c (a box or a rectangle's prism) of an edge's row, its length axis along the edge
// from the corner (atStart) or towards it, grown past its corner end to the corner's mitre
// plane and cut there.
void mitreAtCorner(Cell& c, const MitreCut& cut, bool atStart) {
  const Vec3 x = c.axes.col(0);
  const double slope = cut.normal.dot(atStart ? x : Vec3(-x));  // < 0: the kept side is along the row
  double grow = 0;
  for (int k = 0; k < 8; ++k) {
    if (((k & 1) != 0) == atStart) continue;  // the corner end's four corners
    grow = std::max(grow, (c.corner(k).dot(cut.normal) - cut.offset) / slope);
  }
  if (atStart) c.origin -= x * grow;
  c.size.x() += grow;
  c.profile = {Vec2(0, 0), Vec2(c.size.x(), 0), Vec2(c.size.x(), c.size.y()), Vec2(0, c.size.y())};
  c.cuts.push_back(cut);
}

// Cells along a non-vertical edge filling the region both layers share, piece lengths
// from `next(remaining)` (the last piece takes what is left). The cells' height axis is
// across the edge on the more upright face; where the region reaches into that face (a
// concave edge at a wall's foot) it is whole courses high, so the wall's courses above
// start level.
int alongEdge(CellularTexture& tex, int e, double d, double course, const std::function<double(double)>& next) {
  const FeatureEdge& edge = tex.features().edges[e];
  const double tol = 1e3 * tex.tolerance();
  int placed = 0;
  for (const Interval& gap : tex.edgeMap(e).gaps(0, edge.length, tol)) {
    for (double s = gap.lo; s < gap.hi - tol;) {
      const double piece = std::min(next(gap.hi - s), gap.hi - s);
      const Vec3 pa = edgeAt(edge, s).point, pb = edgeAt(edge, s + piece).point;
      const EdgeSides sd = tex.sidesAt(e, s + 0.5 * piece);
      const int i = std::abs(sd.away[0].dot(tex.up())) >= std::abs(sd.away[1].dot(tex.up())) ? 0 : 1;
      Region r = regionAlong(sd, i, d);
      if (r.ok && r.hi > tol && std::abs(sd.away[i].dot(tex.up())) > 0.9) r.hi = r.lo + inCourses(r.hi - r.lo, course);
      if (r.ok && (pb - pa).norm() > tol) {
        const Vec3 x = (pb - pa).normalized();
        const Vec3 y = (sd.away[i] - sd.away[i].dot(x) * x).normalized();
        const Vec3 z = x.cross(y).dot(sd.normal[i]) >= 0 ? x.cross(y) : Vec3(-x.cross(y));
        Cell c = makeCell(pa + y * r.lo, x, y, z, Vec3((pb - pa).norm(), r.hi - r.lo, d));
        // At a corner whose walls are not square the row runs on to the mitre there.
        if (s <= tol && !edge.closed)
          if (const auto cut = cornerMitre(tex, e, edge.vertices.front(), x)) mitreAtCorner(c, *cut, true);
        if (s + piece >= edge.length - tol && !edge.closed)
          if (const auto cut = cornerMitre(tex, e, edge.vertices.back(), -x)) mitreAtCorner(c, *cut, false);
        placed += tex.add(c, {FeatureKind::Edge, e});
      }
      s += piece;
    }
  }
  return placed;
}

// Equal pieces close to `length`.
std::function<double(double)> evenPieces(double length) {
  return [length](double remaining) {
    const double n = std::max(1.0, std::round(remaining / length));
    return remaining / n;
  };
}

// The strips of face f a generator fills, bottom to top, with their course numbers:
// on a face that rises (a wall, a roof, a tower) the courses of height h counted from
// the texture's course base, so that they continue around every corner; on a level face,
// or `fromLowest` (a roof's rows start at its eaves), strips of h from its lowest v.
struct Strip {
  double v0, v1;
  int course;
};
std::vector<Strip> strips(const CellularTexture& tex, int f, double h, bool fromLowest = false) {
  const FeatureFace& face = tex.features().faces[f];
  const FaceOccupancy& map = tex.faceMap(f);
  std::vector<Strip> out;
  if (map.empty()) return out;
  double rise = 0, v0OfBase = 0;  // v = (height - course base) / rise + v0OfBase
  if (face.kind == FaceKind::Planar) {
    rise = face.vAxis.dot(tex.up());
    v0OfBase = (tex.courseBase() - face.origin.dot(tex.up())) / (rise != 0 ? rise : 1);
  } else if (face.kind == FaceKind::Cylindrical) {
    rise = face.axis.dot(tex.up());
    v0OfBase = (tex.courseBase() - face.centre.dot(tex.up())) / (rise != 0 ? rise : 1);
  }
  const double lo = map.lo().y(), hi = map.hi().y();
  if (rise > 0.5 && !fromLowest) {
    const double step = h / rise;
    const int k0 = int(std::floor((lo - v0OfBase) / step + 1e-9));
    for (int k = k0; v0OfBase + k * step < hi - map.tolerance(); ++k) {
      const double a = std::max(lo, v0OfBase + k * step), b = std::min(hi, v0OfBase + (k + 1) * step);
      if (b > a + map.tolerance()) out.push_back({a, b, k});
    }
  } else {
    for (int k = 0; lo + k * h < hi - map.tolerance(); ++k) out.push_back({lo + k * h, std::min(hi, lo + (k + 1) * h), k});
  }
  return out;
}

// A cell on face f over the parameter rectangle [u, u + len] x [v0, v1], depth d.
Cell faceCell(const FeatureFace& face, double u, double len, double v0, double v1, double d) {
  if (face.kind == FaceKind::Planar)
    return makeCell(faceAt(face, {u, v0}).point, face.uAxis, face.vAxis, face.normal, Vec3(len, v1 - v0, d));
  // Cylindrical: the chord box of the piece.
  const FaceFrame a = faceAt(face, {u, v0}), b = faceAt(face, {u + len, v0}), m = faceAt(face, {u + 0.5 * len, v0});
  const Vec3 x = (b.point - a.point).normalized(), y = a.v;
  Vec3 z = m.normal - m.normal.dot(x) * x - m.normal.dot(y) * y;
  z.normalize();
  return makeCell(a.point, x, y, z, Vec3((b.point - a.point).norm(), v1 - v0, d));
}

// The cells of one run of a course: the closer it starts with (0: none) and the lengths
// that repeat after it.
struct CoursePattern {
  double closer = 0;
  std::array<double, 2> cycle{};  // one or two lengths (a Flemish course: stretcher, header)
  size_t cycleLength = 1;
};
// In a bond (generators.h Bond); the closer is for a run that starts at a free end.
CoursePattern coursePattern(const BrickSize& b, bool odd) {
  const double l = b.length, w = b.depth;  // a stretcher, a header
  switch (b.bond) {
    case Bond::Running: return {odd ? 0.5 * l : 0, {l}};
    case Bond::English: return odd ? CoursePattern{0.5 * w, {w}} : CoursePattern{0, {l}};
    case Bond::Flemish:
      return odd ? CoursePattern{std::max(0.0, 0.5 * (l - w)), {w, l}, 2} : CoursePattern{0, {l, w}, 2};
    case Bond::Header: return {odd ? 0.5 * w : 0, {w}};
  }
  return {0, {l}};
}

// Mitres (docs/cells.md "Mitred cells"): where planar face f meets another planar face at
// a concave straight edge (a valley, an inside corner), the two faces' layers of cells
// overlap over the edge. A cell of f reaching into that overlap keeps the part nearer
// f's plane than the other face's: the plane through the edge halving the dihedral
// angle, so the cells of both faces meet on it at a diagonal, where the overlap guard
// would otherwise shorten or drop the later face's cells and leave the valley bare. The
// plane goes on past the edge's ends and through the solid behind the other face: a
// cell is cut only where it stands in front of the other face (its foot nowhere behind
// that face's plane) and crosses the plane beside the edge.
void mitreAtValleys(const CellularTexture& tex, int f, Cell& c) {
  const FeatureMesh& fm = tex.features();
  const FeatureFace& face = fm.faces[f];
  if (face.kind != FaceKind::Planar) return;
  const double tol = 1e3 * tex.tolerance();
  const size_t footCorners = c.isBox() ? 4 : c.profile.size();  // forEachVertex: the foot first
  for (int ei : face.edges) {
    const FeatureEdge& e = fm.edges[ei];
    if (e.fold != EdgeFold::Concave || e.shape != EdgeShape::Line || e.rightFace < 0 || e.length <= 0) continue;
    const int g = e.leftFace == f ? e.rightFace : e.leftFace;
    if (g == f || fm.faces[g].kind != FaceKind::Planar) continue;
    const Vec3 ng = fm.faces[g].normal, apart = face.normal - ng;
    if (apart.norm() < kCoplanarSine) continue;
    const Vec3 m = apart.normalized(), p0 = e.points.front(), along = (e.points.back() - p0) / e.length;
    const double offset = m.dot(p0);
    bool crosses = false, behind = false;
    size_t k = 0;
    c.forEachVertex([&](const Vec3& p) {
      if (k++ < footCorners && (p - p0).dot(ng) < -tol) behind = true;
      const double s = (p - p0).dot(along);
      if (m.dot(p) > offset + tol && s > -tol && s < e.length + tol) crosses = true;
    });
    if (behind || !crosses) continue;
    if (c.isBox()) c.profile = c.outline();
    c.cuts.push_back({m, offset});
  }
}

// Places the cell over the parameter rectangle [u, u + len] x [v0, v1] of face f: a box
// where all of it is free, else the exact clip of the rectangle against free space (the
// face's outline minus the claims, where it crosses a rake, a hip or a claim's slanted
// side) — one clipped cell where the free part is convex, one per convex piece where a
// claim bites a notch out of it — each mitred over a valley. Returns the cells placed.
int clippedCell(CellularTexture& tex, int f, double u, double len, double v0, double v1, double depth) {
  const FeatureFace& face = tex.features().faces[f];
  const FaceOccupancy& map = tex.faceMap(f);
  const double minArea = 1e3 * map.tolerance() * (v1 - v0);
  const Polygon2 rect{Vec2(u, v0), Vec2(u + len, v0), Vec2(u + len, v1), Vec2(u, v1)};
  const std::vector<Polygon2> pieces = map.freePieces(rect, minArea);
  double free = 0;
  for (const Polygon2& p : pieces) free += signedArea(p);
  const Cell box = faceCell(face, u, len, v0, v1, depth);
  const FeatureRef on{FeatureKind::Face, f};
  if (free >= len * (v1 - v0) - minArea) {
    Cell whole = box;
    mitreAtValleys(tex, f, whole);
    return tex.add(std::move(whole), on) ? 1 : 0;
  }
  if (pieces.empty()) return 0;
  const Polygon2 whole = convexUnion(pieces, minArea * double(pieces.size()));
  const std::vector<Polygon2> parts = whole.empty() ? pieces : std::vector<Polygon2>{whole};
  const double stretch = box.size.x() / len;  // a cylinder's chord over its arc
  int placed = 0;
  for (const Polygon2& part : parts) {
    Cell c = box;
    for (const Vec2& q : part) c.profile.push_back(Vec2((q.x() - u) * stretch, q.y() - v0));
    fitToProfile(c);
    mitreAtValleys(tex, f, c);
    placed += tex.add(c, on) ? 1 : 0;
  }
  return placed;
}

// Lays one run [run.lo, run.hi] of a strip in the pattern: the closer first, then the
// cycle, the last two cells shared evenly rather than leaving a sliver. Each cell is
// clipped to what is free (clippedCell).
int layRun(CellularTexture& tex, int f, const Interval& run, double v0, double v1, const CoursePattern& course,
           double depth) {
  const double tol = 1e3 * tex.faceMap(f).tolerance();
  int placed = 0;
  size_t next = 0;
  bool last = false;  // the two bricks that share the end are being laid
  bool closer = course.closer > 0;
  for (double u = run.lo; run.hi - u > tol;) {
    const double rest = run.hi - u;
    double len;
    if (closer) {
      len = std::min(course.closer, rest);
    } else if (last) {
      len = rest;
    } else {
      const double want = course.cycle[next % course.cycleLength];
      const double after = course.cycle[++next % course.cycleLength];
      // Less than half the following brick would be left after this one: share.
      const double share = after == want ? 1.5 * want : want + 0.5 * after;
      if (rest <= want) len = rest;
      else if (rest <= share) len = 0.5 * rest, last = true;
      else len = want;
    }
    closer = false;
    placed += clippedCell(tex, f, u, len, v0, v1, depth);
    u += len;
  }
  return placed;
}

// Lays face f in courses of height h, cells `depth` deep, each run of a course in the
// pattern pattern(course number, where the run starts, whether that is on the face's own
// outline) gives. A run is as far as the course's free space reaches (at its widest,
// where a rake or a hip cuts across it), and its cells are clipped to that free space.
int coursedFace(CellularTexture& tex, int f, double h, double depth, bool fromLowest,
                const std::function<CoursePattern(int, double, bool)>& pattern) {
  const FaceOccupancy& map = tex.faceMap(f);
  const double tol = 1e3 * map.tolerance();
  int placed = 0;
  for (const Strip& st : strips(tex, f, h, fromLowest)) {
    const std::vector<Interval> outline = map.insideReach(st.v0, st.v1, tol);
    auto atBoundary = [&](double u) {
      for (const Interval& i : outline)
        if (std::abs(i.lo - u) < tol || std::abs(i.hi - u) < tol) return true;
      return false;
    };
    for (const Interval& run : map.reachRuns(st.v0, st.v1, tol))
      placed += layRun(tex, f, run, st.v0, st.v1, pattern(st.course, run.lo, atBoundary(run.lo)), depth);
  }
  return placed;
}

int bondedFace(CellularTexture& tex, int f, const BrickSize& b) {
  // A free end on the face's own outline starts with the course's closer, so the bond
  // shifts from course to course.
  return coursedFace(tex, f, b.height, b.depth, false, [&](int course, double, bool atOutline) {
    CoursePattern p = coursePattern(b, ((course + (b.flip ? 1 : 0)) & 1) != 0);
    if (!atOutline) p.closer = 0;
    return p;
  });
}

bool planarOrCylindrical(const FeatureFace& f) { return f.kind != FaceKind::Freeform; }

void positive(double v, const char* what) {
  if (!(std::isfinite(v) && v > 0)) throw std::invalid_argument(std::string("the ") + what + " must be a positive number");
}

}  // namespace

void checkSize(const BrickSize& s) {
  positive(s.length, "brick length");
  positive(s.height, "course height");
  positive(s.depth, "brick depth");
}

void checkSize(const TileSize& s) {
  positive(s.width, "tile width");
  positive(s.exposure, "tile exposure");
  positive(s.thickness, "tile thickness");
}

void checkSize(const StoneSize& s) {
  positive(s.grid, "stone grid");
  positive(s.maxWidth, "largest stone width");
  positive(s.maxHeight, "largest stone height");
  positive(s.depth, "stone depth");
  if (s.maxWidth < s.grid || s.maxHeight < s.grid)
    throw std::invalid_argument("the largest stone must be at least one grid square");
}

int layBricks(CellularTexture& tex, FeatureRef on, const BrickSize& b) {
  checkSize(b);
  const FeatureMesh& fm = tex.features();
  switch (on.kind) {
    case FeatureKind::Corner: return cornerBlock(tex, on.index, b.depth, b.height);
    case FeatureKind::Edge: {
      const FeatureEdge& e = fm.edges[on.index];
      if (e.rightFace < 0 || e.length <= 0) return 0;  // the faces' bricks run to a free end
      if (isVertical(tex, e)) {
        const double base = tex.courseBase();
        const double zmin = std::min(e.points.front().dot(tex.up()), e.points.back().dot(tex.up()));
        const double first = base + b.height * std::floor((zmin - base) / b.height + 1e-9);
        const int k0 = int(std::llround((first - base) / b.height));
        return verticalCourses(
            tex, on.index, b.depth, ((k0 & 1) != 0) != b.flip, [&](int) { return b.height; },
            [&](int) { return b.length; }, first);
      }
      return alongEdge(tex, on.index, b.depth, b.height, evenPieces(b.length));
    }
    case FeatureKind::Face:
      if (!planarOrCylindrical(fm.faces[on.index])) return 0;
      return bondedFace(tex, on.index, b);
  }
  return 0;
}

int layHeaders(CellularTexture& tex, FeatureRef on, const BrickSize& b) {
  checkSize(b);
  if (on.kind != FeatureKind::Edge) return 0;
  const FeatureEdge& e = tex.features().edges[on.index];
  if (e.rightFace < 0) return 0;
  const double tol = 1e3 * tex.tolerance();
  int placed = 0;
  for (const Interval& gap : tex.edgeMap(on.index).gaps(0, e.length, tol)) {
    const auto piece = evenPieces(b.length);
    for (double s = gap.lo; s < gap.hi - tol;) {
      const double len = std::min(piece(gap.hi - s), gap.hi - s);
      const EdgeSides sd = tex.sidesAt(on.index, s + 0.5 * len);
      // On the more upright face: the wall under a sill, beside a jamb.
      const int i = std::abs(sd.normal[0].dot(tex.up())) <= std::abs(sd.normal[1].dot(tex.up())) ? 0 : 1;
      const Region r = regionAlong(sd, i, b.depth);
      const Vec3 pa = edgeAt(e, s).point, pb = edgeAt(e, s + len).point;
      if (r.ok && (pb - pa).norm() > tol) {
        const Vec3 x = (pb - pa).normalized();
        const Vec3 z = sd.normal[i];
        const Vec3 y = sd.away[i];
        placed += tex.add(makeCell(pa + y * r.lo, x, y, z, Vec3((pb - pa).norm(), b.height, b.depth)),
                          {FeatureKind::Edge, on.index});
      }
      s += len;
    }
  }
  return placed;
}

namespace {

// How far from the arc's axis the cells already laid on arc `edge` reach (their farthest
// corner); 0 when the edge holds no cell yet. A ring starting there overlaps none of them:
// a voussoir's outer face is flat, its corners stand out past its middle.
double outerRingRadius(const CellularTexture& tex, int edge) {
  const FeatureEdge& e = tex.features().edges[edge];
  double outer = 0;
  for (const Cell& c : tex.cells()) {
    if (c.feature.kind != FeatureKind::Edge || c.feature.index != edge) continue;
    for (const Vec3& p : c.vertices()) {
      const Vec3 d = p - e.centre;
      outer = std::max(outer, (d - d.dot(e.axis) * e.axis).norm());
    }
  }
  return outer;
}

// One ring of `count` voussoirs over the arc's whole sweep, from radius r0 outward by the
// brick's length, each as wide as a course (b.height) at r0, in the wall (normal n).
int voussoirRing(CellularTexture& tex, int edge, double from, double to, double r0, const Vec3& n,
                 const BrickSize& b) {
  const FeatureEdge& e = tex.features().edges[edge];
  const double sweep = (to - from) / e.radius;  // radians
  const int count = std::max(1, int(std::lround(sweep * r0 / b.height)));
  const double step = sweep / count;
  int placed = 0;
  for (int k = 0; k < count; ++k) {
    const double a = from / e.radius + (k + 0.5) * step, half = 0.5 * step;
    const Vec3 radial = std::cos(a) * e.ref + std::sin(a) * e.axis.cross(e.ref);
    const Vec3 tangent = e.axis.cross(radial);
    const double w = r0 * std::tan(half);
    const Vec3 origin = e.centre + r0 * radial - w * tangent;
    placed += tex.add(makeCell(origin, radial, tangent, n, Vec3(b.length, 2 * w, b.depth)),
                      {FeatureKind::Edge, edge});
  }
  return placed;
}

}  // namespace

int layArchBricks(CellularTexture& tex, FeatureRef on, const BrickSize& b) {
  checkSize(b);
  if (on.kind != FeatureKind::Edge) return layBricks(tex, on, b);
  const FeatureEdge& e = tex.features().edges[on.index];
  if (e.shape != EdgeShape::Arc || e.rightFace < 0) return layBricks(tex, on, b);
  // The wall is the face the arc lies in (its normal along the arc's axis); the other is
  // the intrados. Voussoirs run radially from where the two layers meet into the wall.
  const EdgeSides sd = tex.sidesAt(on.index, 0.5 * e.length);
  const int wall = std::abs(sd.normal[0].dot(e.axis)) >= std::abs(sd.normal[1].dot(e.axis)) ? 0 : 1;
  const Vec3 n = sd.normal[wall];
  const Vec3 mid = edgeAt(e, 0.5 * e.length).point;
  // Inward: the intrados faces the centre, so the shared region lies inside the radius.
  const bool inside = sd.normal[1 - wall].dot(e.centre - mid) > 0;
  // A second ArchBricks on the same arc lays the next ring outward, from where the rings
  // before it end, over the whole sweep (the edge's own map is theirs already).
  if (const double outer = outerRingRadius(tex, on.index); outer > 0)
    return voussoirRing(tex, on.index, 0, e.length, outer, n, b);
  const double r0 = inside ? e.radius - b.depth : e.radius;
  const double tol = 1e3 * tex.tolerance();
  int placed = 0;
  // The first ring: in each stretch of the edge still free, voussoirs as wide as a course
  // along the edge (at radius e.radius).
  for (const Interval& gap : tex.edgeMap(on.index).gaps(0, e.length, tol)) {
    const BrickSize atEdge{b.length, b.height * r0 / e.radius, b.depth};
    placed += voussoirRing(tex, on.index, gap.lo, gap.hi, r0, n, atEdge);
  }
  return placed;
}

int layStones(CellularTexture& tex, FeatureRef on, const StoneSize& st, RandomStream& rng) {
  checkSize(st);
  const FeatureMesh& fm = tex.features();
  const double g = st.grid;
  const int maxRows = std::max(1, int(std::floor(st.maxHeight / g + 1e-9)));
  const int maxCols = std::max(1, int(std::floor(st.maxWidth / g + 1e-9)));
  auto randomLength = [&](double) { return g * (1 + std::floor(rng.next() * maxCols)); };
  switch (on.kind) {
    case FeatureKind::Corner: return cornerBlock(tex, on.index, st.depth, g);
    case FeatureKind::Edge: {
      const FeatureEdge& e = fm.edges[on.index];
      if (e.rightFace < 0 || e.length <= 0) return 0;
      if (!isVertical(tex, e)) return alongEdge(tex, on.index, st.depth, g, randomLength);
      const double base = tex.courseBase();
      const double zmin = std::min(e.points.front().dot(tex.up()), e.points.back().dot(tex.up()));
      const double first = base + g * std::floor((zmin - base) / g + 1e-9);
      std::vector<double> heights, lengths;  // drawn once per layer, in order
      auto draw = [&](std::vector<double>& v, int k, int most) {
        while (int(v.size()) <= k) v.push_back(g * (1 + std::floor(rng.next() * most)));
        return v[k];
      };
      return verticalCourses(
          tex, on.index, st.depth, false, [&](int k) { return draw(heights, k, maxRows); },
          [&](int k) { return std::max(st.maxWidth * 0.5, draw(lengths, k, maxCols)); }, first);
    }
    case FeatureKind::Face: {
      const FeatureFace& face = fm.faces[on.index];
      if (!planarOrCylindrical(face)) return 0;
      const FaceOccupancy& map = tex.faceMap(on.index);
      const std::vector<Strip> rows = strips(tex, on.index, g);
      if (rows.empty()) return 0;
      const double u0 = map.lo().x();
      const int cols = std::max(1, int(std::ceil((map.hi().x() - u0) / g - 1e-9)));
      // free[r][c]: grid square (c, r) lies wholly in a free run of its row.
      std::vector<std::vector<uint8_t>> free(rows.size(), std::vector<uint8_t>(size_t(cols), 0));
      std::vector<std::pair<int, int>> squares;
      const double tol = 1e3 * map.tolerance();
      for (size_t r = 0; r < rows.size(); ++r)
        for (const Interval& run : map.freeRuns(rows[r].v0, rows[r].v1, tol))
          for (int c = std::max(0, int(std::floor((run.lo - u0) / g + 1e-9))); c < cols; ++c) {
            const double a = u0 + c * g, b = std::min(u0 + (c + 1) * g, map.hi().x());
            if (a < run.lo - tol) continue;
            if (b > run.hi + tol) break;
            free[r][c] = 1;
            squares.push_back({int(r), c});
          }
      for (size_t k = squares.size(); k > 1; --k)  // a seeded Fisher–Yates shuffle
        std::swap(squares[k - 1], squares[size_t(rng.next() * double(k))]);
      int placed = 0;
      for (const auto& [r0, c0] : squares) {
        if (!free[r0][c0]) continue;
        int rows1 = r0 + 1, cols1 = c0 + 1;  // exclusive ends
        for (;;) {
          const bool right = cols1 - c0 < maxCols && cols1 < cols && [&] {
            for (int r = r0; r < rows1; ++r)
              if (!free[r][cols1]) return false;
            return true;
          }();
          const bool up = rows1 - r0 < maxRows && rows1 < int(rows.size()) && [&] {
            for (int c = c0; c < cols1; ++c)
              if (!free[rows1][c]) return false;
            return true;
          }();
          if (!right && !up) break;
          if (right && (!up || rng.next() < 0.5)) ++cols1;
          else ++rows1;
        }
        for (int r = r0; r < rows1; ++r)
          for (int c = c0; c < cols1; ++c) free[r][c] = 0;
        const double a = u0 + c0 * g, b = std::min(u0 + cols1 * g, map.hi().x());
        placed += tex.add(faceCell(face, a, b - a, rows[r0].v0, rows[rows1 - 1].v1, st.depth), on, 1.0);
      }
      return placed;
    }
  }
  return 0;
}

int layShingles(CellularTexture& tex, FeatureRef on, const TileSize& t) {
  checkSize(t);
  if (on.kind == FeatureKind::Corner) return 0;
  if (on.kind == FeatureKind::Edge) {
    const FeatureEdge& e = tex.features().edges[on.index];
    if (e.rightFace < 0 || e.length <= 0 || isVertical(tex, e)) return 0;  // the rows run to it
    return alongEdge(tex, on.index, t.thickness, t.exposure, evenPieces(t.width));
  }
  if (!planarOrCylindrical(tex.features().faces[on.index])) return 0;
  // The joints of a row lie on a grid of the tile width across the whole face, odd rows
  // shifted by half a tile, wherever a run starts (at the eaves' end or at a hip's
  // tiles): a run starts with the tile cut to the next joint.
  const double u0 = tex.faceMap(on.index).lo().x(), tol = 1e3 * tex.faceMap(on.index).tolerance();
  return coursedFace(tex, on.index, t.exposure, t.thickness, true, [&](int row, double start, bool) {
    const double offset = (row & 1) ? 0.5 * t.width : 0;
    const double into = std::fmod(start - u0 - offset + 2 * t.width, t.width);  // past the last joint
    const double cut = t.width - into;
    return CoursePattern{cut > tol && cut < t.width - tol ? cut : 0, {t.width}};
  });
}

}  // namespace fgsg::rt::cells
