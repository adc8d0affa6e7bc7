// Fitting lines, circles, planes and cylinders to features, and mapping between their
// parameter spaces and the world (feature_param.h).
#include "runtime/cells/feature_param.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace fgsg::rt::cells {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kRadiansPerDegree = kPi / 180;

double polylineLength(const std::vector<Vec3>& p) {
  double l = 0;
  for (size_t i = 0; i + 1 < p.size(); ++i) l += (p[i + 1] - p[i]).norm();
  return l;
}

// Into (-pi, pi].
double wrapAngle(double a) {
  while (a <= -kPi) a += 2 * kPi;
  while (a > kPi) a -= 2 * kPi;
  return a;
}

// The circle through three points: false when they are (nearly) collinear.
bool circumcircle(const Vec3& p0, const Vec3& p1, const Vec3& p2, Vec3& centre, double& radius) {
  const Vec3 a = p1 - p0, b = p2 - p0, n = a.cross(b);
  const double n2 = n.squaredNorm();
  if (n2 <= 1e-24 * a.squaredNorm() * b.squaredNorm()) return false;
  centre = p0 + (a.squaredNorm() * b - b.squaredNorm() * a).cross(n) / (2 * n2);
  radius = (p0 - centre).norm();
  return true;
}

bool fitLine(FeatureEdge& e, double tol) {
  if (e.closed) return false;
  const Vec3 a = e.points.front(), d = e.points.back() - a;
  const double len = d.norm();
  if (len <= tol) return false;
  const Vec3 t = d / len;
  double last = -tol;
  for (const Vec3& p : e.points) {
    const double s = (p - a).dot(t);
    if (s < last - tol || (p - a - s * t).norm() > tol) return false;  // off the line, or back
    last = std::max(last, s);
  }
  e.shape = EdgeShape::Line;
  e.length = len;
  return true;
}

bool fitArc(FeatureEdge& e, double tol) {
  const auto& p = e.points;
  const size_t n = p.size();
  if (n < 4) return false;  // a circle through three points is no evidence of an arc
  const size_t i1 = e.closed ? (n - 1) / 3 : (n - 1) / 2, i2 = e.closed ? 2 * (n - 1) / 3 : n - 1;
  Vec3 c;
  double r;
  if (!circumcircle(p[0], p[i1], p[i2], c, r)) return false;
  Vec3 axis = Vec3::Zero();
  for (size_t i = 0; i + 1 < n; ++i) axis += (p[i] - c).cross(p[i + 1] - c);
  if (axis.norm() == 0) return false;
  axis.normalize();
  for (const Vec3& q : p)
    if (std::abs((q - c).norm() - r) > tol || std::abs((q - c).dot(axis)) > tol) return false;
  Vec3 ref = p[0] - c;
  ref = (ref - ref.dot(axis) * axis).normalized();
  const Vec3 e2 = axis.cross(ref);
  double sweep = 0, prev = 0;
  for (size_t i = 1; i < n; ++i) {
    const Vec3 q = p[i] - c;
    const double a = std::atan2(q.dot(e2), q.dot(ref));
    const double step = wrapAngle(a - prev);
    if (step <= 0) return false;  // the chain must run one way round
    sweep += step;
    prev = a;
  }
  if (e.closed ? std::abs(sweep - 2 * kPi) > 1e-6 : sweep >= 2 * kPi) return false;
  e.shape = EdgeShape::Arc;
  e.centre = c;
  e.radius = r;
  e.axis = axis;
  e.ref = ref;
  e.length = r * (e.closed ? 2 * kPi : sweep);
  return true;
}

// The segment of the chain nearest to q, and the arc length of q's foot on it.
std::pair<size_t, double> nearestSegment(const FeatureEdge& e, const Vec3& q) {
  double best = INFINITY, at = 0, start = 0;
  size_t seg = 0;
  for (size_t i = 0; i + 1 < e.points.size(); ++i) {
    const Vec3 a = e.points[i], d = e.points[i + 1] - a;
    const double len = d.norm();
    const double t = len > 0 ? std::clamp((q - a).dot(d) / (len * len), 0.0, 1.0) : 0.0;
    const double dist = (a + t * d - q).norm();
    if (dist < best) best = dist, seg = i, at = start + t * len;
    start += len;
  }
  return {seg, at};
}

Vec3 normalAcross(const FeatureEdge& e, size_t seg, const Vec3& tangent) {
  const Vec3 n = e.segmentNormals[std::min(seg, e.segmentNormals.size() - 1)];
  const Vec3 perp = n - n.dot(tangent) * tangent;
  return perp.norm() > 1e-12 ? Vec3(perp.normalized()) : n;
}

std::vector<int> faceVertices(const FeatureFace& f, const surface::SurfaceMesh& m) {
  std::vector<int> vs;
  for (int t : f.triangles)
    for (int v : m.faces[t]) vs.push_back(v);
  std::sort(vs.begin(), vs.end());
  vs.erase(std::unique(vs.begin(), vs.end()), vs.end());
  return vs;
}

bool fitPlane(FeatureFace& f, const surface::SurfaceMesh& m, const FeatureOptions& o,
              const std::vector<int>& verts, const Vec3& centroid) {
  const double cosTol = std::cos(o.planarDegrees * kRadiansPerDegree) - 1e-12;
  for (int t : f.triangles)
    if (m.faceNormals[t].dot(f.normal) < cosTol) return false;
  const Vec3 n = f.normal;
  const Vec3 up = o.up - o.up.dot(n) * n;
  if (up.norm() > std::sin(o.directionDegrees * kRadiansPerDegree) && up.norm() > 1e-9) {
    f.vAxis = up.normalized();  // a wall or a roof: v up the face, u horizontal
    f.uAxis = f.vAxis.cross(n);
  } else {  // a floor or a ceiling: u along world X (or Y) projected
    Vec3 x = Vec3::UnitX() - Vec3::UnitX().dot(n) * n;
    if (x.norm() < 0.5) x = Vec3::UnitY() - Vec3::UnitY().dot(n) * n;
    f.uAxis = x.normalized();
    f.vAxis = n.cross(f.uAxis);
  }
  double umin = INFINITY, vmin = INFINITY;
  for (int v : verts) {
    const Vec3 d = m.vertices[v] - centroid;
    umin = std::min(umin, d.dot(f.uAxis));
    vmin = std::min(vmin, d.dot(f.vAxis));
  }
  f.origin = centroid + umin * f.uAxis + vmin * f.vAxis;
  f.kind = FaceKind::Planar;
  return true;
}

bool fitCylinder(FeatureFace& f, const surface::SurfaceMesh& m, const FeatureOptions& o,
                 const std::vector<int>& verts, const Vec3& centroid) {
  // The axis is the direction the normals are (nearly) all perpendicular to.
  Mat3 M = Mat3::Zero();
  for (int t : f.triangles) M += m.faceAreas[t] * m.faceNormals[t] * m.faceNormals[t].transpose();
  Eigen::SelfAdjointEigenSolver<Mat3> eig(M);
  Vec3 axis = eig.eigenvectors().col(0).normalized();
  const double sinTol = std::sin(o.planarDegrees * kRadiansPerDegree) + 1e-12;
  for (int t : f.triangles)
    if (std::abs(m.faceNormals[t].dot(axis)) > sinTol) return false;
  int big = 0;
  axis.cwiseAbs().maxCoeff(&big);
  const double upness = axis.dot(o.up);
  if (upness < -1e-9 || (std::abs(upness) <= 1e-9 && axis[big] < 0)) axis = -axis;
  // Kasa's algebraic circle fit in the plane across the axis.
  Vec3 e1 = std::abs(axis.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  e1 = (e1 - e1.dot(axis) * axis).normalized();
  const Vec3 e2 = axis.cross(e1);
  Eigen::MatrixXd A(verts.size(), 3);
  Eigen::VectorXd b(verts.size());
  double hmin = INFINITY;
  for (size_t i = 0; i < verts.size(); ++i) {
    const Vec3 d = m.vertices[verts[i]] - centroid;
    const double x = d.dot(e1), y = d.dot(e2);
    A.row(Eigen::Index(i)) << x, y, 1;
    b[Eigen::Index(i)] = -(x * x + y * y);
    hmin = std::min(hmin, d.dot(axis));
  }
  const Eigen::Vector3d s = A.colPivHouseholderQr().solve(b);
  const double cx = -s[0] / 2, cy = -s[1] / 2, r2 = cx * cx + cy * cy - s[2];
  if (!(r2 > 0) || !std::isfinite(r2)) return false;
  const double r = std::sqrt(r2);
  const Vec3 centre = centroid + cx * e1 + cy * e2 + hmin * axis;
  double outwardness = 0;
  for (int v : verts) {
    Vec3 d = m.vertices[v] - centre;
    d -= d.dot(axis) * axis;
    if (std::abs(d.norm() - r) > o.fitTolerance * r) return false;
  }
  for (int t : f.triangles) {
    const auto& tri = m.faces[t];
    Vec3 d = (m.vertices[tri[0]] + m.vertices[tri[1]] + m.vertices[tri[2]]) / 3 - centre;
    outwardness += m.faceAreas[t] * m.faceNormals[t].dot(d - d.dot(axis) * axis);
  }
  // Angles are measured from the face's middle (so a partial cylinder does not straddle
  // the seam at +-pi), or from its first vertex for a full one.
  Vec3 ref = centroid - centre;
  ref -= ref.dot(axis) * axis;
  if (ref.norm() < 0.5 * r) {
    ref = m.vertices[verts[0]] - centre;
    ref -= ref.dot(axis) * axis;
  }
  f.kind = FaceKind::Cylindrical;
  f.axis = axis;
  f.centre = centre;
  f.radius = r;
  f.ref = ref.normalized();
  f.outward = outwardness >= 0;
  return true;
}

}  // namespace

void fitEdge(FeatureEdge& e, const FeatureOptions& o) {
  const double L = polylineLength(e.points);
  const double tol = o.fitTolerance * L;
  e.length = L;
  e.shape = EdgeShape::Polyline;
  e.direction = EdgeDirection::Curved;
  if (fitLine(e, tol)) {
    const double c = std::abs((e.points.back() - e.points.front()).normalized().dot(o.up.normalized()));
    e.direction = c <= std::sin(o.directionDegrees * kRadiansPerDegree)  ? EdgeDirection::Horizontal
                  : c >= std::cos(o.directionDegrees * kRadiansPerDegree) ? EdgeDirection::Vertical
                                                                : EdgeDirection::Slanted;
  } else {
    fitArc(e, tol);
  }
}

void fitFace(FeatureFace& f, const surface::SurfaceMesh& m, const FeatureOptions& o) {
  Vec3 n = Vec3::Zero(), centroid = Vec3::Zero();
  f.area = 0;
  for (int t : f.triangles) {
    const auto& tri = m.faces[t];
    n += m.faceAreas[t] * m.faceNormals[t];
    centroid += m.faceAreas[t] * (m.vertices[tri[0]] + m.vertices[tri[1]] + m.vertices[tri[2]]) / 3;
    f.area += m.faceAreas[t];
  }
  f.normal = n.norm() > 1e-12 * std::max(f.area, 1e-300) ? Vec3(n.normalized()) : m.faceNormals[f.triangles[0]];
  if (f.area > 0) centroid /= f.area;
  else centroid = m.vertices[m.faces[f.triangles[0]][0]];
  const auto verts = faceVertices(f, m);
  f.kind = FaceKind::Freeform;
  if (!fitPlane(f, m, o, verts, centroid)) fitCylinder(f, m, o, verts, centroid);
}

EdgeFrame edgeAt(const FeatureEdge& e, double s) {
  if (e.closed && e.length > 0) {
    s = std::fmod(s, e.length);
    if (s < 0) s += e.length;
  } else {
    s = std::clamp(s, 0.0, e.length);
  }
  EdgeFrame f;
  if (e.shape == EdgeShape::Line) {
    f.tangent = (e.points.back() - e.points.front()).normalized();
    f.point = e.points.front() + s * f.tangent;
    f.normal = normalAcross(e, nearestSegment(e, f.point).first, f.tangent);
  } else if (e.shape == EdgeShape::Arc) {
    const double a = s / e.radius;
    const Vec3 e2 = e.axis.cross(e.ref);
    f.point = e.centre + e.radius * (std::cos(a) * e.ref + std::sin(a) * e2);
    f.tangent = -std::sin(a) * e.ref + std::cos(a) * e2;
    f.normal = normalAcross(e, nearestSegment(e, f.point).first, f.tangent);
  } else {
    double start = 0;
    size_t i = 0;
    for (; i + 2 < e.points.size(); ++i) {
      const double len = (e.points[i + 1] - e.points[i]).norm();
      if (start + len >= s) break;
      start += len;
    }
    const Vec3 d = e.points[i + 1] - e.points[i];
    const double len = d.norm();
    f.tangent = len > 0 ? Vec3(d / len) : Vec3::UnitX();
    f.point = e.points[i] + std::clamp(s - start, 0.0, len) * f.tangent;
    f.normal = normalAcross(e, i, f.tangent);
  }
  return f;
}

double projectOnEdge(const FeatureEdge& e, const Vec3& p) {
  if (e.shape == EdgeShape::Line) {
    const Vec3 t = (e.points.back() - e.points.front()).normalized();
    return std::clamp((p - e.points.front()).dot(t), 0.0, e.length);
  }
  if (e.shape == EdgeShape::Arc) {
    const Vec3 q = p - e.centre;
    double a = std::atan2(q.dot(e.axis.cross(e.ref)), q.dot(e.ref));
    if (a < 0) a += 2 * kPi;
    const double sweep = e.length / e.radius;
    if (!e.closed && a > sweep) a = (a - sweep < 2 * kPi - a) ? sweep : 0;  // nearer end
    return std::min(e.radius * a, e.length);
  }
  return nearestSegment(e, p).second;
}

FaceFrame faceAt(const FeatureFace& f, const Vec2& param) {
  FaceFrame fr;
  if (f.kind == FaceKind::Planar) {
    fr.point = f.origin + param.x() * f.uAxis + param.y() * f.vAxis;
    fr.u = f.uAxis;
    fr.v = f.vAxis;
    fr.normal = f.normal;
  } else if (f.kind == FaceKind::Cylindrical) {
    const double a = param.x() / f.radius;
    const Vec3 e2 = f.axis.cross(f.ref);
    const Vec3 radial = std::cos(a) * f.ref + std::sin(a) * e2;
    fr.point = f.centre + param.y() * f.axis + f.radius * radial;
    fr.u = -std::sin(a) * f.ref + std::cos(a) * e2;
    fr.v = f.axis;
    fr.normal = f.outward ? radial : Vec3(-radial);
  } else {
    throw std::invalid_argument("faceAt: a freeform face has no closed-form parameterisation");
  }
  return fr;
}

Vec2 projectOnFace(const FeatureFace& f, const Vec3& p) {
  if (f.kind == FaceKind::Planar) {
    const Vec3 d = p - f.origin;
    return {d.dot(f.uAxis), d.dot(f.vAxis)};
  }
  if (f.kind == FaceKind::Cylindrical) {
    const Vec3 d = p - f.centre;
    const double h = d.dot(f.axis);
    double a = std::atan2(d.dot(f.axis.cross(f.ref)), d.dot(f.ref));
    if (a >= kPi) a -= 2 * kPi;  // [-pi, pi)
    return {f.radius * a, h};
  }
  throw std::invalid_argument("projectOnFace: a freeform face has no closed-form parameterisation");
}

}  // namespace fgsg::rt::cells
