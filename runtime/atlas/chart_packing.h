// Packing flat charts into the unit square (Buron et al. §4: charts keep at least one
// empty texel around them for the indirection pixels). All charts are scaled by one common
// factor, so whatever texel density the charts had relative to each other they keep;
// each is placed on whole texels with `gutterTexels` empty texels after it and around the
// border, by a skyline packer taking the tallest charts first. The common factor is the
// largest for which the packer fits everything (a bisection over the factor).
#pragma once

#include "runtime/atlas/atlas.h"

#include <array>
#include <string>
#include <vector>

namespace fgsg::rt::atlas {

// A chart laid flat, before packing.
struct FlatChart {
  std::vector<int> faces;                        // mesh faces
  std::vector<std::array<Vec2, 3>> corners;      // per face in `faces`: its corners' positions
};

// False with a message when options cannot describe an atlas (a resolution too small for
// its own gutter, a gutter under one texel, a normal deviation outside (0, 180]).
bool checkAtlasOptions(const AtlasOptions& options, std::string& error);

// Fills `out` for a mesh of `faceCount` faces (every face in exactly one chart; chart i is
// charts[i]). `allowRotation`: a chart may be turned by 90 degrees where that packs
// better (never mirrored). False with a message when the charts do not fit even at one
// texel each.
bool packCharts(const std::vector<FlatChart>& charts, size_t faceCount, const AtlasOptions& options,
                bool allowRotation, Atlas& out, std::string& error);

}  // namespace fgsg::rt::atlas
