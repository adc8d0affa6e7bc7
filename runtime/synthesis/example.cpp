#include "runtime/synthesis/example.h"

#include "runtime/io/read_input.h"

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

namespace fgsg::rt::synthesis {

namespace {
const char* const kFaceNames[6] = {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};

std::string extensionOf(const std::string& path) {
  auto dot = path.find_last_of('.');
  auto slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string e = path.substr(dot + 1);
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return e;
}
}  // namespace

const char* faceName(int face) { return face >= 0 && face < 6 ? kFaceNames[face] : "?"; }

int faceFromName(std::string_view name) {
  for (int f = 0; f < 6; ++f)
    if (name == kFaceNames[f]) return f;
  return -1;
}

int32_t Example::findLabel(std::string_view name) const {
  for (size_t i = 0; i < labels.size(); ++i)
    if (labels[i].name == name) return int32_t(i);
  return -1;
}

void computeAdjacencyFromGrid(Example& ex) {
  if (!ex.grid) return;
  const LabelGrid& g = *ex.grid;
  const GridSize s = g.size();
  const int k = ex.labelCount();
  // Dense k*k flags per axis, then listed: the pair lists stay sorted and unique.
  for (int a = 0; a < 3; ++a) {
    std::vector<uint8_t> seen(size_t(k) * size_t(k), 0);
    for (int z = 0; z < s.nz; ++z)
      for (int y = 0; y < s.ny; ++y)
        for (int x = 0; x < s.nx; ++x) {
          int x2 = x + (a == 0), y2 = y + (a == 1), z2 = z + (a == 2);
          if (!g.inside(x2, y2, z2)) continue;
          seen[size_t(g.at(x, y, z)) * size_t(k) + size_t(g.at(x2, y2, z2))] = 1;
        }
    ex.allowed[a].clear();
    for (int b = 0; b < k; ++b)
      for (int c = 0; c < k; ++c)
        if (seen[size_t(b) * size_t(k) + size_t(c)]) ex.allowed[a].push_back({b, c});
  }
  ex.dims = s.nz > 1 ? 3 : 2;
  bool explicitWeights = false;
  for (const auto& p : ex.labels) explicitWeights |= p.weight >= 0;
  if (!explicitWeights) {
    for (auto& p : ex.labels) p.weight = 0;
    for (int32_t l : g.data()) ex.labels[size_t(l)].weight += 1;
  } else {
    for (auto& p : ex.labels)
      if (p.weight < 0) p.weight = 1;
  }
}

BorderSpec closedLikeExample(const Example& ex, BorderSpec b) {
  for (int f = 0; f < 6; ++f) {
    const int a = f / 2;
    if (a == 2 && ex.dims == 2) continue;
    std::set<int32_t> labels;
    if (ex.grid) {
      const LabelGrid& g = *ex.grid;
      const GridSize s = g.size();
      for (int z = 0; z < s.nz; ++z)
        for (int y = 0; y < s.ny; ++y)
          for (int x = 0; x < s.nx; ++x) {
            const int p[3] = {x, y, z};
            if (p[a] == (f % 2 == 0 ? 0 : s[a] - 1)) labels.insert(g.at(x, y, z));
          }
    } else {
      for (int l = 0; l < ex.labelCount(); ++l)
        if (ex.labels[size_t(l)].background) labels.insert(l);
    }
    b.only[size_t(f)].assign(labels.begin(), labels.end());
  }
  return b;
}

bool loadExample(const std::string& path, Example& out, Diagnostics& diags) {
  const std::string ext = extensionOf(path);
  if (ext == "png") return loadExampleImage(path, out, diags);
  std::string text, error;
  if (!io::readInputFile(path, "an example file", text, error)) {
    diags.push_back({path, 0, 0, "E701", "cannot open example file: " + io::withoutPath(error, path), ""});
    return false;
  }
  if (ext == "json") return parseTileSetJson(text, path, out, diags);
  return parseExampleText(text, path, out, diags);
}

}  // namespace fgsg::rt::synthesis
