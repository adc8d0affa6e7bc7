// The scope of a shape (CGA / FGSG): an oriented box with position P, orthonormal axes
// X Y Z (the columns of `axes`) and size S. A shape's local point (u, v, w) in [0,1]^3
// lies at P + axes * (S .* (u, v, w)) in world space.
#pragma once

#include <array>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <cstdint>
#include <cstring>

namespace fgsg::rt {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Mat4 = Eigen::Matrix4d;

struct Scope {
  Vec3 P = Vec3::Zero();
  Mat3 axes = Mat3::Identity();  // columns: X, Y, Z
  Vec3 S = Vec3::Ones();
  // On a surface (FGSG §4.3) the scope stands on a surface point: a face (-1: no
  // surface, the plane) and barycentric coordinates, lifted `lift` along the normal.
  int32_t face = -1;
  // On-mesh marching (Buron et al.): the march point this scope stands on (a node of the
  // derivation's march graph; -1: none yet) and, for a Marching's Extruded part, the
  // segment it spans (-1: none), along which its terminals are bent.
  int32_t marchNode = -1;
  Vec3 bary = Vec3::Zero();
  double lift = 0.0;
  int32_t marchSegment = -1;
  // Color(r, g, b): the colour of the instances placed from this scope on, inherited by
  // the shapes it creates; `colored` false: each instance takes its symbol's colour.
  bool colored = false;
  // CityEngine's trim attribute (attr_trim), bits of what differs from its defaults: 1
  // vertical trim planes off (set(trim.vertical, false)), 2 horizontal ones on. In the
  // padding after `colored`.
  uint8_t trim = 0;
  // CityEngine's pivot (setPivot) and trim planes (comp(f)): 1 + the index of the
  // derivation's shape frame (backend/engine/shape_frames.h) this shape and the shapes it
  // creates have; 0: the start shape's object system, no trim planes. In the padding
  // after `colored`: the scope's size, which compiled code is built for, stays the same.
  uint16_t pivot = 0;
  std::array<float, 3> color{0.8f, 0.8f, 0.8f};
  int32_t colorIndex = 0;  // ABOP's `'`: the turtle's colour index (0: Color or the symbols' colours)
  // Texture(...): 1 + the index of the derivation's texture projection the leaves output
  // from this scope on are textured by (backend/commands/texture_commands.h); 0: none.
  uint32_t projection = 0;
  // CGA's split.index / split.total and comp.index / comp.total: this shape's place among
  // the parts of the last split (and comp) above it, inherited by the shapes it creates.
  // comp.sel: 1 + the index of the selector that chose it among the derivation's comp
  // selectors (ir::Module::compSelectors); 0: none (""). Beside comp.total in its word
  // (a selector takes fewer than 2^24 components) so that the scope keeps its size.
  struct Place {
    int32_t splitIndex = 0, splitTotal = 0, compIndex = 0;
    uint32_t compTotal : 24 = 0;
    uint32_t compSel : 8 = 0;
  } place;
  // Material(...) (CGA's material attributes): 1 + the index of the derivation's finish
  // (roughness, metallic, opacity, normal map) the instances placed from this scope on
  // take (backend/commands/texture_commands.h); 0: the default one. In the tail padding:
  // the scope's size, which compiled code is built for, stays the same.
  uint32_t finish = 0;

  Vec3 X() const { return axes.col(0); }
  Vec3 Y() const { return axes.col(1); }
  Vec3 Z() const { return axes.col(2); }

  // Maps the unit cube [0,1]^3 onto the scope box (axes scaled by S, then translated).
  Mat4 unitBoxToWorld() const {
    Mat4 m = Mat4::Identity();
    m.block<3, 3>(0, 0) = axes * S.asDiagonal();
    m.block<3, 1>(0, 3) = P;
    return m;
  }
  // World position of local coordinates given in scope units (not normalised).
  Vec3 toWorld(const Vec3& local) const { return P + axes * local; }
};

// Compiled code reads and writes P and axes in place (backend/codegen/direct_codegen.cpp).
static_assert(sizeof(Vec3) == 24 && sizeof(Mat3) == 72, "Eigen's fixed-size types hold their doubles");
static_assert(sizeof(Scope) == 208, "rt::Scope's size: compiled libraries check it (runtime/abi.h scopeSize)");

// T(x, y, z) on the plane: the origin moves by x X + y Y + z Z. Written out operation by
// operation, so compiled code repeats it bit for bit (the build turns off floating-point
// contraction, which would fuse these into FMAs on some CPUs).
inline void translateLocal(Scope& s, double x, double y, double z) {
  for (int k = 0; k < 3; ++k) s.P[k] = s.P[k] + ((s.axes(k, 0) * x + s.axes(k, 1) * y) + s.axes(k, 2) * z);
}

// cos and sin of an angle in degrees, remembered: grammars turn by a few angles over and
// over. A derivation owns one memo (no thread-local state, which costs a call per access
// in position-independent code); results are exactly std::cos/std::sin's.
// cos and sin of an angle in degrees, as every turn of a scope computes them.
inline void cosSinDegrees(double degrees, double& c, double& s) {
  const double r = degrees * 3.14159265358979323846 / 180.0;
  c = std::cos(r);
  s = std::sin(r);
}

class TrigMemo {
 public:
  void cosSin(double degrees, double& c, double& s) {
    uint64_t bits;
    std::memcpy(&bits, &degrees, sizeof bits);
    Entry& e = memo_[(bits * 0x9e3779b97f4a7c15ull) >> 58];  // all bits, sign included
    if (e.bits != bits) {
      e.bits = bits;
      cosSinDegrees(degrees, e.c, e.s);
    }
    c = e.c;
    s = e.s;
  }

 private:
  struct Entry {
    uint64_t bits = 0;  // the angle's bit pattern: -0 and +0 are different keys
    double c = 1, s = 0;
  };
  Entry memo_[64];
};

// Rotates the scope's axes about its own local axis 0/1/2 by the angle whose cosine and
// sine are given (the CGA and FGSG convention: Rz turns X towards Y). Only the two axes
// in the plane of rotation move.
inline void rotateLocal(Scope& s, int axis, double c, double sn) {
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  const Vec3 a = s.axes.col(i), b = s.axes.col(j);
  s.axes.col(i) = c * a + sn * b;
  s.axes.col(j) = c * b - sn * a;
}

inline void rotateLocal(Scope& s, int axis, double degrees) {
  const double r = degrees * 3.14159265358979323846 / 180.0;
  rotateLocal(s, axis, std::cos(r), std::sin(r));
}

// The centre of an instance's unit box in world space, from its unit-box-to-world map.
inline Vec3 instanceCentre(const Mat4& unitBoxToWorld) {
  return (unitBoxToWorld * Eigen::Vector4d(0.5, 0.5, 0.5, 1.0)).head<3>();
}

}  // namespace fgsg::rt

namespace fgsg::rt {

// Turns the scope's axes by `degrees` about a world direction through the scope's
// origin (RS: about the surface normal; on the plane, its Z).
inline void rotateAboutNormal(Scope& s, const Vec3& normal, double degrees) {
  const double r = degrees * 3.14159265358979323846 / 180.0;
  s.axes = Eigen::AngleAxisd(r, normal.normalized()).toRotationMatrix() * s.axes;
}

}  // namespace fgsg::rt
