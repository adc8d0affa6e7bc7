#include "runtime/synthesis/checker.h"

#include <algorithm>
#include <set>
#include <tuple>

namespace fgsg::rt::synthesis {

namespace {

using Rule = std::tuple<int, int32_t, int32_t>;  // axis, label, label at +axis

std::set<Rule> rulesOf(const Example& ex) {
  std::set<Rule> rules;
  if (ex.grid) {
    const LabelGrid& e = *ex.grid;
    const GridSize s = e.size();
    for (int z = 0; z < s.nz; ++z)
      for (int y = 0; y < s.ny; ++y)
        for (int x = 0; x < s.nx; ++x) {
          if (x + 1 < s.nx) rules.insert({0, e.at(x, y, z), e.at(x + 1, y, z)});
          if (y + 1 < s.ny) rules.insert({1, e.at(x, y, z), e.at(x, y + 1, z)});
          if (z + 1 < s.nz) rules.insert({2, e.at(x, y, z), e.at(x, y, z + 1)});
        }
    return rules;
  }
  for (int a = 0; a < 3; ++a)
    for (auto [b, c] : ex.allowed[size_t(a)]) rules.insert({a, b, c});
  return rules;
}

std::string cellStr(int x, int y, int z) {
  return "(" + std::to_string(x) + "," + std::to_string(y) + "," + std::to_string(z) + ")";
}

}  // namespace

int countConnectedGroups(const LabelGrid& m, const std::vector<uint8_t>& connect,
                         std::array<bool, 3> periodic) {
  const GridSize s = m.size();
  auto on = [&](int64_t i) { int32_t l = m[i]; return l >= 0 && size_t(l) < connect.size() && connect[size_t(l)]; };
  std::vector<uint8_t> seen(size_t(m.cellCount()), 0);
  int groups = 0;
  std::vector<int64_t> todo;
  for (int64_t start = 0; start < m.cellCount(); ++start) {
    if (seen[size_t(start)] || !on(start)) continue;
    ++groups;
    seen[size_t(start)] = 1;
    todo.push_back(start);
    while (!todo.empty()) {
      const Cell c = m.cell(todo.back());
      todo.pop_back();
      const int p[3] = {c.x, c.y, c.z};
      for (int a = 0; a < 3; ++a)
        for (int step : {-1, 1}) {
          int q[3] = {p[0], p[1], p[2]};
          q[a] += step;
          const int n = s[a];
          if (q[a] < 0 || q[a] >= n) {
            if (!periodic[size_t(a)]) continue;
            q[a] = (q[a] + n) % n;
          }
          const int64_t j = m.index(q[0], q[1], q[2]);
          if (!seen[size_t(j)] && on(j)) { seen[size_t(j)] = 1; todo.push_back(j); }
        }
    }
  }
  return groups;
}

std::vector<Violation> checkModel(const LabelGrid& m, const Example& ex, const CheckSpec& spec,
                                  size_t maxViolations) {
  std::vector<Violation> out;
  const GridSize s = m.size();
  const int k = ex.labelCount();
  auto add = [&](int x, int y, int z, std::string what) {
    if (out.size() < maxViolations) out.push_back({{x, y, z}, std::move(what)});
  };
  auto name = [&](int32_t l) { return l >= 0 && l < k ? ex.labels[size_t(l)].name : std::to_string(l); };
  const std::set<Rule> rules = rulesOf(ex);

  for (int z = 0; z < s.nz; ++z)
    for (int y = 0; y < s.ny; ++y)
      for (int x = 0; x < s.nx; ++x) {
        const int32_t b = m.at(x, y, z);
        if (b < 0 || b >= k) { add(x, y, z, "cell " + cellStr(x, y, z) + " has no valid label (" + std::to_string(b) + ")"); continue; }
        const int p[3] = {x, y, z};
        for (int a = 0; a < 3; ++a) {
          int q[3] = {p[0], p[1], p[2]};
          q[a] += 1;
          if (q[a] >= s[a]) {
            if (!spec.periodic[size_t(a)] || s[a] < 2) continue;
            q[a] = 0;
          }
          const int32_t c = m.at(q[0], q[1], q[2]);
          if (c < 0 || c >= k) continue;
          if (!rules.count({a, b, c}))
            add(x, y, z, "labels " + name(b) + " at " + cellStr(x, y, z) + " and " + name(c) + " at " +
                             cellStr(q[0], q[1], q[2]) + " never touch along " + "xyz"[a] + " in the example");
        }
        if (spec.weights && spec.weights->at(m.index(x, y, z), b) <= 0)
          add(x, y, z, "label " + name(b) + " at " + cellStr(x, y, z) + " is excluded there by the mask");
      }

  const BorderSpec border = spec.border ? *spec.border : ex.border;
  for (int f = 0; f < 6; ++f) {
    const int a = f / 2;
    if (spec.periodic[size_t(a)] || (a == 2 && ex.dims == 2)) continue;
    const int32_t fixed = border.fixed[size_t(f)], outside = border.outside[size_t(f)];
    const auto& only = border.only[size_t(f)];
    if (fixed < 0 && outside < 0 && only.empty()) continue;
    for (int z = 0; z < s.nz; ++z)
      for (int y = 0; y < s.ny; ++y)
        for (int x = 0; x < s.nx; ++x) {
          const int p[3] = {x, y, z};
          if (p[a] != (f % 2 == 0 ? 0 : s[a] - 1)) continue;
          const int32_t l = m.at(x, y, z);
          const size_t region = spec.weights && !spec.weights->region.empty()
                                    ? spec.weights->region[size_t(m.index(x, y, z))]
                                    : 0;
          const bool bindsOnly = !(spec.weights && backgroundOnlyRegion(*spec.weights, region, ex));
          if (bindsOnly && !only.empty() && std::find(only.begin(), only.end(), l) == only.end())
            add(x, y, z, "label " + name(l) + " at " + cellStr(x, y, z) + " may not lie on face " + faceName(f));
          if (fixed >= 0 && l != fixed)
            add(x, y, z, "cell " + cellStr(x, y, z) + " on face " + faceName(f) + " must be " + name(fixed) + ", is " + name(l));
          if (outside >= 0) {
            const bool ok = f % 2 == 0 ? rules.count({a, outside, l}) : rules.count({a, l, outside});
            if (!ok) add(x, y, z, "label " + name(l) + " at " + cellStr(x, y, z) + " cannot touch " + name(outside) + " outside face " + faceName(f));
          }
        }
  }

  for (const auto& sym : spec.symmetry) {
    std::vector<int32_t> f(static_cast<size_t>(k));
    for (int l = 0; l < k; ++l) {
      int32_t v = l;
      switch (sym.kind) {
        case SymmetrySpec::kMirrorX: v = ex.mirrorX.empty() ? l : ex.mirrorX[size_t(l)]; break;
        case SymmetrySpec::kMirrorY: v = ex.mirrorY.empty() ? l : ex.mirrorY[size_t(l)]; break;
        case SymmetrySpec::kRotate90: v = ex.rot90.empty() ? l : ex.rot90[size_t(l)]; break;
        case SymmetrySpec::kRotate180: v = ex.rot90.empty() ? l : ex.rot90[size_t(ex.rot90[size_t(l)])]; break;
        default: break;
      }
      f[size_t(l)] = v;
    }
    for (int z = 0; z < s.nz; ++z)
      for (int y = 0; y < s.ny; ++y)
        for (int x = 0; x < s.nx; ++x) {
          int X = x, Y = y;
          switch (sym.kind) {
            case SymmetrySpec::kMirrorX: X = s.nx - 1 - x; break;
            case SymmetrySpec::kMirrorY: Y = s.ny - 1 - y; break;
            case SymmetrySpec::kRotate90: X = s.nx - 1 - y; Y = x; break;
            case SymmetrySpec::kRotate180: X = s.nx - 1 - x; Y = s.ny - 1 - y; break;
            case SymmetrySpec::kTranslateX: X = x + sym.offset; break;
            case SymmetrySpec::kTranslateY: Y = y + sym.offset; break;
          }
          if (!m.inside(X, Y, z)) continue;
          const int32_t b = m.at(x, y, z);
          if (b < 0 || b >= k) continue;
          if (m.at(X, Y, z) != f[size_t(b)])
            add(x, y, z, std::string(symmetryName(sym.kind)) + ": cell " + cellStr(X, Y, z) + " is " + name(m.at(X, Y, z)) +
                             ", expected " + name(f[size_t(b)]) + " (image of " + name(b) + " at " + cellStr(x, y, z) + ")");
        }
  }

  if (spec.connectivity.enabled) {
    std::vector<uint8_t> conn(size_t(k), 0);
    for (int l = 0; l < k; ++l)
      conn[size_t(l)] = spec.connectivity.labels.empty() ? ex.labels[size_t(l)].connect
                                                         : (size_t(l) < spec.connectivity.labels.size() && spec.connectivity.labels[size_t(l)]);
    const int groups = countConnectedGroups(m, conn, spec.periodic);
    if (groups > spec.connectivity.seeds)
      add(0, 0, 0, "connectivity: " + std::to_string(groups) + " separate groups, at most " + std::to_string(spec.connectivity.seeds) + " allowed");
  }
  return out;
}

}  // namespace fgsg::rt::synthesis
