// The reference engine: executes the IR directly, in one backend/engine/ Derivation.
// Sequential (CGA/FGSG) derivations rewrite one shape at a time by priority, then
// breadth- or depth-first; parallel (L-system) derivations rewrite every module of a
// string per step and interpret the final string with the turtle. Other engines must
// produce exactly its results. Compiled code runs inside the same engine (deriveCompiled).
#pragma once

#include "ir/ir.h"
#include "runtime/assets.h"
#include "runtime/derivation.h"

struct FgsgProgram;

namespace fgsg::backend {

rt::DeriveResult interpret(const ir::Module& module, const rt::DeriveOptions& options,
                           rt::AssetLibrary& assets);

// The same derivation with the grammar's successors, guards and probabilities running
// as compiled code (a JIT unit or a compiled library; runtime/abi.h), generated from
// `module` (ir::ProgramLayout numbers both alike). The engine around the code (queues,
// splits, collisions, surfaces) is the interpreter's, so results are bit for bit the
// same. A program whose tables do not match the module is an R900 error.
rt::DeriveResult deriveCompiled(const ir::Module& module, const FgsgProgram& program,
                                const rt::DeriveOptions& options, rt::AssetLibrary& assets);

}  // namespace fgsg::backend
