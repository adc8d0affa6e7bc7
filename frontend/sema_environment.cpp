#include "frontend/sema_environment.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <set>

namespace fgsg::frontend {

namespace {

constexpr double kPi = 3.14159265358979323846;

const SurfaceGeneratorInfo kGenerators[] = {
    {"torus", 2, "torus(R, r)"},     {"sphere", 1, "sphere(r)"}, {"plane", 2, "plane(w, h)"},
    {"genus2", 0, "genus2()"},       {"cylinder", 2, "cylinder(r, h)"}, {"tori3", 2, "tori3(R, r)"},
};
constexpr const char* kGeneratorList =
    "torus(R, r), sphere(r), plane(w, h), genus2(), cylinder(r, h) or tori3(R, r)";

// The argument names of a generator, as in its signature.
std::string argumentName(const std::string& generator, size_t k) {
  static const std::map<std::string, std::vector<const char*>> kNames = {
      {"torus", {"R", "r"}}, {"sphere", {"r"}}, {"plane", {"w", "h"}}, {"cylinder", {"r", "h"}},
      {"tori3", {"R", "r"}}};
  auto it = kNames.find(generator);
  const SurfaceGeneratorInfo* g = findSurfaceGenerator(generator);
  if (g && k == static_cast<size_t>(g->args)) return "resolution";
  if (it == kNames.end() || k >= it->second.size()) return "argument " + std::to_string(k + 1);
  return it->second[k];
}

const char* const kElementKinds = "regular, wedge, trisector, node, centre (or center), saddle";
const std::set<std::string> kElements = {"regular", "wedge", "trisector", "node", "centre", "saddle"};
// Every keyword an item may contain (`vertex` only after `at`).
const std::set<std::string> kKeywords = {"at",    "vertex",   "decay",     "direction",
                                         "angle", "strength", "iterations"};

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

bool wholeNumber(double v) { return std::isfinite(v) && v >= 0 && v == std::floor(v) && v <= 2147483647.0; }

// The keyword of a design word, without its value (columns count characters).
SourceRange keywordRange(const FieldDesignWord& w) {
  SourceRange r = w.range;
  int chars = 0;
  for (unsigned char c : w.keyword) chars += (c & 0xC0) != 0x80;
  if (chars > 0) r.end = {r.begin.line, r.begin.col + chars - 1};
  return r;
}

// A value written in a design item: an expression, or the name of a constant that the
// grammar read as a keyword (`decay d` parses as the two words `decay` and `d`).
struct WordValue {
  const Expr* expr = nullptr;
  std::string name;
  SourceRange range;
  bool present() const { return expr || !name.empty(); }
};

class EnvironmentChecker {
 public:
  EnvironmentChecker(const Program& p, SemaResult& r, Diagnostics& d, const ConstEvaluator& e,
                     const SurfaceExpressionChecker& x)
      : prog_(p), res_(r), diags_(d), eval_(e), checkExpression_(x) {}

  void run() {
    for (size_t i = 0; i < prog_.surfaces.size(); ++i) {
      SurfaceInfo info;
      if (surface(prog_.surfaces[i], info) && i == 0) res_.surface = info;  // a second is E029
    }
    if (!prog_.fields.empty() && prog_.surfaces.empty()) {
      const FieldDecl& first = prog_.fields.front();
      diags_.error("E037", first.nameRange,
                   "field '" + first.name +
                       "' needs a surface: fields live on surfaces. Declare one, e.g. `surface "
                       "\"mesh.off\";` or `surface torus(2, 0.6);` (for the plane: `surface "
                       "plane(10, 10);`)");
    }
    std::set<std::string> names;
    for (const FieldDecl& f : prog_.fields) {
      FieldInfo info;
      // A name declared twice is E022 (reported with the other names); only the first counts.
      if (field(f, info) && names.insert(f.name).second) res_.fieldSpecs.push_back(std::move(info));
    }
  }

 private:
  // ------------------------------------------------------------ surface

  bool surface(const SurfaceDecl& d, SurfaceInfo& out) {
    out.range = d.range;
    if (d.generator.empty()) {
      if (d.path.empty()) {
        diags_.error("E033", d.target,
                     "the surface's file name is empty: `surface \"mesh.off\";`");
        return false;
      }
      out.path = d.path;
      out.present = true;
      return true;
    }
    const SurfaceGeneratorInfo* g = findSurfaceGenerator(d.generator);
    if (!g) {
      diags_.error("E033", d.nameRange,
                   "unknown surface '" + d.generator + "' (expected " + kGeneratorList +
                       "; a mesh file is written as a string: `surface \"" + d.generator +
                       ".off\";`)");
      return false;
    }
    const int n = static_cast<int>(d.args.size());
    // After its arguments a generator may take one more: its resolution (segments around
    // the tube or along the plane's longer side, sphere subdivisions, genus-2 levels).
    if (n != g->args && n != g->args + 1) {
      diags_.error("E033", d.target,
                   "'" + d.generator + "' takes " + std::to_string(g->args) + " argument" +
                       (g->args == 1 ? "" : "s") + " and an optional resolution, got " +
                       std::to_string(n) + ": " + g->signature);
      return false;
    }
    bool ok = true;
    for (size_t k = 0; k < d.args.size(); ++k) {
      const Expr& arg = *d.args[k];
      const std::string what = "'" + argumentName(d.generator, k) + "' of " + g->signature;
      ConstValue v;
      if (!eval_(arg, v)) {
        diags_.error("E034", arg.range,
                     what + " must be a constant number (numbers, constants, arithmetic and math "
                            "functions)");
        ok = false;
      } else if (v.type != ValueType::Num) {
        diags_.error("E034", arg.range,
                     what + " must be a number, got a " + valueTypeName(v.type));
        ok = false;
      } else if (!std::isfinite(v.num) || !(v.num > 0)) {
        diags_.error("E034", arg.range, what + " must be a positive number, got " + number(v.num));
        ok = false;
      } else {
        out.args.push_back(v.num);
      }
    }
    if (ok && d.generator == "torus" && out.args[1] >= out.args[0]) {
      diags_.error("E034", d.args[1]->range,
                   "the tube radius r = " + number(out.args[1]) +
                       " of torus(R, r) must be smaller than the radius R = " +
                       number(out.args[0]));
      ok = false;
    }
    if (ok && d.generator == "tori3" && 2 * out.args[1] >= out.args[0]) {
      diags_.error("E034", d.args[1]->range,
                   "the tube radius r = " + number(out.args[1]) +
                       " of tori3(R, r) must be less than half the radius R = " + number(out.args[0]) +
                       " (the tubes' six junctions must stay apart)");
      ok = false;
    }
    if (!ok) return false;
    out.generator = d.generator;
    out.present = true;
    return true;
  }

  // ------------------------------------------------------------ fields

  bool field(const FieldDecl& f, FieldInfo& out) {
    out.name = f.name;
    out.range = f.range;
    bool ok = true;
    if (f.name == "Scope" || f.name == "Shape" || f.name == "Geometry" || f.name == "context") {
      const char* what = f.name == "Scope"      ? "the scope queries (Scope.sx ...)"
                         : f.name == "Shape"    ? "the shape queries (Shape.depth ...)"
                         : f.name == "Geometry" ? "the geometry queries (Geometry.area ...)"
                                             : "the texture contexts (context.mask(texCoord))";
      diags_.error("E036", f.nameRange,
                   "a field cannot be called '" + f.name + "': '" + f.name + "' names " + what +
                       "; choose another name, e.g. F1");
      ok = false;
    }
    if (f.source == "design") return design(f, out) && ok;
    if (f.source == "curvature") {
      out.source = "curvature";
      out.kind = "tensor";
      return ok;
    }
    std::string path;
    bool isFile = false;
    if (f.source == "file") {
      path = f.path;
      isFile = true;
    } else if ((f.function == "tensor" || f.function == "vector" || f.function == "image" ||
                f.function == "scalar") && f.args.size() == 1) {
      ConstValue v;  // tensor(pathConst), image(pathConst)
      if (eval_(*f.args[0], v) && v.type == ValueType::Str) {
        path = v.str;
        isFile = true;
      } else if (f.function == "scalar") {
        // scalar(EXPR): a number at each vertex from its position.
        if (!checkExpression_(*f.args[0])) return false;
        out.source = "expression";
        out.kind = "scalar";
        out.expression = f.args[0].get();
        return ok;
      }
    }
    if (isFile) {
      if (path.empty()) {
        diags_.error("E035", f.sourceRange,
                     "the field's file name is empty: `" + f.function + "(\"foot." +
                         (f.function == "tensor" ? "tfield" : f.function == "scalar" ? "sfield" : "vfield") + "\")`");
        return false;
      }
      // image("cat.pgm"): the structure tensor of the image's gradients (FGSG Fig. 12).
      // scalar("heights.sfield") or scalar("map.png"): a number per vertex, or a picture's
      // brightness under each vertex.
      out.source = f.function == "image" ? "image" : "file";
      out.kind = f.function == "image" ? "tensor" : f.function;
      out.path = path;
      return ok;
    }
    if (f.function == "tensor" || f.function == "vector") {
      diags_.error("E035", f.args.size() == 1 ? f.args[0]->range : f.sourceRange,
                   "'" + f.function + "' loads a field from a file and takes its path as a constant "
                   "string: `" + f.function + "(\"foot." + (f.function == "tensor" ? "tfield" : "vfield") +
                       "\")`; to design one, write `design " + f.function + " { ... }`");
    } else if (f.function == "image") {
      diags_.error("E035", f.args.size() == 1 ? f.args[0]->range : f.sourceRange,
                   "'image' reads a picture (PNG, JPEG, PGM ...) and takes its path as a constant "
                   "string: `image(\"cat.png\")`");
    } else if (f.function == "scalar") {
      diags_.error("E035", f.sourceRange,
                   "'scalar' takes one argument: the path of a field file or a picture as a constant "
                   "string (`scalar(\"heights.sfield\")`, `scalar(\"map.png\")`), or an expression "
                   "over the surface's points x, y, z (`scalar(0.5 * y + sin(20 * x))`)");
    } else if (f.function == "curvature") {
      diags_.error("E035", f.sourceRange,
                   "'curvature' takes no arguments: `field " + f.name + " = curvature;` is the "
                   "curvature tensor of the surface");
    } else if (f.function == "design") {
      diags_.error("E035", f.sourceRange,
                   "a design names the field's kind and lists its elements: `design tensor { wedge "
                   "at vertex 0; }` or `design vector { ... }`");
    } else {
      diags_.error("E035", f.functionRange.begin.line ? f.functionRange : f.sourceRange,
                   "unknown field source '" + f.function +
                       "' (expected tensor(\"file\"), vector(\"file\"), scalar(\"file\"), design tensor { ... }, "
                       "design vector { ... }, curvature or image(\"file\"))");
    }
    return false;
  }

  // ------------------------------------------------------------ designs

  bool design(const FieldDecl& f, FieldInfo& out) {
    out.source = "design";
    if (f.function != "tensor" && f.function != "vector") {
      diags_.error("E035", f.functionRange,
                   "a design makes a tensor or a vector field: `design tensor { ... }` or `design "
                   "vector { ... }`, not '" + f.function + "'");
      return false;
    }
    out.kind = f.function;
    bool ok = true;
    int elements = 0;
    const FieldDesignItem* smooth = nullptr;
    for (const FieldDesignItem& item : f.design) {
      const bool isSmooth = item.kind == "smooth";
      if (isSmooth && smooth) {
        diags_.error("E038", item.kindRange,
                     "'smooth' is written twice in this design (first on line " +
                         std::to_string(smooth->range.begin.line) +
                         "): give one number of iterations");
        ok = false;
        continue;
      }
      if (isSmooth) smooth = &item;
      FieldDesignInfo info;
      const bool itemOk = designItem(item, out.kind, info);
      if (!isSmooth && kElements.count(info.kind)) ++elements;
      if (!itemOk) {
        ok = false;
        continue;
      }
      out.design.push_back(std::move(info));
    }
    if (elements == 0 && ok) {
      diags_.error("E038", f.sourceRange,
                   "a design needs at least one element (" + std::string(kElementKinds) +
                       "), e.g. `design " + f.function + " { " +
                       (f.function == "tensor" ? "wedge" : "node") + " at vertex 0; }`");
      ok = false;
    }
    return ok;
  }

  bool designItem(const FieldDesignItem& item, const std::string& fieldKind, FieldDesignInfo& out) {
    out.range = item.range;
    out.kind = item.kind == "center" ? "centre" : item.kind;
    if (out.kind != "smooth" && !kElements.count(out.kind)) {
      diags_.error("E038", item.kindRange,
                   "unknown design element '" + item.kind + "' (expected " + kElementKinds +
                       ", or smooth N)");
      return false;
    }
    if (fieldKind == "vector" && (out.kind == "wedge" || out.kind == "trisector")) {
      diags_.error("E038", item.kindRange,
                   "a vector field has no " + out.kind +
                       "s: wedges and trisectors (index +1/2 and -1/2) exist only in tensor "
                       "fields; use regular, node, centre or saddle, or `design tensor { ... }`");
      return false;
    }
    return out.kind == "smooth" ? smoothWords(item, out) : elementWords(item, out);
  }

  bool isAttr(const std::string& name) const {
    for (const auto& a : res_.attrs)
      if (a.name == name) return true;
    return false;
  }

  // The name of a value that the grammar read as a keyword: a word without a value whose
  // keyword is not a design keyword but a constant (or pi). An attr is taken too, to be
  // reported as not constant.
  bool constantNameAt(const FieldDesignItem& item, size_t k) const {
    if (k >= item.words.size()) return false;
    const FieldDesignWord& w = item.words[k];
    if (w.keyword.empty() || w.value || kKeywords.count(w.keyword)) return false;
    return res_.constants.count(w.keyword) || w.keyword == "pi" || w.keyword == "PI" ||
           isAttr(w.keyword);
  }

  static WordValue valueOf(const FieldDesignWord& w) {
    WordValue v;
    v.expr = w.value.get();
    v.range = w.value ? w.value->range : w.range;
    return v;
  }
  static WordValue nameValue(const FieldDesignWord& w) {
    WordValue v;
    v.name = w.keyword;
    v.range = w.range;
    return v;
  }

  // The value of a word that needs one: its own, or the constant named by the next word.
  WordValue takeValue(const FieldDesignItem& item, size_t& k) const {
    WordValue v = valueOf(item.words[k]);
    if (!v.present() && constantNameAt(item, k + 1)) v = nameValue(item.words[++k]);
    return v;
  }

  static std::string elementKeywords(const std::string& kind) {
    return kind == "regular"
               ? "at vertex N, at (x, y, z), decay d, strength s, direction (x, y, z), angle a"
               : "at vertex N, at (x, y, z), decay d, strength s";
  }

  // `wedge at vertex 120 decay 2 strength 1;`, `regular at (0, 0, 1) angle 30;`
  bool elementWords(const FieldDesignItem& item, FieldDesignInfo& out) {
    const std::string& kind = out.kind;
    bool ok = true;
    std::map<std::string, SourceRange> seen;  // "at" (a position), "decay" ...
    for (size_t k = 0; k < item.words.size(); ++k) {
      const FieldDesignWord& w = item.words[k];
      SourceRange where = w.range;
      if (w.keyword.empty()) {
        diags_.error("E039", w.range,
                     "a value in a design element follows its keyword (" + elementKeywords(kind) +
                         "), e.g. `" + item.kind + " at (0.2, 0.1, 0.9);`");
        ok = false;
        continue;
      }
      std::string key = w.keyword;
      WordValue value;
      if (key == "at") {
        value = valueOf(w);
        if (!value.present() && k + 1 < item.words.size() && item.words[k + 1].keyword == "vertex") {
          key = "vertex";
          ++k;
          value = takeValue(item, k);
          where.end = item.words[k].range.end;
        } else if (!value.present() && constantNameAt(item, k + 1)) {
          value = nameValue(item.words[++k]);
          where.end = item.words[k].range.end;
        }
      } else if (key == "vertex") {
        diags_.error("E039", keywordRange(w), "a vertex is a position: write `at vertex N`");
        ok = false;
        continue;
      } else if (!kKeywords.count(key) || key == "iterations") {
        diags_.error("E039", keywordRange(w),
                     "unknown word '" + key + "' in a " + kind + " element (expected " +
                         elementKeywords(kind) + ")");
        ok = false;
        continue;
      } else if ((key == "direction" || key == "angle") && kind != "regular") {
        diags_.error("E039", keywordRange(w),
                     "'" + key + "' is for regular elements only: a " + kind +
                         "'s directions follow from its kind (a " + kind + " takes " +
                         elementKeywords(kind) + ")");
        ok = false;
        continue;
      } else {
        value = takeValue(item, k);
        where.end = item.words[k].range.end;
      }
      const std::string slot = key == "vertex" ? "at" : key;
      if (seen.count(slot)) {
        diags_.error("E039", where,
                     slot == "at" ? "this " + kind + " has two positions; give one `at`"
                                  : "'" + key + "' is written twice in this " + kind);
        ok = false;
        continue;
      }
      seen[slot] = where;
      std::vector<double> values;
      if (!wordValues(key, value, where, values)) {
        ok = false;
        continue;
      }
      out.words.push_back({key, std::move(values)});
    }
    if (seen.count("direction") && seen.count("angle")) {
      diags_.error("E039", seen["angle"],
                   "a regular element takes a direction or an angle, not both");
      ok = false;
    }
    if (!seen.count("at")) {
      diags_.error("E039", item.kindRange,
                   "a " + kind + " needs a position: `" + item.kind + " at vertex 0;` or `" +
                       item.kind + " at (x, y, z);` (the point closest to it on the surface)");
      ok = false;
    }
    return ok;
  }

  // `smooth 300;` (also `smooth iterations 300;`)
  bool smoothWords(const FieldDesignItem& item, FieldDesignInfo& out) {
    bool ok = true;
    bool counted = false;
    for (size_t k = 0; k < item.words.size(); ++k) {
      const FieldDesignWord& w = item.words[k];
      SourceRange where = w.range;
      WordValue value;
      if (w.keyword.empty()) {
        value = valueOf(w);
      } else if (w.keyword == "iterations") {
        value = takeValue(item, k);
        where.end = item.words[k].range.end;
      } else if (constantNameAt(item, k)) {
        value = nameValue(w);
      } else {
        diags_.error("E039", keywordRange(w),
                     "'smooth' takes only its number of iterations: `smooth 300;`, not '" +
                         w.keyword + "'");
        ok = false;
        continue;
      }
      if (counted) {
        diags_.error("E039", where,
                     "'smooth' takes one number of iterations: `smooth 300;`");
        ok = false;
        continue;
      }
      counted = true;
      std::vector<double> values;
      if (!wordValues("iterations", value, where, values)) {
        ok = false;
        continue;
      }
      out.words.push_back({"iterations", std::move(values)});
    }
    if (!counted && ok) {
      diags_.error("E040", item.kindRange,
                   "'smooth' needs its number of iterations: `smooth 300;`");
      ok = false;
    }
    return ok;
  }

  // Evaluates and checks the value of one keyword.
  bool wordValues(const std::string& key, const WordValue& value, const SourceRange& where,
                  std::vector<double>& out) {
    const bool point = key == "at" || key == "direction";
    const std::string example = key == "at"          ? "`at (0.2, 0.1, 0.9)` or `at vertex 120`"
                                : key == "direction" ? "`direction (1, 0, 0)`"
                                : key == "vertex"     ? "`at vertex 120`"
                                : key == "iterations" ? "`smooth 300`"
                                                      : "`" + key + " 2`";
    const std::string what = key == "vertex" ? "'at vertex'" : key == "iterations" ? "'smooth'" : "'" + key + "'";
    if (!value.present()) {
      diags_.error("E040", where, what + " needs a value: " + example);
      return false;
    }
    ConstValue v;
    bool constant = false;
    if (value.expr) {
      constant = eval_(*value.expr, v);
    } else if (value.name == "pi" || value.name == "PI") {
      v = {};
      v.num = kPi;
      constant = true;
    } else {
      auto c = res_.constants.find(value.name);
      if (c != res_.constants.end()) v = c->second, constant = true;
    }
    if (!constant) {
      const bool badVector = value.expr && value.expr->kind == ExprKind::Vector &&
                             value.expr->args.size() != 3;
      if (!value.expr && isAttr(value.name)) {
        diags_.error("E040", value.range,
                     "the value of " + what + " must be a constant, and '" + value.name +
                         "' is an attr (it can change with --set); declare it `const`");
        return false;
      }
      diags_.error("E040", value.range,
                   badVector ? what + " takes a point of three coordinates: " + example
                             : "the value of " + what +
                                   " must be a constant (numbers, constants, arithmetic and math "
                                   "functions; write an expression in parentheses: `decay (2 * "
                                   "k)`)");
      return false;
    }
    const ValueType want = point ? ValueType::Vec3 : ValueType::Num;
    if (v.type != want) {
      diags_.error("E040", value.range,
                   what + " takes " + (point ? "a point (x, y, z)" : "a number") + ", got a " +
                       valueTypeName(v.type) + ": " + example);
      return false;
    }
    if (point) {
      for (double c : v.vec)
        if (!std::isfinite(c)) {
          diags_.error("E040", value.range, what + " must have finite coordinates");
          return false;
        }
      if (key == "direction" && v.vec[0] == 0 && v.vec[1] == 0 && v.vec[2] == 0) {
        diags_.error("E040", value.range, "a direction must not be (0, 0, 0)");
        return false;
      }
      out.assign(v.vec, v.vec + 3);
      return true;
    }
    const double x = v.num;
    std::string problem;
    if (!std::isfinite(x)) problem = what + " must be a finite number, got " + number(x);
    else if ((key == "vertex" || key == "iterations") && !wholeNumber(x))
      problem = key == "vertex" ? "a vertex number is a whole number from 0 to 2147483647, got " + number(x)
                                : "the number of smoothing iterations is a whole number from 0 to "
                                  "2147483647, got " + number(x);
    else if (key == "decay" && !(x > 0))
      problem = "'decay' must be positive, got " + number(x);
    if (!problem.empty()) {
      diags_.error("E040", value.range, problem);
      return false;
    }
    out.assign(1, x);
    return true;
  }

  const Program& prog_;
  SemaResult& res_;
  Diagnostics& diags_;
  const ConstEvaluator& eval_;
  const SurfaceExpressionChecker& checkExpression_;
};

}  // namespace

const SurfaceGeneratorInfo* findSurfaceGenerator(const std::string& name) {
  for (const auto& g : kGenerators)
    if (name == g.name) return &g;
  return nullptr;
}

void checkSurfaceAndFields(const Program& program, SemaResult& res, Diagnostics& diags,
                           const ConstEvaluator& evalConst, const SurfaceExpressionChecker& checkExpression) {
  EnvironmentChecker(program, res, diags, evalConst, checkExpression).run();
}

}  // namespace fgsg::frontend
