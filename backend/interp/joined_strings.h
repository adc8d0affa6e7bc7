// CityEngine's string `+` at run time (ir::ExprOp::Join): "roof.area." + kind, "floor" + 3,
// "Result: " + true. The joined strings of one derivation get ids after the module's own
// (Module::strings), and a text the module holds keeps the module's id, so that `==` on
// string ids stays `==` on texts. Both engines join here: the interpreter through its
// Evaluator, compiled code through fgsg_rt_join (runtime/abi.def).
#pragma once

#include "ir/ir.h"

#include <string>
#include <unordered_map>
#include <vector>

namespace fgsg::backend {

// A number as CityEngine prints it in a string: whole numbers without a decimal point
// ("floor" + 3 is "floor3", str(1.69 - 69/100) "1"), others in the fewest significant
// digits that read back as the same double ("1.69", 1/3 as "0.3333333333333333");
// -0 is "0", infinities "inf" and "-inf", NaN "nan".
std::string cityEngineNumberText(double v);

// The longest text a string `+` may make: a rule that keeps joining a string to itself
// doubles it each step and would otherwise take all memory before any limit is asked.
constexpr size_t kMaxJoinedText = size_t(1) << 20;

class JoinedStrings {
 public:
  explicit JoinedStrings(const std::vector<std::string>& moduleStrings) : module_(moduleStrings) {}

  // a + b, each read as its type says (Num, Bool, or Str: a string id); the id of the result.
  // Throws DeriveError R020 (no location: the caller knows it) past kMaxJoinedText.
  double join(double a, ir::Type ta, double b, ir::Type tb);
  // The text of a string id: the module's, or a joined one; empty for an unknown id.
  const std::string& text(double id) const;
  // Whether `id` names a string (the module's or a joined one).
  bool holds(double id) const { return id >= 0 && id < double(module_.size() + joined_.size()); }
  // The joined strings, in id order from the module's count on (for the outputs' tables).
  const std::vector<std::string>& joined() const { return joined_; }

 private:
  std::string valueText(double v, ir::Type t) const;

  const std::vector<std::string>& module_;
  std::vector<std::string> joined_;
  std::unordered_map<std::string, uint32_t> ids_;  // every text with an id, once the first join asks
  size_t indexedModule_ = 0;                        // module strings already in ids_
};

}  // namespace fgsg::backend
