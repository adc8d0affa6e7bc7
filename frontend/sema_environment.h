// Semantic analysis of the environment declarations a field-guided grammar grows in:
// `surface ...;` and `field NAME = ...;` (docs/language.md, Declarations). Checks them
// (E033..E040) and evaluates them to constants for lowering (SemaResult::surface and
// SemaResult::fieldSpecs). Part of frontend/sema; run by analyze() after the constants.
#pragma once

#include "frontend/sema.h"

#include <functional>

namespace fgsg::frontend {

// Evaluates a constant expression (numbers, earlier constants, math functions); false
// when the expression is not constant.
using ConstEvaluator = std::function<bool(const Expr&, ConstValue&)>;
// Checks a scalar field's expression over the surface (surfacePointNames, consts, attrs,
// math): true when it is a number, else false with the errors reported.
using SurfaceExpressionChecker = std::function<bool(const Expr&)>;

void checkSurfaceAndFields(const Program& program, SemaResult& res, Diagnostics& diags,
                           const ConstEvaluator& evalConst, const SurfaceExpressionChecker& checkExpression);

// The procedural surfaces `surface NAME(args);` knows, with their signatures.
struct SurfaceGeneratorInfo {
  const char* name;
  int args;
  const char* signature;  // "torus(R, r)"
};
const SurfaceGeneratorInfo* findSurfaceGenerator(const std::string& name);

}  // namespace fgsg::frontend
