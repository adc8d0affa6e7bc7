// An instance transform as glTF places things: translation, rotation (a unit quaternion)
// and scale along the rotated axes — what a node's TRS and EXT_mesh_gpu_instancing's
// TRANSLATION / ROTATION / SCALE can express. A 4x4 transform whose linear part has
// orthogonal columns is one; a shear (a scale along axes other than the asset's own) or a
// flattened axis is not, and a mirror only as a node's matrix (a negative scale).
#pragma once

#include <array>

namespace fgsg::rt::output {

struct Trs {
  std::array<double, 3> translation{};
  std::array<double, 4> rotation{0, 0, 0, 1};  // x y z w, w >= 0
  std::array<double, 3> scale{1, 1, 1};
};

enum class TrsFit : unsigned char {
  Rigid,       // rotation and positive scales: instanced
  Mirrored,    // orthogonal but det < 0: the scale's x is negative (a node with a matrix)
  Sheared,     // columns not orthogonal, or a projective last row: no TRS (baked)
  Degenerate,  // a column (nearly) zero or not finite: the asset flattened (baked)
};

// Columns closer to orthogonal than this (the cosine of their angle) count as orthogonal:
// the scopes' rotations are orthonormal to rounding, while a real shear is far from it.
inline constexpr double kOrthogonalCosine = 1e-9;
// A column shorter than this relative to the longest flattens its axis.
inline constexpr double kFlatScale = 1e-12;

// Decomposes the column-major `m` (Instance::transform); `trs` is set for Rigid and
// Mirrored and recomposes `m` to rounding. `flatAxis` (0..2, or -1): an axis along which
// the placed mesh has no extent (a CGA face's own geometry lies in its scope's z = 0), so
// that m may flatten it: its zero column is then taken as the unit normal of the other
// two (right-handed), which places the mesh alike and turns its normals as the flattened
// output does.
TrsFit decomposeTrs(const std::array<double, 16>& m, Trs& trs, int flatAxis = -1);

// The column-major 4x4 matrix of `trs`.
std::array<double, 16> composeTrs(const Trs& trs);

}  // namespace fgsg::rt::output
