// Reading an annotated base mesh from OBJ (base_mesh_file.h).
#include "runtime/cells/base_mesh_file.h"

#include "runtime/io/quoted_text.h"
#include "runtime/io/read_input.h"
#include "runtime/surface/load_surface.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <map>
#include <stdexcept>

namespace fgsg::rt::cells {

namespace {

[[noreturn]] void fail(const std::string& name, size_t line, const std::string& what) {
  throw std::runtime_error(name + ":" + std::to_string(line) + ": " + what);
}

std::string_view trim(std::string_view s) {
  const size_t b = s.find_first_not_of(" \t\r\f\v");
  if (b == std::string_view::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t\r\f\v") - b + 1);
}

// Splits off the first whitespace-separated token of `rest` ("" when none is left).
std::string_view token(std::string_view& rest) {
  rest = trim(rest);
  const size_t e = std::min(rest.find_first_of(" \t\r\f\v"), rest.size());
  const std::string_view t = rest.substr(0, e);
  rest.remove_prefix(e);
  return t;
}

template <class T>
bool parseWhole(std::string_view s, T& out) {
  if (s.size() > 1 && s[0] == '+' && s[1] != '-') s.remove_prefix(1);  // from_chars takes no '+'
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return !s.empty() && ec == std::errc() && end == s.data() + s.size();
}

}  // namespace

LabelledMesh parseBaseMeshObj(std::string_view text, const std::string& name) {
  std::vector<Vec3> raw;                         // as written, before welding
  std::map<std::array<double, 3>, int> welded;  // position -> mesh vertex
  std::vector<int> weldedOf;                     // raw index -> mesh vertex (-1: unused yet)
  std::map<std::string, int, std::less<>> groupIndex;
  std::string group;
  LabelledMesh out;
  auto& m = out.mesh;

  size_t lineNo = 0;
  while (!text.empty()) {
    const size_t nl = std::min(text.find('\n'), text.size());
    std::string_view rest = text.substr(0, nl);
    text.remove_prefix(std::min(nl + 1, text.size()));
    ++lineNo;
    if (const size_t hash = rest.find('#'); hash != std::string_view::npos) rest = rest.substr(0, hash);
    const std::string_view kw = token(rest);
    if (kw.empty() || kw == "vt" || kw == "vn" || kw == "s" || kw == "mtllib") continue;
    if (kw == "g" || kw == "o" || kw == "usemtl") {
      group = std::string(trim(rest));
    } else if (kw == "v") {
      Vec3 p;
      for (int k = 0; k < 3; ++k) {
        const std::string_view t = token(rest);
        if (t.empty()) fail(name, lineNo, "'v' needs three coordinates");
        if (!parseWhole(t, p[k]) || !std::isfinite(p[k]))
          fail(name, lineNo, io::quoteText(t) + " is not a finite number");
      }
      raw.push_back(p);
      weldedOf.push_back(-1);
    } else if (kw == "f") {
      std::vector<int> poly;
      for (std::string_view t = token(rest); !t.empty(); t = token(rest)) {
        // i, i/t, i//n or i/t/n: only the position index matters here.
        const std::string_view idx = t.substr(0, t.find('/'));
        long long i = 0;
        bool ok = parseWhole(idx, i) && i != 0;
        std::string_view more = t.substr(idx.size());
        for (int parts = 0; ok && !more.empty(); ++parts) {  // "/t", "/", "/n"
          more.remove_prefix(1);
          const std::string_view p = more.substr(0, more.find('/'));
          long long ignored;
          ok = parts < 2 && (p.empty() || parseWhole(p, ignored));
          more.remove_prefix(p.size());
        }
        if (!ok) fail(name, lineNo, io::quoteText(t) + " is not a face corner (i, i/t, i//n or i/t/n)");
        const long long n = (long long)raw.size(), at = i < 0 ? n + i : i - 1;
        if (at < 0 || at >= n)
          fail(name, lineNo, "vertex index " + std::to_string(i) + " is out of range (" + std::to_string(n) +
                                 " vertices so far)");
        int& w = weldedOf[size_t(at)];
        if (w < 0) {  // first use: weld with an equal position, or a new mesh vertex
          const Vec3& p = raw[size_t(at)];
          const auto [it, fresh] = welded.emplace(std::array<double, 3>{p.x(), p.y(), p.z()}, int(m.vertices.size()));
          if (fresh) m.vertices.push_back(p);
          w = it->second;
        }
        poly.push_back(w);
      }
      if (poly.size() < 3) fail(name, lineNo, "a face needs at least three corners");
      auto [it, fresh] = groupIndex.emplace(group, int(out.groups.size()));
      if (fresh) out.groups.push_back(group);
      for (size_t k = 1; k + 1 < poly.size(); ++k) {
        const std::array<int, 3> t{poly[0], poly[k], poly[k + 1]};
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
          fail(name, lineNo, "the face uses a vertex twice (after welding equal positions)");
        // Checked here, while the line is known (validateSurface only names the triangle).
        const Vec3 &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]];
        const double longest = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
        if ((b - a).cross(c - a).norm() <= surface::kDegenerateFaceTolerance * longest)
          fail(name, lineNo, "the face is degenerate (its fan triangle " + std::to_string(k) +
                                 " has no area; a polygon must not have three corners in a row on a line)");
        m.faces.push_back(t);
        out.triangleGroup.push_back(it->second);
      }
    } else {
      fail(name, lineNo, "unknown statement " + io::quoteText(kw));
    }
  }
  if (m.faces.empty()) throw std::runtime_error(name + ": the file has no faces");
  std::vector<std::string> problems;
  if (!surface::validateSurface(m, problems)) {
    std::string msg = name + ": not a valid base mesh: ";
    for (size_t i = 0; i < problems.size(); ++i) msg += (i ? "; " : "") + problems[i];
    throw std::runtime_error(msg);
  }
  m.buildTopology();
  return out;
}

LabelledMesh readBaseMeshObj(const std::string& path) {
  std::string bytes, error;
  if (!io::readInputFile(path, "a base mesh file", bytes, error)) throw std::runtime_error(error);
  return parseBaseMeshObj(bytes, path);
}

FeatureMesh buildLabelledFeatureMesh(const LabelledMesh& lm, const FeatureOptions& options) {
  FeatureMesh fm = buildFeatureMesh(lm.mesh, options, &lm.triangleGroup);
  applyGroupLabels(fm, lm.groups, lm.triangleGroup);
  return fm;
}

}  // namespace fgsg::rt::cells
