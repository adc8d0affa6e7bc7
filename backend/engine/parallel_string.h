// The string of a parallel (L-system) derivation: modules with their evaluated
// arguments in one pool, and the next string a successor appends to.
#pragma once

#include "ir/ir.h"

#include <cstdint>
#include <vector>

namespace fgsg::backend {

// One module: a shape symbol or a command, with its arguments in the string's pool.
struct StringModule {
  const ir::Op* op = nullptr;  // the op that produced it (Emit for a symbol)
  uint32_t firstArg = 0;
  uint32_t argCount = 0;
  uint64_t key = 0;
  uint32_t index = 0;           // position among the symbols of its successor (Shape.index)
  uint32_t owner = UINT32_MAX;  // symbol whose rule produced it; UINT32_MAX: the axiom
};

// A parallel derivation's next string, which a successor's modules are appended to.
struct StringTarget {
  std::vector<StringModule>* out;
  std::vector<double>* args;
  uint64_t key;     // the rewritten module's key (its children's keys derive from it)
  uint32_t owner;   // the symbol rewritten (UINT32_MAX: the axiom)
  uint32_t child = 0;
  // The rewritten module's parameter slots: an instance its successor places records
  // them (Shape.params in --instances), as a sequential derivation's do.
  const double* ownerParams = nullptr;
  uint32_t ownerParamCount = 0;
};

}  // namespace fgsg::backend
