#include "runtime/synthesis/constraints.h"
#include "runtime/synthesis/image_reader.h"

#include <charconv>

namespace fgsg::rt::synthesis {

const char* symmetryName(SymmetrySpec::Kind k) {
  switch (k) {
    case SymmetrySpec::kMirrorX: return "mirror-x";
    case SymmetrySpec::kMirrorY: return "mirror-y";
    case SymmetrySpec::kRotate90: return "rotate-90";
    case SymmetrySpec::kRotate180: return "rotate-180";
    case SymmetrySpec::kTranslateX: return "translate-x";
    case SymmetrySpec::kTranslateY: return "translate-y";
  }
  return "?";
}

bool parseSymmetry(const std::string& text, SymmetrySpec& out) {
  std::string name = text, arg;
  if (auto c = text.find(':'); c != std::string::npos) { name = text.substr(0, c); arg = text.substr(c + 1); }
  for (int k = 0; k <= SymmetrySpec::kTranslateY; ++k)
    if (name == symmetryName(SymmetrySpec::Kind(k))) {
      out.kind = SymmetrySpec::Kind(k);
      const bool translate = out.kind == SymmetrySpec::kTranslateX || out.kind == SymmetrySpec::kTranslateY;
      if (translate != !arg.empty()) return false;
      if (translate) {
        auto r = std::from_chars(arg.data(), arg.data() + arg.size(), out.offset);
        if (r.ec != std::errc() || r.ptr != arg.data() + arg.size() || out.offset < 1 || out.offset > kMaxTranslation)
          return false;  // larger shifts leave every grid (1 << 20 cells a side) and overflow x + N
      }
      return true;
    }
  return false;
}

int64_t symmetryImage(const SymmetrySpec& s, const GridSize& n, int64_t cell) {
  const int x = int(cell % n.nx), y = int((cell / n.nx) % n.ny);
  const int64_t z = cell / (int64_t(n.nx) * n.ny);
  int X = x, Y = y;
  switch (s.kind) {
    case SymmetrySpec::kMirrorX: X = n.nx - 1 - x; break;
    case SymmetrySpec::kMirrorY: Y = n.ny - 1 - y; break;
    case SymmetrySpec::kRotate90:  // a quarter turn counter-clockwise about the centre
      if (n.nx != n.ny) return -1;
      X = n.nx - 1 - y;
      Y = x;
      break;
    case SymmetrySpec::kRotate180: X = n.nx - 1 - x; Y = n.ny - 1 - y; break;
    case SymmetrySpec::kTranslateX: X = x + s.offset; break;
    case SymmetrySpec::kTranslateY: Y = y + s.offset; break;
  }
  if (X < 0 || Y < 0 || X >= n.nx || Y >= n.ny) return -1;
  return X + int64_t(n.nx) * (Y + int64_t(n.ny) * z);
}

std::vector<int32_t> symmetryLabelMap(const SymmetrySpec& s, const Example& ex) {
  const int k = ex.labelCount();
  std::vector<int32_t> id(static_cast<size_t>(k));
  for (int i = 0; i < k; ++i) id[size_t(i)] = i;
  auto get = [&](const std::vector<int32_t>& m) { return m.empty() ? id : m; };
  switch (s.kind) {
    case SymmetrySpec::kMirrorX: return get(ex.mirrorX);
    case SymmetrySpec::kMirrorY: return get(ex.mirrorY);
    case SymmetrySpec::kRotate90: return get(ex.rot90);
    case SymmetrySpec::kRotate180: {
      auto r = get(ex.rot90), out = id;
      for (int i = 0; i < k; ++i) out[size_t(i)] = r[size_t(r[size_t(i)])];
      return out;
    }
    default: return id;
  }
}

bool backgroundOnlyRegion(const PositionWeights& w, size_t region, const Example& ex) {
  if (w.empty() || region >= w.factor.size()) return false;
  for (int l = 0; l < ex.labelCount(); ++l)
    if (w.factor[region][size_t(l)] > 0 && !ex.labels[size_t(l)].background) return false;
  return true;
}

PositionWeights maskFromCells(const std::vector<uint8_t>& inside, const GridSize& size,
                              const Example& ex, double insideBoost) {
  PositionWeights w;
  const int k = ex.labelCount();
  w.factor.assign(2, std::vector<double>(size_t(k), 1.0));
  for (int l = 0; l < k; ++l) {
    const bool bg = ex.labels[size_t(l)].background;
    w.factor[0][size_t(l)] = bg ? 1.0 : 0.0;
    w.factor[1][size_t(l)] = bg ? 1.0 : insideBoost;
  }
  w.region.assign(size_t(size.count()), 0);
  for (int64_t c = 0; c < size.count(); ++c) {
    const int64_t xy = c % (int64_t(size.nx) * size.ny);
    w.region[size_t(c)] = inside[size_t(xy)] ? 1 : 0;
  }
  return w;
}

bool maskFromImage(const std::string& path, const GridSize& size, const Example& ex,
                   double insideBoost, PositionWeights& out, std::string& error) {
  RgbImage img;
  if (!readRgbImage(path, img, error)) return false;
  std::vector<uint8_t> inside(size_t(size.nx) * size_t(size.ny), 0);
  for (int y = 0; y < size.ny; ++y)
    for (int x = 0; x < size.nx; ++x) {
      // Nearest pixel to the cell centre; image row 0 is the top (y = ny-1).
      const int px = std::min(img.width - 1, int((x + 0.5) * img.width / size.nx));
      const int py = std::min(img.height - 1, int((size.ny - 1 - y + 0.5) * img.height / size.ny));
      const uint32_t c = img.pixel(px, py);
      const double lum = 0.299 * ((c >> 16) & 255) + 0.587 * ((c >> 8) & 255) + 0.114 * (c & 255);
      inside[size_t(y) * size_t(size.nx) + size_t(x)] = lum < 128.0;
    }
  out = maskFromCells(inside, size, ex, insideBoost);
  return true;
}

}  // namespace fgsg::rt::synthesis
