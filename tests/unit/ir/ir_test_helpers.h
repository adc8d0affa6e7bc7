// Builders shared by the IR tests; defined in test_ir.cpp.
#pragma once

#include "ir/ir.h"

#include <cstdint>

namespace fgsg::ir::testing {

Module sampleModule();
Expr param(uint32_t slot, Type t = Type::Num);
Expr binary(ExprOp op, Type t, Expr a, Expr b);

}  // namespace fgsg::ir::testing
