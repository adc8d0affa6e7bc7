// The result of a derivation: every terminal instance placed by I / IC / IM (or drawn
// by a turtle F), with the asset, the 4x4 transform that maps the asset's unit box
// into world space, the symbol of the shape that placed it, and its parameters.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace fgsg::rt {

struct Instance {
  uint32_t asset = 0;           // index into InstanceList::assets
  uint32_t symbol = 0;          // index into InstanceList::symbols
  std::array<double, 16> transform{};  // column-major, unit box [0,1]^3 -> world
  std::array<float, 3> color{0.8f, 0.8f, 0.8f};
  uint32_t firstParam = 0;      // into InstanceList::params
  uint32_t paramCount = 0;
};

// How a parameter's slots read: a number, a boolean (0/1), a string (an index into
// InstanceList::strings) or a vector (three slots).
enum class ParamKind : uint8_t { Number, Boolean, String, Vector };

struct InstanceList {
  std::vector<std::string> assets;   // asset names as written in the grammar
  std::vector<std::string> symbols;  // symbol names
  std::vector<Instance> instances;
  std::vector<double> params;        // parameter slots of all instances
  // Per symbol, the kinds of its parameters; a symbol without an entry has plain numbers.
  std::vector<std::vector<ParamKind>> paramKinds;
  std::vector<std::string> strings;  // the texts string parameters refer to
};

}  // namespace fgsg::rt
