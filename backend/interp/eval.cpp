#include "backend/interp/eval.h"
#include "ir/pinned_attr.h"

#include "frontend/did_you_mean.h"

#include "runtime/builtins_math.h"

#include <cmath>
#include <cstdlib>

namespace fgsg::backend {
double Evaluator::numSlow(const ir::Expr& e, const Frame& f) const {
  using ir::ExprOp;
  switch (e.op) {
    case ExprOp::Const: return e.num;
    case ExprOp::Param: return f.params[e.index];
    case ExprOp::Attr: return attrs_[3 * e.index];
    case ExprOp::Neg: return -num(e.args[0], f);
    case ExprOp::Not: return num(e.args[0], f) == 0.0 ? 1.0 : 0.0;
    // Operands are evaluated left to right, spelled out: C++ leaves the order of operands
    // unspecified, and the order decides which Rand gets which draw.
    case ExprOp::Add: { const double x = num(e.args[0], f), y = num(e.args[1], f); return x + y; }
    case ExprOp::Sub: { const double x = num(e.args[0], f), y = num(e.args[1], f); return x - y; }
    case ExprOp::Mul: { const double x = num(e.args[0], f), y = num(e.args[1], f); return x * y; }
    case ExprOp::Div: { const double x = num(e.args[0], f), y = num(e.args[1], f); return x / y; }
    case ExprOp::Mod: { const double x = num(e.args[0], f), y = num(e.args[1], f); return fgsg_rt_fmod(x, y); }
    case ExprOp::Pow: { const double x = num(e.args[0], f), y = num(e.args[1], f); return fgsg_rt_pow(x, y); }
    case ExprOp::Eq:
    case ExprOp::Ne: {
      bool eq;
      if (e.args[0].type == ir::Type::Vec3) {
        const rt::Vec3 x = vec(e.args[0], f), y = vec(e.args[1], f);
        eq = x == y;
      } else {
        const double x = num(e.args[0], f), y = num(e.args[1], f);
        eq = x == y;
      }
      return (e.op == ExprOp::Eq) == eq ? 1.0 : 0.0;
    }
    case ExprOp::Lt: { const double x = num(e.args[0], f), y = num(e.args[1], f); return x < y ? 1.0 : 0.0; }
    case ExprOp::Le: { const double x = num(e.args[0], f), y = num(e.args[1], f); return x <= y ? 1.0 : 0.0; }
    case ExprOp::Gt: { const double x = num(e.args[0], f), y = num(e.args[1], f); return x > y ? 1.0 : 0.0; }
    case ExprOp::Ge: { const double x = num(e.args[0], f), y = num(e.args[1], f); return x >= y ? 1.0 : 0.0; }
    case ExprOp::And: return truth(e.args[0], f) && truth(e.args[1], f) ? 1.0 : 0.0;
    case ExprOp::Or: return truth(e.args[0], f) || truth(e.args[1], f) ? 1.0 : 0.0;
    case ExprOp::Select: return truth(e.args[0], f) ? num(e.args[1], f) : num(e.args[2], f);
    case ExprOp::Call: return call(e, f);
    case ExprOp::Rand: {
      // Bounds first, then the draw: the order every engine follows.
      const double lo = num(e.args[0], f), hi = num(e.args[1], f);
      return fgsg_rt_rand_scale(lo, hi, f.rng->next());
    }
    case ExprOp::Query: return query(e, f);
    case ExprOp::VecElem: return vec(e.args[0], f)[e.index];
    case ExprOp::Join: {
      const double x = num(e.args[0], f), y = num(e.args[1], f);
      try {
        return joined_.join(x, e.args[0].type, y, e.args[1].type);
      } catch (DeriveError& error) {
        if (error.loc.line == 0) error.loc = e.loc;  // the join's own place in the grammar
        throw;
      }
    }
    case ExprOp::MakeVec: break;
  }
  throw DeriveError{e.loc, "R900", "internal: a vector was used as a number"};
}

rt::Vec3 Evaluator::vec(const ir::Expr& e, const Frame& f) const {
  using ir::ExprOp;
  switch (e.op) {
    case ExprOp::Const: return {e.vec[0], e.vec[1], e.vec[2]};
    case ExprOp::Param: return {f.params[e.index], f.params[e.index + 1], f.params[e.index + 2]};
    case ExprOp::Attr: return {attrs_[3 * e.index], attrs_[3 * e.index + 1], attrs_[3 * e.index + 2]};
    case ExprOp::MakeVec: return {num(e.args[0], f), num(e.args[1], f), num(e.args[2], f)};
    case ExprOp::Neg: return -vec(e.args[0], f);
    case ExprOp::Add: { const rt::Vec3 x = vec(e.args[0], f), y = vec(e.args[1], f); return x + y; }
    case ExprOp::Sub: { const rt::Vec3 x = vec(e.args[0], f), y = vec(e.args[1], f); return x - y; }
    case ExprOp::Mul:
      if (e.args[0].type == ir::Type::Vec3) {
        const rt::Vec3 v = vec(e.args[0], f);
        const double s = num(e.args[1], f);
        return v * s;
      } else {
        const double s = num(e.args[0], f);
        const rt::Vec3 v = vec(e.args[1], f);
        return s * v;
      }
    case ExprOp::Div: {
      const rt::Vec3 v = vec(e.args[0], f);
      const double s = num(e.args[1], f);
      return v / s;
    }
    case ExprOp::Select: return truth(e.args[0], f) ? vec(e.args[1], f) : vec(e.args[2], f);
    case ExprOp::Call:
      if (static_cast<ir::Builtin>(e.index) == ir::Builtin::Normalize) {
        rt::Vec3 v = vec(e.args[0], f);
        double n = fgsg_rt_vec_length(v.x(), v.y(), v.z());
        return n > 0 ? rt::Vec3(v / n) : v;
      }
      break;
    case ExprOp::Query:
      if (static_cast<ir::Query>(e.index) == ir::Query::Field) {
        requireScope(e, f);
        return f.host->fieldVector(*f.scope, e.env, m_.strings[e.extra], e.loc);
      }
      break;
    default: break;
  }
  throw DeriveError{e.loc, "R900", "internal error: a vector expression the interpreter cannot read"};
}

double Evaluator::call(const ir::Expr& e, const Frame& f) const {
  using ir::Builtin;
  auto a = [&](int k) { return num(e.args[k], f); };
  switch (static_cast<Builtin>(e.index)) {
    case Builtin::Sin: return fgsg_rt_sin_deg(a(0));
    case Builtin::Cos: return fgsg_rt_cos_deg(a(0));
    case Builtin::Tan: return fgsg_rt_tan_deg(a(0));
    case Builtin::Asin: return fgsg_rt_asin_deg(a(0));
    case Builtin::Acos: return fgsg_rt_acos_deg(a(0));
    case Builtin::Atan: return fgsg_rt_atan_deg(a(0));
    case Builtin::Atan2: {
      const double y = a(0), x = a(1);
      return fgsg_rt_atan2_deg(y, x);
    }
    case Builtin::Sqrt: return std::sqrt(a(0));
    case Builtin::Abs: return std::abs(a(0));
    case Builtin::Min: { const double x = a(0), y = a(1); return std::min(x, y); }
    case Builtin::Max: { const double x = a(0), y = a(1); return std::max(x, y); }
    case Builtin::Floor: return std::floor(a(0));
    case Builtin::Ceil: return std::ceil(a(0));
    case Builtin::Round: return fgsg_rt_round(a(0));
    case Builtin::Clamp: {
      const double x = a(0), lo = a(1), hi = a(2);
      return std::min(std::max(x, lo), hi);
    }
    case Builtin::Lerp: {
      const double x = a(0), y = a(1), t = a(2);
      return x + (y - x) * t;
    }
    case Builtin::Pow: { const double x = a(0), y = a(1); return fgsg_rt_pow(x, y); }
    case Builtin::Exp: return fgsg_rt_exp(a(0));
    case Builtin::Log: return fgsg_rt_log(a(0));
    case Builtin::Sign: { const double x = a(0); return (x > 0) - (x < 0); }
    case Builtin::Length: {
      const rt::Vec3 v = vec(e.args[0], f);
      return fgsg_rt_vec_length(v.x(), v.y(), v.z());
    }
    case Builtin::Dot: {
      const rt::Vec3 x = vec(e.args[0], f), y = vec(e.args[1], f);
      return fgsg_rt_vec_dot(x.x(), x.y(), x.z(), y.x(), y.y(), y.z());
    }
    case Builtin::Normalize: break;
  }
  throw DeriveError{e.loc, "R900", "internal: unknown builtin"};
}

void Evaluator::requireScope(const ir::Expr& e, const Frame& f) {
  if (!f.scope)
    throw DeriveError{e.loc, "R006",
                      "scope queries cannot be answered while a parallel derivation rewrites "
                      "its string: modules get their scope only when the turtle interprets it"};
}

double Evaluator::query(const ir::Expr& e, const Frame& f) const {
  using ir::Query;
  const auto q = static_cast<Query>(e.index);
  if (q != Query::ShapeDepth && q != Query::ShapeIndex && q != Query::Feature) requireScope(e, f);
  if (ir::isGeometryQuery(q))
    return f.host->geometry(q, *f.scope, f.geom ? *f.geom : rt::GeomRef{},
                            q == Query::GeometryIsPlanar ? num(e.args[0], f)
                            : q == Query::GeometryAngle || q == Query::GeometryDu || q == Query::GeometryDv
                                ? double(e.extra)
                                : 0.0,
                            e.loc);
  if (ir::isContextQuery(q))
    return f.host->context(q, e.extra, string(num(e.args[0], f)), *f.scope, f.geom ? *f.geom : rt::GeomRef{}, e.loc);
  switch (q) {
    case Query::ScopeSx: return f.scope->S.x();
    case Query::ScopeSy: return f.scope->S.y();
    case Query::ScopeSz: return f.scope->S.z();
    case Query::ScopePx: return f.scope->P.x();
    case Query::ScopePy: return f.scope->P.y();
    case Query::ScopePz: return f.scope->P.z();
    case Query::ShapeDepth: return f.depth;
    case Query::ShapeIndex: return f.index;
    case Query::ShapeVisible: return f.host->visible(*f.scope, string(num(e.args[0], f)), e.loc);
    case Query::ScopeOcc: return f.host->occlusion(*f.scope, e.loc);
    case Query::Field:
      return f.host->fieldNumber(*f.scope, e.env, m_.strings[e.extra], e.loc);
    case Query::Texture: return f.host->texture(*f.scope, e.env, e.loc);
    case Query::Feature:
      return f.host->feature(m_.strings[e.extra], e.args.empty() ? std::string() : string(num(e.args[0], f)), e.loc);
    case Query::ShapeSplitIndex: return f.scope->place.splitIndex;
    case Query::ShapeSplitTotal: return f.scope->place.splitTotal;
    case Query::ShapeCompIndex: return f.scope->place.compIndex;
    case Query::ShapeCompTotal: return f.scope->place.compTotal;
    case Query::ShapeCompSel: return compSelector(m_, f.scope->place, e.extra);
    default: break;  // the geometry queries, above
  }
  throw DeriveError{e.loc, "R900", "internal: unknown query"};
}

namespace {

// Reads `text` as a value of attribute `a` into out[0..2]; false when it is not one. A
// string takes any text (the caller interns it).
bool readAttributeValue(const ir::Module& m, int a, const std::string& text, double out[3],
                        std::string& expected) {
  switch (m.attrs[a].type) {
    case ir::Type::Num: {
      char* end = nullptr;
      const double v = std::strtod(text.c_str(), &end);
      expected = "a number";
      if (text.empty() || *end != '\0' || !std::isfinite(v)) return false;
      out[0] = v;
      return true;
    }
    case ir::Type::Bool:
      expected = "true or false";
      if (text != "true" && text != "false" && text != "1" && text != "0") return false;
      out[0] = (text == "true" || text == "1") ? 1.0 : 0.0;
      return true;
    case ir::Type::Str: return true;
    case ir::Type::Vec3: {
      double x, y, z;
      char tail;
      expected = "x,y,z";
      if (std::sscanf(text.c_str(), "%lf,%lf,%lf%c", &x, &y, &z, &tail) != 3) return false;
      out[0] = x, out[1] = y, out[2] = z;
      return true;
    }
  }
  return false;
}

}  // namespace

std::string attributeOverrideProblem(const ir::Module& m, const std::string& name, const std::string& text) {
  const int a = m.findAttr(name);
  if (a < 0) {
    std::string known;
    std::vector<std::string> names;
    for (const auto& at : m.attrs) {
      known += (known.empty() ? "" : ", ") + at.name;
      names.push_back(at.name);
    }
    const std::string meant = frontend::closestName(name, names);
    return name + ": the grammar declares no attr '" + name + "'" +
           (meant.empty() ? "" : "; did you mean '" + meant + "'?") +
           (known.empty() ? " (it declares none)" : " (attrs: " + known + ")");
  }
  double value[3];
  std::string expected;
  if (!readAttributeValue(m, a, text, value, expected)) return name + "=" + text + ": expected " + expected;
  if (a == m.countAttr && !(value[0] >= 0 && value[0] <= 2147483647.0 && value[0] == std::floor(value[0])))
    return name + "=" + text + ": `derive " +
           (m.mode == ir::DeriveMode::Parallel ? "parallel" : m.mode == ir::DeriveMode::DepthFirst ? "depthfirst" : "breadthfirst") +
           " " + name + "` needs a whole number from 0 to 2147483647";
  return "";
}

int parallelDerivationLength(const ir::Module& m, const std::vector<std::pair<std::string, std::string>>& overrides) {
  if (m.mode != ir::DeriveMode::Parallel) return -1;
  if (m.countAttr < 0) return m.steps;
  ir::Module values = m;  // attributeSlots interns string values in the module it reads
  const double count = attributeSlots(values, overrides)[3 * size_t(m.countAttr)];
  // As Derivation reads it: a value out of range (an import's attr) leaves the grammar's N.
  return count >= 0 && count <= 2147483647.0 ? int(count) : m.steps;
}

namespace {

// A .cga attr whose default texture() or i() took as its file (ir/pinned_attr.h) must keep it.
void checkFilesFixedAtCompile(const ir::Module& m, const std::vector<double>& slots) {
  for (size_t i = 0; i < m.attrs.size(); ++i) {
    const ir::Attr& at = m.attrs[i];
    for (const ir::AttrAnnotation& note : at.annotations) {
      if (note.name != ir::kPinnedAttrAnnotation || at.type != ir::Type::Str) continue;
      const double id = slots[3 * i];
      const std::string given = id >= 0 && id < double(m.strings.size()) ? m.strings[size_t(id)] : "";
      const std::string fixed = at.value.num >= 0 && at.value.num < double(m.strings.size())
                                    ? m.strings[size_t(at.value.num)] : "";
      if (given == fixed) continue;
      ir::Loc loc;
      for (const auto& [key, text] : note.args) (key == "line" ? loc.line : loc.col) = std::atoi(text.c_str());
      throw DeriveError{loc, "R038",
                        "attr '" + at.name + "' = \"" + given + "\": this file takes its default \"" + fixed +
                            "\" as a texture's or an asset's file, found when the grammar is compiled; "
                            "another file from --set or a lot's property (CityEngine CGA) is not supported yet"};
    }
  }
}

}  // namespace

uint64_t attributeRandomKey(uint64_t seed, size_t start) {
  return rt::childKey(rt::keyWithSalt(rt::rootKey(seed), 0xa77b5eedull), start);
}

std::vector<double> attributeSlots(
    ir::Module& m, const std::vector<std::pair<std::string, std::string>>& overrides, uint64_t randomKey) {
  std::vector<double> slots(3 * m.attrs.size(), 0.0);
  for (size_t i = 0; i < m.attrs.size(); ++i) {
    const ir::Expr& v = m.attrs[i].value;
    slots[3 * i] = m.attrs[i].type == ir::Type::Vec3 ? v.vec[0] : v.num;
    slots[3 * i + 1] = v.vec[1];
    slots[3 * i + 2] = v.vec[2];
  }
  for (const auto& [name, text] : overrides) {
    const std::string problem = attributeOverrideProblem(m, name, text);
    if (!problem.empty()) throw DeriveError{{}, "R010", "--set " + problem};
    const int a = m.findAttr(name);
    double* out = &slots[3 * a];
    std::string expected;
    readAttributeValue(m, a, text, out, expected);
    if (m.attrs[a].type == ir::Type::Str) out[0] = m.internString(text);
  }
  // An import's attr set from the importer's attrs follows their values now known, unless
  // it is set itself; those it reads come before it.
  for (size_t i = 0; i < m.attrs.size(); ++i) {
    const ir::Attr& at = m.attrs[i];
    if (!at.fromImporter ||
        std::any_of(overrides.begin(), overrides.end(), [&](const auto& o) { return o.first == at.name; }))
      continue;
    const Evaluator ev(m, slots);
    rt::RandomStream rng{rt::childKey(randomKey, i), 0};  // an attr's draws do not depend on the others'
    Frame frame;
    frame.rng = &rng;
    ev.store(at.importerValue, frame, &slots[3 * i]);
    if (at.type == ir::Type::Str) slots[3 * i] = m.internString(ev.string(slots[3 * i]));  // a joined one too
  }
  checkFilesFixedAtCompile(m, slots);
  return slots;
}

}  // namespace fgsg::backend
