// Semantic analysis of `tileset NAME { ... }` (Chan & Hui's tiles for Evolve): which items
// exist, that their values are constants of the right form, and unique names. The tile
// set's own rules (points in the unit square, cross-section ends, letters) are checked by
// the runtime's validateTileSet, which `fgsg check` and Evolve both ask.
#include "frontend/sema_analyzer.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

namespace fgsg::frontend::sema_detail {

// The genetic algorithm's settings (rt::evolve::EvolveOptions) a tileset may give: how many
// numbers each takes and their range. Whether parents and elite fit the population is the
// GA's own check (R025 at Evolve).
struct GaSetting {
  const char* name;
  size_t minValues, maxValues;
  double lo, hi;
  bool whole;
  const char* example;
};

namespace {

constexpr const char* kItemKinds =
    "locus, section, orientations, symbols, or a GA setting: population, max_generations, threshold, weights, "
    "crossover, mutation, parents, elite; or a variation (Chan & Hui §6.4): faces, colours";

constexpr GaSetting kGaSettings[] = {
    {"population", 1, 1, 2, 100000, true, "population 100;"},
    {"max_generations", 1, 1, 0, 1000000, true, "max_generations 200;"},
    {"threshold", 1, 1, 0, 1, false, "threshold 0.7;"},
    {"weights", 3, 4, 0, 1e9, false, "weights 1, 1, 1, 3;"},
    {"crossover", 1, 1, 0, 1, false, "crossover 0.9;"},
    {"mutation", 1, 1, 0, 1, false, "mutation 0.1;"},
    {"parents", 1, 1, 1, 100000, true, "parents 20;"},
    {"elite", 1, 1, 0, 100000, true, "elite 2;"},
    // Not the GA's: the L-system generation whose cells carry the colour symmetry's colours.
    {"colours", 1, 1, 0, 12, true, "colours 1;"},
};

// `faces "+z -z";`: the face-let directions, as the setting's numbers 0 +x, 1 -x, 2 +y,
// 3 -y, 4 +z, 5 -z (backend/declared_tiles.h).
constexpr const char* kFaceDirections[] = {"+x", "-x", "+y", "-y", "+z", "-z"};

const GaSetting* gaSetting(const std::string& name) {
  for (const GaSetting& s : kGaSettings)
    if (name == s.name) return &s;
  return nullptr;
}

constexpr const char* kCurveForms = "polyline((x, y), (x, y), ...) or cubic(p0, p1, p2, p3)";

}  // namespace

// Declared, whether or not it checked out (a failing one has its own errors).
bool Analyzer::tilesetDeclared(const std::string& name) const {
  for (const TilesetDecl& t : prog_.tilesets)
    if (t.name == name) return true;
  return false;
}

// `locus arc = cubic((0.5, 0), (0.5, 0.276), (0.724, 0.5), (1, 0.5));`
bool Analyzer::tileCurve(const TilesetItem& item, TileCurveInfo& out) {
  out.name = item.name;
  out.range = item.range;
  const Expr* call = item.values.size() == 1 ? item.values[0].get() : nullptr;
  if (!call || call->kind != ExprKind::Call || (call->text != "polyline" && call->text != "cubic")) {
    diags_.error("E041", item.values.size() == 1 && item.values[0] ? item.values[0]->range : item.range,
                 "a " + item.kind + " is one curve: " + kCurveForms);
    return false;
  }
  out.cubic = call->text == "cubic";
  if (out.cubic && call->args.size() != 4) {
    diags_.error("E041", call->range,
                 "a cubic has 4 points (p0, two control points, p3), got " + std::to_string(call->args.size()));
    return false;
  }
  if (!out.cubic && call->args.size() < 2) {
    diags_.error("E041", call->range, "a polyline needs 2 or more points, got " + std::to_string(call->args.size()));
    return false;
  }
  bool ok = true;
  for (const ExprPtr& p : call->args) {
    std::array<double, 2> xy{};
    bool good = p && p->kind == ExprKind::Vector && p->args.size() == 2 && p->args[0] && p->args[1];
    for (size_t k = 0; good && k < 2; ++k) {
      ConstValue v;
      good = evalConst(*p->args[k], v) && v.type == ValueType::Num && std::isfinite(v.num);
      xy[k] = v.num;
    }
    if (!good) {
      diags_.error("E041", p ? p->range : call->range,
                   "a point of a " + item.kind + " is (x, y): two constant numbers in parentheses");
      ok = false;
      continue;
    }
    out.points.push_back(xy);
  }
  return ok;
}

// `population 100;`, `weights 1, 1, 1, 3;`: constant numbers in the setting's range.
bool Analyzer::gaSettingItem(const TilesetItem& item, const GaSetting& setting, const std::string& tileset,
                             TilesetInfo& out) {
  const std::string form = std::string("`") + setting.example + "`";
  if (!item.name.empty()) {
    diags_.error("E041", item.nameRange, "'" + item.kind + "' takes no name: " + form);
    return false;
  }
  for (const auto& [name, values] : out.settings)
    if (name == item.kind) {
      diags_.error("E041", item.kindRange, "'" + item.kind + "' is given twice in tileset '" + tileset + "'");
      return false;
    }
  if (item.values.size() < setting.minValues || item.values.size() > setting.maxValues) {
    diags_.error("E041", item.range,
                 "'" + item.kind + "' takes " +
                     (setting.minValues == setting.maxValues ? "one number"
                                                             : std::to_string(setting.minValues) + " or " +
                                                                   std::to_string(setting.maxValues) + " numbers") +
                     ": " + form);
    return false;
  }
  std::vector<double> numbers;
  for (const ExprPtr& e : item.values) {
    ConstValue v;
    if (!e) return false;
    const bool number = evalConst(*e, v) && v.type == ValueType::Num && std::isfinite(v.num);
    if (!number || v.num < setting.lo || v.num > setting.hi || (setting.whole && v.num != std::floor(v.num))) {
      diags_.error("E041", e->range,
                   "'" + item.kind + "' takes " + (setting.whole ? "whole numbers" : "numbers") + " from " +
                       formatNumber(setting.lo) + " to " + formatNumber(setting.hi) +
                       (number ? ", got " + formatNumber(v.num) : std::string(", a constant")) + ": " + form);
      return false;
    }
    numbers.push_back(v.num);
  }
  if (item.kind == "weights" && numbers[0] + numbers[1] + numbers[2] <= 0) {
    diags_.error("E041", item.range, "the weights of symmetry, connectivity and complexity cannot all be 0");
    return false;
  }
  out.settings.emplace_back(item.kind, std::move(numbers));
  return true;
}

// `faces "+z";`, `faces "+x -x +y -y";`: one constant string of directions (spaces or
// commas between), each at most once.
bool Analyzer::facesItem(const TilesetItem& item, const std::string& tileset, TilesetInfo& out) {
  constexpr const char* form = "`faces \"+z -z\";` (directions +x -x +y -y +z -z)";
  for (const auto& [name, values] : out.settings)
    if (name == item.kind) {
      diags_.error("E041", item.kindRange, "'faces' is given twice in tileset '" + tileset + "'");
      return false;
    }
  ConstValue v;
  const Expr* value = item.values.size() == 1 ? item.values[0].get() : nullptr;
  if (!item.name.empty() || !value || !evalConst(*value, v) || v.type != ValueType::Str) {
    diags_.error("E041", value ? value->range : item.range, "'faces' is one constant string: " + std::string(form));
    return false;
  }
  std::vector<double> codes;
  std::string word;
  auto take = [&]() {
    if (word.empty()) return true;
    const auto* at = std::find(std::begin(kFaceDirections), std::end(kFaceDirections), word);
    if (at == std::end(kFaceDirections)) {
      diags_.error("E041", value->range, "'faces': unknown direction '" + word + "': " + form);
      return false;
    }
    const double code = double(at - std::begin(kFaceDirections));
    if (std::find(codes.begin(), codes.end(), code) != codes.end()) {
      diags_.error("E041", value->range, "'faces': direction '" + word + "' is listed twice");
      return false;
    }
    codes.push_back(code);
    word.clear();
    return true;
  };
  for (const char c : v.str) {
    if (c == ' ' || c == ',' || c == '\t') {
      if (!take()) return false;
    } else {
      word += c;
    }
  }
  if (!take()) return false;
  if (codes.empty()) {
    diags_.error("E041", value->range, "'faces' names no direction: " + std::string(form));
    return false;
  }
  out.settings.emplace_back(item.kind, std::move(codes));
  return true;
}

void Analyzer::collectTilesets() {
  std::set<std::string> taken(res_.fields.begin(), res_.fields.end());
  taken.insert(res_.textures.begin(), res_.textures.end());
  for (const auto& v : prog_.values) taken.insert(v.name);
  for (const TilesetDecl& d : prog_.tilesets) {
    if (!taken.insert(d.name).second) {
      diags_.error("E022", d.nameRange, "tileset '" + d.name + "' is declared twice (or names a const, attr, field or texture)");
      continue;
    }
    TilesetInfo info;
    info.name = d.name;
    info.range = d.range;
    bool ok = true, haveOrientations = false, haveSymbols = false;
    std::set<std::string> loci, sections;
    for (const TilesetItem& item : d.items) {
      if (item.kind == "locus" || item.kind == "section") {
        auto& names = item.kind == "locus" ? loci : sections;
        if (!item.name.empty() && !names.insert(item.name).second) {
          diags_.error("E041", item.nameRange, item.kind + " '" + item.name + "' is declared twice in tileset '" + d.name + "'");
          ok = false;
          continue;
        }
        TileCurveInfo curve;
        if (!tileCurve(item, curve)) {
          ok = false;
          continue;
        }
        (item.kind == "locus" ? info.loci : info.sections).push_back(std::move(curve));
        continue;
      }
      if (item.kind == "faces") {
        if (!facesItem(item, d.name, info)) ok = false;
        continue;
      }
      if (const GaSetting* setting = gaSetting(item.kind)) {
        if (!gaSettingItem(item, *setting, d.name, info)) ok = false;
        continue;
      }
      if (item.kind != "orientations" && item.kind != "symbols") {
        diags_.error("E041", item.kindRange, "unknown tileset item '" + item.kind + "' (expected " + kItemKinds + ")");
        ok = false;
        continue;
      }
      if (!item.name.empty()) {
        diags_.error("E041", item.nameRange, "'" + item.kind + "' takes no name: `" + item.kind +
                                                 (item.kind == "symbols" ? " \"AB\";`" : " 0, 90, 180, 270;`"));
        ok = false;
        continue;
      }
      bool& given = item.kind == "symbols" ? haveSymbols : haveOrientations;
      if (given) {
        diags_.error("E041", item.kindRange, "'" + item.kind + "' is given twice in tileset '" + d.name + "'");
        ok = false;
        continue;
      }
      given = true;
      if (item.kind == "symbols") {
        ConstValue v;
        const Expr* value = item.values.size() == 1 ? item.values[0].get() : nullptr;
        if (!value || !evalConst(*value, v) || v.type != ValueType::Str) {
          diags_.error("E041", item.values.empty() || !item.values[0] ? item.range : item.values[0]->range,
                       "'symbols' is one constant string, a letter per locus x section: `symbols \"AB\";`");
          ok = false;
        } else {
          info.symbols = v.str;
        }
        continue;
      }
      for (const ExprPtr& e : item.values) {
        if (!e) continue;  // a syntax error, reported already
        ConstValue v;
        const bool number = evalConst(*e, v) && v.type == ValueType::Num;
        const bool quarter = number && (v.num == 0 || v.num == 90 || v.num == 180 || v.num == 270);
        if (!quarter) {
          diags_.error("E041", e->range,
                       "an orientation is 0, 90, 180 or 270 (degrees)" +
                           (number ? ", got " + formatNumber(v.num) : std::string()));
          ok = false;
        } else if (std::find(info.orientations.begin(), info.orientations.end(), int(v.num)) != info.orientations.end()) {
          diags_.error("E041", e->range, "orientation " + formatNumber(v.num) + " is listed twice");
          ok = false;
        } else {
          info.orientations.push_back(int(v.num));
        }
      }
    }
    if (ok && (info.loci.empty() || info.sections.empty())) {
      diags_.error("E041", d.nameRange,
                   "tileset '" + d.name + "' needs at least one locus and one section, e.g. `locus arc = " +
                       "cubic((0.5, 0), (0.5, 0.276), (0.724, 0.5), (1, 0.5)); section round = " +
                       "polyline((-1, 0), (0, 1), (1, 0));`");
      ok = false;
    }
    if (ok) res_.tilesets.push_back(std::move(info));
  }
}

}  // namespace fgsg::frontend::sema_detail
