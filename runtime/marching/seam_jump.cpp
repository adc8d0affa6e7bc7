// Leaving a chart (Buron et al. §5, cases B-D of Fig. 3): which indirection pointer to
// follow (§5.1), where exactly to land, and how the marching direction turns (§5.2).
#include "runtime/marching/marching_surface_impl.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace fgsg::rt::marching {

namespace {

// The texel with a pointer for the chart is looked for along the marching line this far
// past the exit, in steps this fine (a chart's conservative texels reach about one
// texel past its border, the band of indirection texels lies just beyond).
constexpr double kProbeTexels = 4;
constexpr double kProbeStep = 0.25;
// §5.1 compares the candidates' targets as seen from the current position P_cur; the
// march's exact stand-in is a point on the path this many texel lengths before the exit.
constexpr double kReferenceBackTexels = 2;
// Pointers tried (best first) before the mesh's own neighbour is taken, and looked at.
constexpr int kMaxLandingTries = 6;
constexpr int kMaxCandidates = 64;
// A landing back in the same chart this close (texels) to the exit would only bounce.
constexpr double kMinSelfJumpTexels = 0.5;

bool hasPointerFor(const GeometryImage& img, int texel, int chart) {
  for (const IndirectionPointer& p : img.pointers(texel))
    if (p.chart == chart) return true;
  return false;
}

// §5.2 made exact: the direction keeps its components along the seam edge and across it
// (in the face's plane), so it keeps its angle with the seam; on a fold that is the
// rotation about the edge that unfolds one face onto the other. The paper estimates the
// seam's tangent from K border texels on each side; the mesh's own edge is exact.
Vec2 turnAcross(const MarchingSurface::Impl& s, int f, int edge, int h, const Vec2& d) {
  const auto& mesh = s.mesh;
  const Vec3 d3 = s.triangles[f].toSurface * d;
  const Vec3 nf = mesh.faceNormals[f], nh = mesh.faceNormals[h];
  const Vec3 e = (mesh.vertices[mesh.faces[f][(edge + 1) % 3]] - mesh.vertices[mesh.faces[f][edge]]).normalized();
  Vec3 eh = e - e.dot(nh) * nh;
  Vec3 turned;
  if (eh.norm() > 1e-9) {
    eh.normalize();
    turned = d3.dot(e) * eh + d3.dot(nf.cross(e)) * nh.cross(eh);
  } else {  // the edge stands along h's normal (a landing at a vertex only): project
    turned = d3 - d3.dot(nh) * nh;
  }
  Vec2 dh = s.triangles[h].toImage * turned;
  if (!(dh.norm() > 0) || !dh.allFinite()) dh = s.triangles[h].toImage * (d3 - d3.dot(nh) * nh);
  return dh.norm() > 0 && dh.allFinite() ? Vec2(dh.normalized()) : Vec2(1, 0);
}

}  // namespace

bool jumpAcrossSeam(const MarchingSurface::Impl& s, int f, int edge, const Vec3& bary, const Vec2& d, SeamJump& out) {
  const ImageTriangle& t = s.triangles[f];
  const GeometryImage& img = s.image;
  const int chart = t.chart;
  const Vec3 P = surfacePoint(s.mesh, ChartPoint{f, bary});
  const Vec2 x = t.imagePoint(bary);

  // P0: the first texel past the exit holding a pointer for this chart (Fig. 3 B, or
  // the binary search of C and D, here a short scan since the exit is known exactly);
  // P_near: the last texel of the chart before it.
  int first = -1, near = img.texelAt(x);
  for (double k = 0; k <= kProbeTexels; k += kProbeStep) {
    const int texel = img.texelAt(x + k * d);
    if (hasPointerFor(img, texel, chart)) {
      first = texel;
      break;
    }
    if (img.chart(texel) == chart) near = texel;
  }
  // §5.1: the candidates are the pointers for this chart around P0 and P_near (fixed
  // buffers: a jump happens often, from many threads).
  std::array<int, kMaxCandidates> targets;
  int count = 0;
  auto collect = [&](int centre, int radius) {
    const int n = img.size(), cx = centre % n, cy = centre / n;
    for (int y = std::max(0, cy - radius); y <= std::min(n - 1, cy + radius); ++y)
      for (int x2 = std::max(0, cx - radius); x2 <= std::min(n - 1, cx + radius); ++x2)
        for (const IndirectionPointer& p : img.pointers(img.index(x2, y)))
          if (p.chart == chart && p.target >= 0 && count < kMaxCandidates &&
              std::find(targets.begin(), targets.begin() + count, p.target) == targets.begin() + count)
            targets[count++] = p.target;
  };
  if (first >= 0) collect(first, 1);
  collect(near, 1);
  if (count == 0) collect(near, 2);

  // ... best first: the target whose direction from P_cur is closest to the marching
  // direction r (P_cur a point of the path just before the exit).
  const Vec3 r = (t.toSurface * d).normalized();
  const Vec3 from = P - kReferenceBackTexels * t.texelLength * r;
  std::array<std::pair<double, int>, kMaxCandidates> ranked;
  for (int i = 0; i < count; ++i)
    ranked[i] = {-(img.position(targets[i]).cast<double>() - from).normalized().dot(r), targets[i]};
  std::sort(ranked.begin(), ranked.begin() + count);

  // The pointer says which chart and where about; the landing is the exact seam point
  // there, so the path stays continuous to rounding whatever the resolution.
  for (int i = 0; i < std::min(count, kMaxLandingTries); ++i) {
    const int target = ranked[i].second;
    ChartPoint landing;
    if (!landNear(s.mesh, s.triangles, img.face(target), P, s.landingTolerance, landing)) continue;
    const ImageTriangle& lt = s.triangles[landing.face];
    if (lt.chart == chart && (lt.imagePoint(landing.bary) - x).norm() < kMinSelfJumpTexels) continue;
    out.landing = landing;
    out.viaPointer = true;
    out.dir = turnAcross(s, f, edge, landing.face, d);
    return true;
  }
  // No pointer landed on the exit point: a slit in the chart narrower than a texel (no
  // indirection texel in it), charts touching without a gutter, a pointer into a chart
  // that holds the exit point only far away. The mesh's own neighbour across the edge
  // is exact.
  const int g = s.mesh.neighbours[f][edge];
  if (g < 0) return false;  // the surface's own boundary
  out.landing = ChartPoint{g, baryAcross(s.mesh, f, edge, bary, g)};
  out.viaPointer = false;
  out.dir = turnAcross(s, f, edge, g, d);
  return true;
}

}  // namespace fgsg::rt::marching
