#include "runtime/field/singularities.h"

#include <algorithm>
#include <cmath>
#include <complex>

namespace fgsg::rt::field {

namespace {

using Complex = std::complex<double>;
constexpr double kPi = 3.14159265358979323846;
// A vertex value this much smaller than the field's largest counts as exactly zero.
constexpr double kZeroRelative = 1e-12;
// Index +1 of a vector field: the angle between the field and the radial direction
// (or the spiral angle of the Jacobian's eigenvalues) below this is a node, above
// 90 degrees minus it a centre, a focus in between.
constexpr double kNodeAngle = kPi / 8;

// The value whose winding gives the index: the vector, or the deviatoric part.
Complex vectorOf(const Vec2& v) { return {v.x(), v.y()}; }
Complex deviatoricOf(const Mat2& t) {
  return {0.5 * (t(0, 0) - t(1, 1)), 0.5 * (t(0, 1) + t(1, 0))};
}

// Rounded number of turns of a closed loop of values.
int winding(const Complex* z, int n) {
  double total = 0;
  for (int k = 0; k < n; ++k) total += std::arg(z[(k + 1) % n] / z[k]);
  return int(std::lround(total / (2 * kPi)));
}

// Node, focus or centre from the angle between the field and the radial direction
// (folded into [0, pi/2]).
Degeneracy::Kind plusOneKind(double spiral) {
  if (spiral < kNodeAngle) return Degeneracy::Node;
  if (spiral > kPi / 2 - kNodeAngle) return Degeneracy::Centre;
  return Degeneracy::Focus;
}

struct Values {
  const TangentField& field;
  std::vector<double> magnitude;  // |vector| or |deviatoric| per vertex
  double zero = 0;

  explicit Values(const TangentField& f) : field(f), magnitude(f.vertexCount()) {
    double largest = 0;
    for (size_t v = 0; v < magnitude.size(); ++v) {
      magnitude[v] = f.isTensor() ? std::abs(deviatoricOf(f.vertexTensor(int(v))))
                                  : f.vertexVector(int(v)).norm();
      largest = std::max(largest, magnitude[v]);
    }
    zero = kZeroRelative * largest;
  }
  bool isZero(int v) const { return magnitude[v] <= zero; }
  // Corner k of face f in the face frame.
  Complex corner(int f, int k) const {
    const int v = field.mesh().faces[f][k];
    return field.isTensor()
               ? deviatoricOf(field.frames().tensorToFace(f, k, field.vertexTensor(v)))
               : vectorOf(field.frames().vectorToFace(f, k, field.vertexVector(v)));
  }
};

int faceWinding(const Values& values, int f, Complex z[3]) {
  const auto& t = values.field.mesh().faces[f];
  for (int k = 0; k < 3; ++k) {
    if (values.isZero(t[k])) return 0;
    z[k] = values.corner(f, k);
  }
  return winding(z, 3);
}

// Where the affine interpolation of z vanishes, clamped into the face.
Vec3 zeroOf(const Complex z[3]) {
  Mat2 A;
  A << (z[1] - z[0]).real(), (z[2] - z[0]).real(), (z[1] - z[0]).imag(), (z[2] - z[0]).imag();
  if (std::abs(A.determinant()) <= 0) return Vec3::Constant(1.0 / 3);
  const Vec2 b = A.inverse() * Vec2(-z[0].real(), -z[0].imag());
  Vec3 bary(1 - b.x() - b.y(), b.x(), b.y());
  bary = bary.cwiseMax(0.0);
  return bary / bary.sum();
}

Degeneracy faceDegeneracy(const Values& values, int f, int turns, const Complex z[3]) {
  Degeneracy d;
  d.face = f;
  d.at.face = f;
  d.at.bary = zeroOf(z);
  if (values.field.isTensor()) {
    d.indexTimesTwo = turns;
    d.kind = turns == 1 ? Degeneracy::Wedge : turns == -1 ? Degeneracy::Trisector
                                                          : Degeneracy::Other;
    return d;
  }
  d.indexTimesTwo = 2 * turns;
  if (turns == -1) {
    d.kind = Degeneracy::Saddle;
  } else if (turns == 1) {
    // The Jacobian's eigenvalues: real for a node, imaginary for a centre.
    Mat2 dv;
    dv << z[1].real() - z[0].real(), z[2].real() - z[0].real(), z[1].imag() - z[0].imag(),
        z[2].imag() - z[0].imag();
    const Mat2 J = dv * values.field.frames().faceInverseEdges(f);
    const double half = 0.5 * J.trace(), disc = half * half - J.determinant();
    d.kind = disc >= 0 ? Degeneracy::Node
                       : plusOneKind(std::atan2(std::sqrt(-disc), std::abs(half)));
  }
  return d;
}

// A vertex with a zero value: the winding around its one-ring, in its own frame (each
// neighbour's value carried over by the vertex-to-vertex transport, so every link vertex
// has one value and the angle changes add up to whole turns).
bool vertexDegeneracy(const Values& values, int v, Degeneracy& d) {
  const TangentField& field = values.field;
  const SurfaceMesh& mesh = field.mesh();
  const TangentFrames& F = field.frames();
  if (mesh.boundaryVertex[v] || mesh.vertexFace[v] < 0) return false;
  const int power = field.isTensor() ? 2 : 1;
  auto inFrame = [&](int a) {
    int r = F.neighbourBegin(v);
    while (F.neighbour(r) != a) ++r;
    const Complex z = field.isTensor() ? deviatoricOf(field.vertexTensor(a))
                                       : vectorOf(field.vertexVector(a));
    return std::pow(F.neighbourToVertex(r), power) * z;
  };
  double total = 0;
  Complex radial(0, 0);
  for (int f : mesh.facesAround(v)) {
    const int k = mesh.cornerOf(f, v);
    const int a = mesh.faces[f][(k + 1) % 3], b = mesh.faces[f][(k + 2) % 3];
    if (values.isZero(a) || values.isZero(b)) return false;
    const Complex za = inFrame(a), zb = inFrame(b);
    total += std::arg(zb / za);  // a -> b turns counter-clockwise about v
    // The field against the direction of the spoke to a (doubled for a tensor).
    const Vec2 s = F.vertexFrame(v).toLocal(mesh.vertices[a] - mesh.vertices[v]);
    const Complex spoke = std::pow(Complex(s.x(), s.y()) / s.norm(), power);
    radial += za / std::abs(za) * std::conj(spoke);
  }
  const int turns = int(std::lround(total / (2 * kPi)));
  if (turns == 0) return false;
  const int f = mesh.vertexFace[v];
  d.face = f;
  d.at.face = f;
  d.at.bary = Vec3::Zero();
  d.at.bary[mesh.cornerOf(f, v)] = 1;
  d.indexTimesTwo = field.isTensor() ? turns : 2 * turns;
  if (d.indexTimesTwo < 0) {
    d.kind = d.indexTimesTwo == -1 ? Degeneracy::Trisector : Degeneracy::Saddle;
  } else if (d.indexTimesTwo == 1) {
    d.kind = Degeneracy::Wedge;
  } else {
    double spiral = std::abs(std::arg(radial)) / power;
    if (spiral > kPi / 2) spiral = kPi - spiral;
    d.kind = plusOneKind(spiral);
  }
  return true;
}

}  // namespace

int faceIndexTimesTwo(const TangentField& field, int face) {
  return indexSumTimesTwo(field.degeneraciesIn(face));
}

std::vector<Degeneracy> findDegeneracies(const TangentField& field) {
  const Values values(field);
  const SurfaceMesh& mesh = field.mesh();
  std::vector<Degeneracy> out;
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    Complex z[3];
    const int turns = faceWinding(values, int(f), z);
    if (turns != 0) out.push_back(faceDegeneracy(values, int(f), turns, z));
  }
  for (size_t v = 0; v < mesh.vertexCount(); ++v) {
    Degeneracy d;
    if (values.isZero(int(v)) && vertexDegeneracy(values, int(v), d)) out.push_back(d);
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const Degeneracy& a, const Degeneracy& b) { return a.face < b.face; });
  return out;
}

int indexSumTimesTwo(const std::vector<Degeneracy>& degeneracies) {
  int sum = 0;
  for (const Degeneracy& d : degeneracies) sum += d.indexTimesTwo;
  return sum;
}

}  // namespace fgsg::rt::field
