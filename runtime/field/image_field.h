// A tensor field from a picture (FGSG Fig. 12, curvilinear mosaics): the picture is laid
// over the surface seen from above (its bounding box's XY extent, image row 0 at +Y) and
// at every vertex the field is the structure tensor of the picture's gradients, turned a
// quarter: its major eigenvector runs along the picture's edges, so tiles placed along
// the field follow the outlines. Flat regions take the direction of nearby edges through
// a wide smoothing window and then Laplacian smoothing on the surface.
#pragma once

#include "runtime/field/tangent_field.h"

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace fgsg::rt::field {

// The picture's brightness, for the `intensity` query and for building the field, and
// its colours, for the `rgb` query.
class Picture {
 public:
  // Any format stb_image reads (PNG, JPEG, PGM ...); false with a message otherwise.
  bool load(const std::string& path, std::string& error);
  int width() const { return width_; }
  int height() const { return height_; }
  // Brightness in [0, 1] at image coordinates (x right, y down, in pixels), bilinear,
  // clamped at the border.
  double at(double x, double y) const;
  // The brightness under the surface point p, by the surface's XY bounding box.
  double under(const SurfaceMesh& mesh, const Vec3& p) const;
  // The colour (r, g, b in [0, 1], bilinear) under p, likewise.
  Vec3 colourUnder(const SurfaceMesh& mesh, const Vec3& p) const;

  std::vector<float>& values() { return grey_; }
  const std::vector<float>& values() const { return grey_; }

 private:
  int width_ = 0, height_ = 0;
  std::vector<float> grey_;  // row-major, row 0 at the top
  std::array<std::vector<float>, 3> channels_;  // red, green, blue, likewise
};

// Gaussian scales (in pixels) of the structure tensor: the gradient's pre-smoothing, and
// the window over which gradient outer products are averaged (wide, so that flat areas
// inherit the direction of the nearest outlines).
constexpr double kGradientSigma = 1.0;
constexpr double kWindowSigma = 6.0;
// Laplacian smoothing iterations on the surface after sampling.
constexpr int kImageFieldSmoothing = 20;

TangentField imageField(std::shared_ptr<const TangentFrames> frames, const Picture& picture);

}  // namespace fgsg::rt::field
