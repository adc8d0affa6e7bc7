// A picture of a marching surface's geometry image, for people checking an atlas: each
// chart in its own colour, indirection texels white (red where they mark the surface's
// own boundary: no target), and a sample of pointers drawn as yellow lines from their
// texel to their target. y up, as the image.
#pragma once

#include "runtime/marching/marching_surface.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace fgsg::rt::marching {

using Rgb = std::array<uint8_t, 3>;
constexpr Rgb kPreviewBackground = {24, 24, 28};
constexpr Rgb kPreviewIndirection = {255, 255, 255};
constexpr Rgb kPreviewBoundary = {230, 40, 40};
constexpr Rgb kPreviewPointer = {255, 210, 0};
// Images larger than this are shown one texel in `step` along each side.
constexpr int kPreviewMaxSide = 2048;
// One pointer in so many is drawn, evenly through the image, about one per this many
// pixels of the picture's side: targets often lie across the atlas, and more lines would
// hide the charts.
constexpr int kPreviewPixelsPerLine = 8;

// The colour of a chart: hues spread by the golden ratio, so neighbouring numbers differ.
Rgb chartColour(int chart);

struct PreviewImage {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;  // rows top to bottom
  Rgb at(int x, int y) const {  // (x, y) in picture rows, top to bottom
    const size_t i = 3 * (size_t(y) * width + x);
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
};

PreviewImage renderAtlasPreview(const MarchingSurface& surface);

// renderAtlasPreview as a PNG, written atomically. False with a message when it cannot be.
bool writeAtlasPreview(const MarchingSurface& surface, const std::string& pngPath, std::string& error);

}  // namespace fgsg::rt::marching
