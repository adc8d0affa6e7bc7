// The label-grid text format (documented in docs/synthesis.md):
//
//   size NX NY [NZ]
//   label NAME ASSET [rot=R] [mirror] [color=#rrggbb] [weight=W]
//                    [mirror-x=NAME] [mirror-y=NAME] [rot90=NAME] [empty|ground|background|connect]
//   border FACE LABEL [fixed]
//   layer Z
//   NX tokens per row, NY rows per layer (first row is y = NY-1), NZ layers bottom-up.
//
// Tokens are separated by blanks or commas (so CSV rows work); '#' starting a token
// starts a comment.
#include "runtime/synthesis/example.h"

#include <charconv>
#include <cmath>
#include <map>
#include <sstream>

namespace fgsg::rt::synthesis {

namespace {

// Words of the format that cannot name a label: a grid written back would not read.
bool isKeyword(std::string_view name) {
  return name == "size" || name == "label" || name == "border" || name == "layer" || name == "fgsg-labels";
}

struct Token {
  std::string_view text;
  int column = 0;  // 1-based
};

std::vector<Token> tokenize(std::string_view line) {
  std::vector<Token> out;
  size_t i = 0;
  while (i < line.size()) {
    char c = line[i];
    if (c == ' ' || c == '\t' || c == ',' || c == '\r') {
      ++i;
      continue;
    }
    if (c == '#') break;
    size_t j = i;
    while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != ',' && line[j] != '\r') ++j;
    out.push_back({line.substr(i, j - i), int(i) + 1});
    i = j;
  }
  return out;
}

bool parseInt(std::string_view s, long long& v) {
  auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

bool parseDouble(std::string_view s, double& v) {
  std::string tmp(s);
  char* end = nullptr;
  v = std::strtod(tmp.c_str(), &end);
  return !tmp.empty() && end == tmp.c_str() + tmp.size() && std::isfinite(v);
}

bool parseColor(std::string_view s, std::array<float, 3>& c) {
  if (!s.empty() && s[0] == '#') s.remove_prefix(1);
  if (s.size() != 6) return false;
  for (int i = 0; i < 3; ++i) {
    unsigned v = 0;
    auto r = std::from_chars(s.data() + 2 * i, s.data() + 2 * i + 2, v, 16);
    if (r.ec != std::errc() || r.ptr != s.data() + 2 * i + 2) return false;
    c[size_t(i)] = float(v) / 255.0f;
  }
  return true;
}

constexpr long long kMaxExtent = 1 << 20;
constexpr long long kMaxCells = 1LL << 28;

struct PendingRef {  // a label named before all labels are known
  std::string name;
  int line, column;
  std::string source;
  int32_t* target;
};

}  // namespace

bool parseExampleText(std::string_view text, const std::string& fileName, Example& out,
                      Diagnostics& diags) {
  out = Example{};
  out.path = fileName;
  const size_t diagStart = diags.size();
  auto error = [&](int line, int col, const char* code, std::string msg, std::string_view src) {
    diags.push_back({fileName, line, col, code, std::move(msg), std::string(src)});
  };

  bool haveSize = false;
  GridSize size;
  std::map<std::string, int32_t, std::less<>> byName;
  bool declared = false;      // any `label` line: grid tokens must then be declared
  std::vector<int32_t> cells;  // filled row by row in file order
  int rowsRead = 0;            // rows of the whole file so far
  int expectLayerHeader = -1;  // not used for validation beyond the `layer` check
  std::vector<PendingRef> refs;
  std::vector<std::array<int32_t, 3>> maps;  // per label: mirror-x, mirror-y, rot90
  bool closed = false;                        // `border closed`
  (void)expectLayerHeader;

  int lineNo = 0;
  size_t pos = 0;
  while (pos <= text.size()) {
    size_t nl = text.find('\n', pos);
    if (nl == std::string_view::npos) nl = text.size();
    std::string_view line = text.substr(pos, nl - pos);
    pos = nl + 1;
    ++lineNo;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    auto toks = tokenize(line);
    if (toks.empty()) {
      if (nl == text.size()) break;
      continue;
    }
    const bool inLayer = haveSize && rowsRead % size.ny != 0;
    std::string_view head = toks[0].text;
    if (!inLayer && head == "fgsg-labels") continue;
    if (!inLayer && head == "size") {
      if (haveSize) { error(lineNo, toks[0].column, "E702", "`size` given twice", line); continue; }
      if (toks.size() < 3 || toks.size() > 4) {
        error(lineNo, toks[0].column, "E702", "expected `size NX NY [NZ]`", line);
        continue;
      }
      long long v[3] = {1, 1, 1};
      bool ok = true;
      for (size_t i = 1; i < toks.size(); ++i)
        if (!parseInt(toks[i].text, v[i - 1]) || v[i - 1] < 1 || v[i - 1] > kMaxExtent) {
          error(lineNo, toks[i].column, "E702", "grid extent must be an integer in 1.." + std::to_string(kMaxExtent), line);
          ok = false;
        }
      if (!ok) continue;
      if (v[0] * v[1] * v[2] > kMaxCells) {
        error(lineNo, toks[0].column, "E702", "grid has too many cells", line);
        continue;
      }
      size = {int(v[0]), int(v[1]), int(v[2])};
      haveSize = true;
      continue;
    }
    if (!inLayer && head == "label") {
      if (!cells.empty()) { error(lineNo, toks[0].column, "E703", "labels must be declared before the grid rows", line); continue; }
      if (toks.size() < 3) { error(lineNo, toks[0].column, "E703", "expected `label NAME ASSET [options]`", line); continue; }
      std::string name(toks[1].text);
      if (isKeyword(name)) {
        error(lineNo, toks[1].column, "E703", "`" + name + "` is a keyword, not a label name", line);
        continue;
      }
      if (byName.count(name)) { error(lineNo, toks[1].column, "E703", "label `" + name + "` declared twice", line); continue; }
      Piece p;
      p.name = name;
      p.weight = -1;
      p.asset = toks[2].text == "none" ? "" : std::string(toks[2].text);
      std::array<int32_t, 3> m{-1, -1, -1};
      const int32_t id = int32_t(out.labels.size());
      bool isEmpty = false;
      for (size_t i = 3; i < toks.size(); ++i) {
        std::string_view t = toks[i].text;
        auto eq = t.find('=');
        std::string_view key = t.substr(0, eq), val = eq == std::string_view::npos ? "" : t.substr(eq + 1);
        long long iv = 0;
        double dv = 0;
        if (key == "empty" && eq == std::string_view::npos) { isEmpty = true; p.background = true; }
        else if ((key == "ground" || key == "background") && eq == std::string_view::npos) p.background = true;
        else if (key == "connect" && eq == std::string_view::npos) p.connect = true;
        else if (key == "mirror" && eq == std::string_view::npos) p.mirrored = true;
        else if (key == "rot" && parseInt(val, iv) && iv >= 0 && iv <= 3) p.rotation = int(iv);
        else if (key == "weight" && parseDouble(val, dv) && dv >= 0) p.weight = dv;
        else if (key == "color" && parseColor(val, p.color)) p.hasColor = true;
        else if ((key == "mirror-x" || key == "mirror-y" || key == "rot90") && !val.empty()) {
          int slot = key == "mirror-x" ? 0 : key == "mirror-y" ? 1 : 2;
          refs.push_back({std::string(val), lineNo, toks[i].column + int(eq) + 1, std::string(line), nullptr});
          m[size_t(slot)] = int32_t(refs.size() - 1);  // resolved below
        } else {
          error(lineNo, toks[i].column, "E703",
                "bad label option `" + std::string(t) +
                    "` (expected rot=0..3, mirror, color=#rrggbb, weight=W>=0, mirror-x=L, "
                    "mirror-y=L, rot90=L, empty, ground, background, connect)",
                line);
        }
      }
      out.labels.push_back(p);
      maps.push_back(m);
      byName.emplace(name, id);
      if (isEmpty) out.emptyLabel = id;
      declared = true;
      continue;
    }
    if (!inLayer && head == "border" && toks.size() == 2 && toks[1].text == "closed") {
      closed = true;
      continue;
    }
    if (!inLayer && head == "border") {
      if (toks.size() < 3 || toks.size() > 4 || (toks.size() == 4 && toks[3].text != "fixed")) {
        error(lineNo, toks[0].column, "E704", "expected `border FACE LABEL [fixed]`", line);
        continue;
      }
      int face = faceFromName(toks[1].text);
      if (face < 0) { error(lineNo, toks[1].column, "E704", "unknown face (xmin xmax ymin ymax zmin zmax)", line); continue; }
      int32_t* target = toks.size() == 4 ? &out.border.fixed[size_t(face)] : &out.border.outside[size_t(face)];
      refs.push_back({std::string(toks[2].text), lineNo, toks[2].column, std::string(line), target});
      continue;
    }
    if (!inLayer && head == "layer") {
      long long z = 0;
      if (!haveSize) { error(lineNo, toks[0].column, "E705", "`size` must come before the grid", line); return false; }
      int expected = rowsRead / size.ny;
      if (toks.size() != 2 || !parseInt(toks[1].text, z) || z != expected) {
        error(lineNo, toks[0].column, "E705", "expected `layer " + std::to_string(expected) + "`", line);
      }
      continue;
    }
    // A grid row.
    if (!haveSize) { error(lineNo, toks[0].column, "E705", "`size NX NY [NZ]` must come before the grid rows", line); return false; }
    if (rowsRead >= size.ny * size.nz) { error(lineNo, toks[0].column, "E706", "more grid rows than `size` says (" + std::to_string(size.ny * size.nz) + ")", line); break; }
    if (int(toks.size()) != size.nx) {
      int col = int(toks.size()) > size.nx ? toks[size_t(size.nx)].column : int(line.size()) + 1;
      error(lineNo, col, "E706", "row has " + std::to_string(toks.size()) + " labels, expected " + std::to_string(size.nx), line);
      ++rowsRead;
      cells.insert(cells.end(), size_t(size.nx), 0);
      continue;
    }
    for (const auto& t : toks) {
      auto it = byName.find(t.text);
      if (it == byName.end()) {
        if (declared) {
          error(lineNo, t.column, "E707", "unknown label `" + std::string(t.text) + "`", line);
          cells.push_back(0);
          continue;
        }
        if (isKeyword(t.text)) {  // a cell would make it a label of that name
          error(lineNo, t.column, "E703", "`" + std::string(t.text) + "` is a keyword, not a label name", line);
          cells.push_back(0);
          continue;
        }
        Piece p;  // undeclared labels: '.', '_', '0' are empty space, others cubes
        p.name = std::string(t.text);
        p.weight = -1;
        bool empty = t.text == "." || t.text == "_" || t.text == "0" || t.text == "empty";
        p.asset = empty ? "" : "cube";
        p.background = empty;
        it = byName.emplace(p.name, int32_t(out.labels.size())).first;
        if (empty && out.emptyLabel < 0) out.emptyLabel = it->second;
        out.labels.push_back(p);
        maps.push_back({-1, -1, -1});
      }
      cells.push_back(it->second);
    }
    ++rowsRead;
  }

  if (!haveSize) {
    diags.push_back({fileName, 0, 0, "E705", "missing `size NX NY [NZ]`", ""});
    return false;
  }
  if (rowsRead != size.ny * size.nz && diags.size() == diagStart) {
    diags.push_back({fileName, lineNo, 1, "E706",
                     "grid ends after " + std::to_string(rowsRead) + " rows, expected " +
                         std::to_string(size.ny * size.nz) + " (NY*NZ)",
                     ""});
  }
  // Resolve forward references (symmetry maps, borders).
  std::vector<int32_t> refValue(refs.size(), -1);
  for (size_t i = 0; i < refs.size(); ++i) {
    auto it = byName.find(refs[i].name);
    if (it == byName.end()) {
      error(refs[i].line, refs[i].column, "E707", "unknown label `" + refs[i].name + "`", refs[i].source);
      continue;
    }
    refValue[i] = it->second;
    if (refs[i].target) *refs[i].target = it->second;
  }
  if (diags.size() != diagStart) return false;

  const int k = out.labelCount();
  bool anyMap[3] = {false, false, false};
  for (const auto& m : maps)
    for (int s = 0; s < 3; ++s) anyMap[s] |= m[size_t(s)] >= 0;
  std::vector<int32_t>* mapVec[3] = {&out.mirrorX, &out.mirrorY, &out.rot90};
  for (int s = 0; s < 3; ++s) {
    if (!anyMap[s]) continue;
    mapVec[s]->resize(size_t(k));
    for (int l = 0; l < k; ++l) {
      int r = maps[size_t(l)][size_t(s)];
      (*mapVec[s])[size_t(l)] = r >= 0 ? refValue[size_t(r)] : l;
    }
  }
  if (out.emptyLabel < 0) {
    for (const char* n : {".", "_", "0", "empty"})
      if (auto it = byName.find(n); it != byName.end()) { out.emptyLabel = it->second; break; }
  }
  LabelGrid g(size);
  // File order: layers bottom-up, rows top-down (first row y = ny-1), x left to right.
  for (int z = 0; z < size.nz; ++z)
    for (int r = 0; r < size.ny; ++r)
      for (int x = 0; x < size.nx; ++x)
        g.at(x, size.ny - 1 - r, z) = cells[size_t((int64_t(z) * size.ny + r) * size.nx + x)];
  out.grid = std::move(g);
  computeAdjacencyFromGrid(out);
  if (closed) out.border = closedLikeExample(out, out.border);
  return true;
}

std::string writeLabelGridText(const LabelGrid& grid, const Example& ex) {
  std::ostringstream o;
  const GridSize s = grid.size();
  o << "fgsg-labels 1\n";
  o << "size " << s.nx << ' ' << s.ny << ' ' << s.nz << "\n";
  size_t width = 1;
  for (const auto& p : ex.labels) width = std::max(width, p.name.size());
  for (size_t l = 0; l < ex.labels.size(); ++l) {
    const Piece& p = ex.labels[l];
    o << "label " << p.name << ' ' << (p.asset.empty() ? "none" : p.asset);
    if (p.rotation) o << " rot=" << p.rotation;
    if (p.mirrored) o << " mirror";
    if (p.hasColor) {
      char buf[16];
      std::snprintf(buf, sizeof buf, "#%02x%02x%02x", int(std::lround(p.color[0] * 255)),
                    int(std::lround(p.color[1] * 255)), int(std::lround(p.color[2] * 255)));
      o << " color=" << buf;
    }
    o << " weight=" << p.weight;
    if (!ex.mirrorX.empty() && ex.mirrorX[l] != int32_t(l)) o << " mirror-x=" << ex.labels[size_t(ex.mirrorX[l])].name;
    if (!ex.mirrorY.empty() && ex.mirrorY[l] != int32_t(l)) o << " mirror-y=" << ex.labels[size_t(ex.mirrorY[l])].name;
    if (!ex.rot90.empty() && ex.rot90[l] != int32_t(l)) o << " rot90=" << ex.labels[size_t(ex.rot90[l])].name;
    if (int32_t(l) == ex.emptyLabel) o << " empty";
    else if (p.background) o << " background";
    if (p.connect) o << " connect";
    o << "\n";
  }
  for (int z = 0; z < s.nz; ++z) {
    o << "layer " << z << "\n";
    for (int y = s.ny - 1; y >= 0; --y) {
      for (int x = 0; x < s.nx; ++x) {
        int32_t l = grid.at(x, y, z);
        std::string name = l >= 0 && l < ex.labelCount() ? ex.labels[size_t(l)].name : "?";
        o << name;
        if (x + 1 < s.nx) o << std::string(width + 1 - name.size(), ' ');
      }
      o << "\n";
    }
  }
  return o.str();
}

}  // namespace fgsg::rt::synthesis
