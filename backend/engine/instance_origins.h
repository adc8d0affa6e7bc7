// Who placed each instance, for fgsg view's picking (DeriveOptions::recordOrigins): the rule
// whose successor holds the placing op, found by the op's source location, and the placing
// shape's depth.
#pragma once

#include "ir/ir.h"
#include "runtime/instances.h"

#include <cstdint>
#include <unordered_map>

namespace fgsg::backend {

class InstanceOrigins {
 public:
  // Learns where m's rules' ops are; `on` false: of() is never asked.
  void setup(const ir::Module& m, bool on);
  bool on() const { return on_; }
  // The origin of an instance placed by the op at `loc`, its shape at `depth`.
  rt::InstanceOrigin of(ir::Loc loc, uint32_t depth) const;

 private:
  static uint64_t key(ir::Loc loc) { return (uint64_t(uint32_t(loc.line)) << 32) | uint32_t(loc.col); }
  void learn(const ir::Block& ops, uint32_t rule);

  bool on_ = false;
  std::unordered_map<uint64_t, uint32_t> ruleAt_;  // op location -> rule (absent: the axiom)
};

}  // namespace fgsg::backend
