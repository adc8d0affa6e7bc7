#include "runtime/field/image_field.h"

#include "runtime/field/smooth.h"
#include "runtime/synthesis/image_reader.h"

#include <algorithm>
#include <cmath>

namespace fgsg::rt::field {
namespace {

// Separable Gaussian blur of a w x h image, the kernel cut at 3 sigma, edges clamped.
std::vector<float> blur(const std::vector<float>& in, int w, int h, double sigma) {
  const int r = std::max(1, static_cast<int>(std::ceil(3 * sigma)));
  std::vector<double> k(2 * r + 1);
  double sum = 0;
  for (int i = -r; i <= r; ++i) sum += k[i + r] = std::exp(-0.5 * i * i / (sigma * sigma));
  for (double& x : k) x /= sum;
  std::vector<float> tmp(in.size()), out(in.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double s = 0;
      for (int i = -r; i <= r; ++i) s += k[i + r] * in[size_t(y) * w + std::clamp(x + i, 0, w - 1)];
      tmp[size_t(y) * w + x] = static_cast<float>(s);
    }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double s = 0;
      for (int i = -r; i <= r; ++i) s += k[i + r] * tmp[size_t(std::clamp(y + i, 0, h - 1)) * w + x];
      out[size_t(y) * w + x] = static_cast<float>(s);
    }
  return out;
}

double bilinear(const std::vector<float>& img, int w, int h, double x, double y) {
  x = std::clamp(x, 0.0, double(w - 1));
  y = std::clamp(y, 0.0, double(h - 1));
  const int x0 = std::min(static_cast<int>(x), w - 2 < 0 ? 0 : w - 2);
  const int y0 = std::min(static_cast<int>(y), h - 2 < 0 ? 0 : h - 2);
  const int x1 = std::min(x0 + 1, w - 1), y1 = std::min(y0 + 1, h - 1);
  const double fx = x - x0, fy = y - y0;
  auto p = [&](int xx, int yy) { return double(img[size_t(yy) * w + xx]); };
  return (1 - fy) * ((1 - fx) * p(x0, y0) + fx * p(x1, y0)) + fy * ((1 - fx) * p(x0, y1) + fx * p(x1, y1));
}

// Image coordinates (pixels) of a world point, by the mesh's XY bounding box.
void pixelOf(const SurfaceMesh& m, const Vec3& p, int w, int h, double& x, double& y) {
  const Vec3 lo = m.boundsMin, hi = m.boundsMax;
  const double u = hi.x() > lo.x() ? (p.x() - lo.x()) / (hi.x() - lo.x()) : 0.5;
  const double v = hi.y() > lo.y() ? (hi.y() - p.y()) / (hi.y() - lo.y()) : 0.5;
  x = u * (w - 1);
  y = v * (h - 1);
}

}  // namespace

bool Picture::load(const std::string& path, std::string& error) {
  synthesis::RgbImage rgb;
  if (!synthesis::readRgbImage(path, rgb, error)) return false;
  if (rgb.width < 2 || rgb.height < 2) {
    error = path + ": the picture must be at least 2 x 2 pixels";
    return false;
  }
  width_ = rgb.width;
  height_ = rgb.height;
  grey_.resize(size_t(width_) * height_);
  for (auto& channel : channels_) channel.resize(grey_.size());
  for (size_t i = 0; i < grey_.size(); ++i) {
    for (int c = 0; c < 3; ++c) channels_[c][i] = static_cast<float>(rgb.rgb[3 * i + c] / 255.0);
    grey_[i] = static_cast<float>(  // Rec. 709 luma
        (0.2126 * rgb.rgb[3 * i] + 0.7152 * rgb.rgb[3 * i + 1] + 0.0722 * rgb.rgb[3 * i + 2]) / 255.0);
  }
  return true;
}

double Picture::at(double x, double y) const { return bilinear(grey_, width_, height_, x, y); }

double Picture::under(const SurfaceMesh& mesh, const Vec3& p) const {
  double x, y;
  pixelOf(mesh, p, width_, height_, x, y);
  return at(x, y);
}

Vec3 Picture::colourUnder(const SurfaceMesh& mesh, const Vec3& p) const {
  double x, y;
  pixelOf(mesh, p, width_, height_, x, y);
  return {bilinear(channels_[0], width_, height_, x, y), bilinear(channels_[1], width_, height_, x, y),
          bilinear(channels_[2], width_, height_, x, y)};
}

TangentField imageField(std::shared_ptr<const TangentFrames> frames, const Picture& picture) {
  const int w = picture.width(), h = picture.height();
  const std::vector<float> smooth1 = blur(picture.values(), w, h, kGradientSigma);
  // Gradient outer products, x right and y up (world orientation), averaged over the window.
  std::vector<float> gxx(smooth1.size()), gxy(smooth1.size()), gyy(smooth1.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      auto at = [&](int xx, int yy) { return smooth1[size_t(std::clamp(yy, 0, h - 1)) * w + std::clamp(xx, 0, w - 1)]; };
      const double gx = 0.5 * (at(x + 1, y) - at(x - 1, y));
      const double gy = -0.5 * (at(x, y + 1) - at(x, y - 1));  // rows run down, y up
      const size_t i = size_t(y) * w + x;
      gxx[i] = float(gx * gx);
      gxy[i] = float(gx * gy);
      gyy[i] = float(gy * gy);
    }
  const auto sxx = blur(gxx, w, h, kWindowSigma), sxy = blur(gxy, w, h, kWindowSigma),
             syy = blur(gyy, w, h, kWindowSigma);
  TangentField field(frames, FieldType::Tensor);
  const SurfaceMesh& mesh = frames->mesh();
  // Normalised so the strongest outline has eigenvalue 1 (the queries stay readable).
  double scale = 0;
  for (size_t i = 0; i < sxx.size(); ++i) scale = std::max(scale, double(sxx[i] + syy[i]));
  if (scale <= 0) scale = 1;
  for (size_t v = 0; v < mesh.vertexCount(); ++v) {
    double x, y;
    pixelOf(mesh, mesh.vertices[v], w, h, x, y);
    const double a = bilinear(sxx, w, h, x, y) / scale, b = bilinear(sxy, w, h, x, y) / scale,
                 c = bilinear(syy, w, h, x, y) / scale;
    // J = [[a, b], [b, c]] has the gradient as its major direction; (tr J) I - J has the
    // same eigenvectors with the eigenvalues swapped: the edge direction becomes major.
    Mat3 t = Mat3::Zero();
    t(0, 0) = c;
    t(0, 1) = t(1, 0) = -b;
    t(1, 1) = a;
    field.setVertexTensorWorld(static_cast<int>(v), t);
  }
  smooth(field, kImageFieldSmoothing);
  return field;
}

}  // namespace fgsg::rt::field
