#include "backend/engine/instance_origins.h"

namespace fgsg::backend {

void InstanceOrigins::setup(const ir::Module& m, bool on) {
  on_ = on;
  ruleAt_.clear();
  if (!on) return;
  for (uint32_t r = 0; r < m.rules.size(); ++r)
    for (const ir::Alternative& alt : m.rules[r].alternatives) learn(alt.ops, r);
}

void InstanceOrigins::learn(const ir::Block& ops, uint32_t rule) {
  for (const ir::Op& op : ops) {
    ruleAt_.emplace(key(op.loc), rule);
    for (const ir::Block& body : op.bodies) learn(body, rule);
  }
}

rt::InstanceOrigin InstanceOrigins::of(ir::Loc loc, uint32_t depth) const {
  const auto at = ruleAt_.find(key(loc));
  return {at == ruleAt_.end() ? UINT32_MAX : at->second, depth};
}

}  // namespace fgsg::backend
