#include "runtime/marching/atlas_preview.h"

#include "runtime/io/atomic_file.h"
#include "runtime/io/png_encode.h"
#include "runtime/marching/geometry_image.h"

#include <algorithm>
#include <cmath>
#include <new>


namespace fgsg::rt::marching {

Rgb chartColour(int chart) {
  const double hue = std::fmod(0.13 + 0.6180339887498949 * chart, 1.0) * 6;
  const double s = 0.55, v = 0.85;
  const int sector = int(hue) % 6;
  const double f = hue - std::floor(hue);
  const double p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  const double rgb[6][3] = {{v, t, p}, {q, v, p}, {p, v, t}, {p, q, v}, {t, p, v}, {v, p, q}};
  return {uint8_t(std::lround(255 * rgb[sector][0])), uint8_t(std::lround(255 * rgb[sector][1])),
          uint8_t(std::lround(255 * rgb[sector][2]))};
}

PreviewImage renderAtlasPreview(const MarchingSurface& surface) {
  const GeometryImage& img = surface.image();
  const int n = img.size();
  const int step = (n + kPreviewMaxSide - 1) / kPreviewMaxSide;
  PreviewImage out;
  out.width = out.height = (n + step - 1) / step;
  out.rgb.resize(size_t(out.width) * out.height * 3);
  auto paint = [&](int px, int py, const Rgb& c) {  // py counted upwards, as the image
    if (px < 0 || py < 0 || px >= out.width || py >= out.height) return;
    const size_t i = 3 * (size_t(out.height - 1 - py) * out.width + px);
    out.rgb[i] = c[0], out.rgb[i + 1] = c[1], out.rgb[i + 2] = c[2];
  };
  for (int py = 0; py < out.height; ++py)
    for (int px = 0; px < out.width; ++px) {
      const int t = img.index(px * step, py * step);
      Rgb c = kPreviewBackground;
      if (img.kind(t) == TexelKind::Inner) c = chartColour(img.chart(t));
      else if (img.kind(t) == TexelKind::Indirection) {
        bool boundary = false;
        for (const IndirectionPointer& p : img.pointers(t)) boundary |= p.target < 0;
        c = boundary ? kPreviewBoundary : kPreviewIndirection;
      }
      paint(px, py, c);
    }
  // Pointer lines over the texels: every k-th pointer with a target.
  const size_t lines = std::max(1, out.width / kPreviewPixelsPerLine);
  const size_t every = std::max<size_t>(1, img.stats().pointers / lines);
  size_t seen = 0;
  for (int t = 0; t < n * n; ++t)
    for (const IndirectionPointer& p : img.pointers(t)) {
      if (p.target < 0 || seen++ % every != 0) continue;
      const double x0 = (t % n + 0.5) / step, y0 = (t / n + 0.5) / step;
      const double x1 = (p.target % n + 0.5) / step, y1 = (p.target / n + 0.5) / step;
      const int samples = int(std::ceil(std::max(std::abs(x1 - x0), std::abs(y1 - y0)))) + 1;
      for (int k = 0; k <= samples; ++k) {
        const double a = double(k) / samples;
        paint(int(x0 + a * (x1 - x0)), int(y0 + a * (y1 - y0)), kPreviewPointer);
      }
    }
  return out;
}

bool writeAtlasPreview(const MarchingSurface& surface, const std::string& pngPath, std::string& error) {
  std::string png;
  try {
    const PreviewImage img = renderAtlasPreview(surface);
    if (!io::encodePng(img.width, img.height, 3, img.rgb.data(), png)) {
      error = "cannot write '" + pngPath + "': cannot encode the atlas preview as PNG";
      return false;
    }
  } catch (const std::bad_alloc&) {
    error = "cannot write '" + pngPath + "': out of memory while drawing the atlas preview";
    return false;
  }
  return io::writeFileAtomically(pngPath, png, error);
}

}  // namespace fgsg::rt::marching
