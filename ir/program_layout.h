// How a grammar's code is numbered for compiled engines: every block (the axiom, each
// rule alternative, each split / roof / Lock body) and every op gets an id, in one
// deterministic walk. Code generation and the engine that runs the generated code
// both number the same IR this way, so ids are all that crosses between them.
#pragma once

#include "ir/ir.h"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace fgsg::ir {

struct ProgramLayout {
  // Block ids: 0 the axiom, 1 + a global alternative index for each alternative, then
  // the bodies of ops, each op's bodies consecutive.
  std::vector<const Block*> blocks;
  std::vector<uint32_t> firstAlternative;  // per rule: global index of its first alternative
  uint32_t alternativeCount = 0;
  std::vector<const Op*> ops;  // by op id: every op of every block, blocks in id order
  std::vector<uint32_t> firstBody;  // by op id: block id of bodies[0] (none: ~0u)
  std::vector<uint32_t> firstOp;    // by block id: the id of its first op (a block's ops are consecutive)

  uint32_t alternativeBlock(uint32_t rule, uint32_t alternative) const {
    return 1 + firstAlternative[rule] + alternative;
  }
  // The block id of op's body `k`; op must belong to the module this layout was made for.
  uint32_t bodyBlock(const Op& op, size_t k) const { return firstBody[opId(op)] + static_cast<uint32_t>(k); }
  uint32_t opId(const Op& op) const { return opIds_.at(&op); }

  std::unordered_map<const Op*, uint32_t> opIds_;
};

// Numbers `m`; the layout points into m, which must outlive it and not change.
ProgramLayout layoutProgram(const Module& m);

}  // namespace fgsg::ir
