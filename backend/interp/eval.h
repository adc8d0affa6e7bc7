// Expression evaluation for the interpreter: the reference semantics of every IR
// expression. Numbers are doubles; booleans 0/1; strings their id in the string table;
// vectors three doubles. Angles are degrees everywhere (trig functions included), as
// in the scope commands.
#pragma once

#include "backend/interp/joined_strings.h"
#include "ir/ir.h"
#include "runtime/geometry.h"
#include "runtime/random.h"
#include "runtime/scope.h"

#include <algorithm>
#include <string>
#include <vector>

namespace fgsg::rt {
struct DeriveOptions;
}

namespace fgsg::backend {

// A user-facing problem found while deriving (located in the grammar).
struct DeriveError {
  ir::Loc loc;
  std::string code;
  std::string message;
};

// What a query may ask about the shape being derived. Scope is null in a parallel
// derivation's rewriting steps, where modules have no scope yet.
struct QueryHost {
  virtual ~QueryHost() = default;
  virtual double visible(const rt::Scope& scope, const std::string& target, ir::Loc at) = 0;
  virtual double occlusion(const rt::Scope& scope, ir::Loc at) = 0;  // a string id
  // F.member of the field at environment entry `env`, at the scope's surface point.
  virtual double fieldNumber(const rt::Scope& scope, uint32_t env, const std::string& member,
                             ir::Loc at) = 0;
  virtual rt::Vec3 fieldVector(const rt::Scope& scope, uint32_t env, const std::string& member,
                               ir::Loc at) = 0;
  // context.NAME(texCoord): the texture at environment entry `env`, sampled at the
  // scope's surface point.
  virtual double texture(const rt::Scope& scope, uint32_t env, ir::Loc at) = 0;
  // Feature.member inside Cells (`arg`: Feature.label's string, else empty): a number, or
  // 1 / 0 for a truth value.
  virtual double feature(const std::string& member, const std::string& arg, ir::Loc at) = 0;
  // Geometry.area ... (CGA's geometry.*()) of the shape's own geometry; `arg`: isPlanar's
  // tolerance in degrees, angle's selector (the query's extra).
  virtual double geometry(ir::Query q, const rt::Scope& scope, const rt::GeomRef& geom, double arg, ir::Loc at) {
    (void)q, (void)scope, (void)geom, (void)arg;
    throw DeriveError{at, "R900", "internal: geometry queries are not answered here"};
  }
  // CGA's inside/overlaps/touches (1 or 0), minimumDistance and contextCount of the shape
  // among the context shapes of `target` (an ir::ContextTarget) with `label` ("": any).
  virtual double context(ir::Query q, uint32_t target, const std::string& label, const rt::Scope& scope,
                         const rt::GeomRef& geom, ir::Loc at) {
    (void)q, (void)target, (void)label, (void)scope, (void)geom;
    throw DeriveError{at, "R900", "internal: context queries are not answered here"};
  }
};

// CGA's comp.sel of a shape at `place` (Query::ShapeCompSel): the string id of the name of
// the selector that chose it (ir::Module::compSelectors), else `noneId` (the string "").
inline double compSelector(const ir::Module& m, const rt::Scope::Place& place, uint32_t noneId) {
  return place.compSel > 0 && place.compSel <= m.compSelectors.size() ? m.compSelectors[place.compSel - 1] : noneId;
}

struct Frame {
  const double* params = nullptr;  // the rule's parameter block
  rt::RandomStream* rng = nullptr;
  const rt::Scope* scope = nullptr;
  uint32_t depth = 0;
  uint32_t index = 0;
  QueryHost* host = nullptr;
  const rt::GeomRef* geom = nullptr;  // the shape's own geometry (null: its scope box)
};

class Evaluator {
 public:
  Evaluator(const ir::Module& m, std::vector<double> attrSlots)
      : m_(m), attrs_(std::move(attrSlots)), joined_(m.strings) {}

  // Constants and parameters, most arguments in practice, are read without a call.
  double num(const ir::Expr& e, const Frame& f) const {
    if (e.op == ir::ExprOp::Const) return e.num;
    if (e.op == ir::ExprOp::Param) return f.params[e.index];
    if (e.op == ir::ExprOp::Attr) return attrs_[3 * e.index];
    return numSlow(e, f);
  }
  rt::Vec3 vec(const ir::Expr& e, const Frame& f) const;
  bool truth(const ir::Expr& e, const Frame& f) const { return num(e, f) != 0.0; }
  // Writes a value of any type into slots (1 or 3 doubles).
  void store(const ir::Expr& e, const Frame& f, double* out) const {
    if (e.type == ir::Type::Vec3) {
      const rt::Vec3 v = vec(e, f);
      out[0] = v.x(), out[1] = v.y(), out[2] = v.z();
    } else {
      out[0] = num(e, f);
    }
  }
  // A string id's text: the module's, or one a string `+` joined while deriving.
  const std::string& string(double id) const { return joined_.text(id); }
  // CGA's string `+` (ExprOp::Join), for compiled code too (fgsg_rt_join).
  double join(double a, ir::Type ta, double b, ir::Type tb) const { return joined_.join(a, ta, b, tb); }
  const JoinedStrings& joinedStrings() const { return joined_; }
  // The attribute slots as compiled code reads them (three per attribute).
  const double* attrData() const { return attrs_.data(); }
  // Another set of values (a lot's, --lots) in the same slots: compiled code keeps reading
  // them where it did.
  void setAttrSlots(const std::vector<double>& slots) { std::copy(slots.begin(), slots.end(), attrs_.begin()); }
  const std::vector<double>& attrSlots() const { return attrs_; }

 private:
  double numSlow(const ir::Expr& e, const Frame& f) const;
  double call(const ir::Expr& e, const Frame& f) const;
  double query(const ir::Expr& e, const Frame& f) const;
  // R006 for a query that needs a scope where there is none (a parallel rewriting step).
  static void requireScope(const ir::Expr& e, const Frame& f);

  const ir::Module& m_;
  std::vector<double> attrs_;  // three slots per attribute
  mutable JoinedStrings joined_;  // evaluating is const; joining a string records it
};

// Why `name=text` cannot override an attribute of m: an unknown name, or a value that is
// not of the attribute's type ("count=lots: expected a number"); empty when it can. Shared
// by `--set` (checked when deriving) and fgsg_set_attribute (checked when set).
std::string attributeOverrideProblem(const ir::Module& m, const std::string& name, const std::string& text);

// The attribute values for a derivation: defaults, with `--set name=value` overrides
// parsed by the attribute's type. Throws DeriveError for an unknown name or a bad value.
// A CityEngine attr computed from others may draw random numbers (`attr h = rand(30, 50)`):
// from `randomKey` (attributeRandomKey), so once per start shape and alike in every engine.
std::vector<double> attributeSlots(
    ir::Module& m, const std::vector<std::pair<std::string, std::string>>& overrides, uint64_t randomKey = 0);

// The key of the random numbers the attrs of start shape `start` (a lot's index, 0 without
// lots) draw under `seed`.
uint64_t attributeRandomKey(uint64_t seed, size_t start);

// How many steps an L-system (`derive parallel N;`) rewrites with these `--set` values:
// N, or its attr's value (`derive parallel n;`); -1 for a sequential grammar. What
// `--step` is checked against. Throws DeriveError as attributeSlots does.
int parallelDerivationLength(const ir::Module& m, const std::vector<std::pair<std::string, std::string>>& overrides);

// The attribute values for each lot of `options.lots`: attributeSlots with, after --set,
// every attr named like one of the lot's properties set to its value, and an attr
// `lot_area` set to the lot's area. Throws DeriveError (R010) naming the lot for a value
// that does not fit its attr.
std::vector<std::vector<double>> lotAttributeSlots(ir::Module& m, const rt::DeriveOptions& options);

}  // namespace fgsg::backend
