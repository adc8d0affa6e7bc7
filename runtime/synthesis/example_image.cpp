// A labelled example image: each distinct colour is a label named by its hex value
// ("ff8800"), placed as a flat coloured quad. Image row 0 is the top (y = ny-1).
#include "runtime/io/read_input.h"
#include "runtime/synthesis/example.h"
#include "runtime/synthesis/image_reader.h"

#include <cstdio>
#include <unordered_map>

namespace fgsg::rt::synthesis {

constexpr int kMaxImageLabels = 1024;

bool loadExampleImage(const std::string& path, Example& out, Diagnostics& diags) {
  out = Example{};
  out.path = path;
  RgbImage img;
  std::string err;
  if (!readRgbImage(path, img, err)) {
    diags.push_back({path, 0, 0, "E721", io::withoutPath(err, path), ""});
    return false;
  }
  std::unordered_map<uint32_t, int32_t> byColor;
  LabelGrid g(GridSize{img.width, img.height, 1});
  for (int r = 0; r < img.height; ++r)
    for (int x = 0; x < img.width; ++x) {
      uint32_t c = img.pixel(x, r);
      auto it = byColor.find(c);
      if (it == byColor.end()) {
        if (int(out.labels.size()) >= kMaxImageLabels) {
          diags.push_back({path, 0, 0, "E722", "more than " + std::to_string(kMaxImageLabels) + " distinct colours", ""});
          return false;
        }
        Piece p;
        char name[8];
        std::snprintf(name, sizeof name, "%06x", c);
        p.name = name;
        p.asset = "cube";
        p.hasColor = true;
        p.color = {float((c >> 16) & 255) / 255.f, float((c >> 8) & 255) / 255.f, float(c & 255) / 255.f};
        p.weight = -1;
        it = byColor.emplace(c, int32_t(out.labels.size())).first;
        out.labels.push_back(p);
      }
      g.at(x, img.height - 1 - r, 0) = it->second;
    }
  out.emptyLabel = g.at(0, img.height - 1, 0);
  out.labels[size_t(out.emptyLabel)].background = true;
  out.labels[size_t(out.emptyLabel)].asset.clear();
  out.grid = std::move(g);
  computeAdjacencyFromGrid(out);
  return true;
}

}  // namespace fgsg::rt::synthesis
