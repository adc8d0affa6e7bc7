// The reference engine: executes the IR directly. Sequential (CGA/FGSG) derivations
// rewrite one shape at a time by priority, then breadth- or depth-first; parallel
// (L-system) derivations rewrite every module of a string per step and interpret the
// final string with the turtle. Other engines must produce exactly its results.
#pragma once

#include "ir/ir.h"
#include "runtime/assets.h"
#include "runtime/derivation.h"

namespace fgsg::backend {

rt::DeriveResult interpret(const ir::Module& module, const rt::DeriveOptions& options,
                           rt::AssetLibrary& assets);

}  // namespace fgsg::backend
