#include "ir/program_layout.h"

namespace fgsg::ir {

ProgramLayout layoutProgram(const Module& m) {
  ProgramLayout layout;
  layout.blocks.push_back(&m.axiom);
  for (const Rule& r : m.rules) {
    layout.firstAlternative.push_back(layout.alternativeCount);
    layout.alternativeCount += static_cast<uint32_t>(r.alternatives.size());
    for (const Alternative& alt : r.alternatives) layout.blocks.push_back(&alt.ops);
  }
  // Blocks are visited in id order; an op's bodies get the next free ids when the
  // block holding it is visited, so nested bodies come after their parents.
  for (size_t b = 0; b < layout.blocks.size(); ++b) {
    layout.firstOp.push_back(static_cast<uint32_t>(layout.ops.size()));
    for (const Op& op : *layout.blocks[b]) {
      const uint32_t id = static_cast<uint32_t>(layout.ops.size());
      layout.ops.push_back(&op);
      layout.opIds_[&op] = id;
      layout.firstBody.push_back(op.bodies.empty() ? ~0u : static_cast<uint32_t>(layout.blocks.size()));
      for (const Block& body : op.bodies) layout.blocks.push_back(&body);
    }
  }
  return layout;
}

}  // namespace fgsg::ir
