#include "runtime/field/smooth.h"

#include <complex>

namespace fgsg::rt::field {

namespace {

// The field as plain arrays: complex values (a vector, or a tensor's deviatoric part
// (t11 - t22) / 2 + i t12) and, for tensors, the mean eigenvalue, which does not turn.
// Complex products are written out: std::complex's operator* checks for infinities.
struct SmoothedValues {
  std::vector<double> re, im, mean;
};

// One Jacobi sweep: out = in + step * (mean of transported neighbours - in).
void sweep(const TangentFrames& frames, const std::vector<double>& rotRe,
           const std::vector<double>& rotIm, const SmoothedValues& in, SmoothedValues& out,
           const SmoothOptions& o) {
  const int n = int(frames.vertexCount());
  const bool tensor = !in.mean.empty();
  for (int v = 0; v < n; ++v) {
    if (o.deadline && (v & 255) == 0) o.deadline->check();
    const int begin = frames.neighbourBegin(v), end = frames.neighbourEnd(v);
    if (begin == end || (o.locked && (*o.locked)[v])) {
      out.re[v] = in.re[v];
      out.im[v] = in.im[v];
      if (tensor) out.mean[v] = in.mean[v];
      continue;
    }
    double re = 0, im = 0, mean = 0;
    for (int i = begin; i < end; ++i) {
      const int j = frames.neighbour(i);
      re += rotRe[i] * in.re[j] - rotIm[i] * in.im[j];
      im += rotRe[i] * in.im[j] + rotIm[i] * in.re[j];
      if (tensor) mean += in.mean[j];
    }
    const double inv = 1.0 / (end - begin);
    out.re[v] = in.re[v] + o.step * (re * inv - in.re[v]);
    out.im[v] = in.im[v] + o.step * (im * inv - in.im[v]);
    if (tensor) out.mean[v] = in.mean[v] + o.step * (mean * inv - in.mean[v]);
  }
}

}  // namespace

void smooth(TangentField& field, int iterations, const SmoothOptions& options) {
  if (iterations <= 0) return;
  const TangentFrames& frames = field.frames();
  const size_t n = field.vertexCount();
  const bool tensor = field.isTensor();
  // A neighbour's vector turns by the transport, a deviatoric part by its square.
  const size_t ring = n ? size_t(frames.neighbourEnd(int(n) - 1)) : 0;
  std::vector<double> rotRe(ring), rotIm(ring);
  for (size_t i = 0; i < ring; ++i) {
    Rot2 r = frames.neighbourToVertex(int(i));
    if (tensor) r = r * r;
    rotRe[i] = r.real();
    rotIm[i] = r.imag();
  }
  SmoothedValues a, b;
  for (SmoothedValues* x : {&a, &b}) {
    x->re.resize(n);
    x->im.resize(n);
    if (tensor) x->mean.resize(n);
  }
  for (size_t v = 0; v < n; ++v) {
    if (tensor) {
      const Mat2& t = field.vertexTensor(int(v));
      a.re[v] = 0.5 * (t(0, 0) - t(1, 1));
      a.im[v] = t(0, 1);
      a.mean[v] = 0.5 * (t(0, 0) + t(1, 1));
    } else {
      a.re[v] = field.vertexVector(int(v)).x();
      a.im[v] = field.vertexVector(int(v)).y();
    }
  }
  for (int it = 0; it < iterations; ++it) {
    sweep(frames, rotRe, rotIm, a, b, options);
    std::swap(a, b);
  }
  if (tensor) {
    std::vector<Mat2> out(n);
    for (size_t v = 0; v < n; ++v)  // mean +- (h, b): [[m + h, b], [b, m - h]]
      out[v] << a.mean[v] + a.re[v], a.im[v], a.im[v], a.mean[v] - a.re[v];
    field.setVertexTensors(std::move(out));
  } else {
    std::vector<Vec2> out(n);
    for (size_t v = 0; v < n; ++v) out[v] = Vec2(a.re[v], a.im[v]);
    field.setVertexVectors(std::move(out));
  }
}

}  // namespace fgsg::rt::field
