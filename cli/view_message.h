// The messages a page may send to `fgsg view` (cli/view_session.h), checked before they
// change anything: a size cap, a nesting cap before any recursive parse, then a strict
// schema. A message that fails gets a {"type":"rejected"} reply and is otherwise ignored.
//   {"type":"set", "attrs":{"name": "text" | number | boolean, ...}, "seed": N}
//   {"type":"pick", "instance": N}
// Whether each name is an attribute of the grammar, and each value one of its kind, the
// session checks against the grammar it has compiled.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace fgsg::cli {

constexpr size_t kMaxPageMessageBytes = size_t(64) << 10;
constexpr int kMaxPageMessageDepth = 4;
constexpr size_t kMaxPageAttrs = 256;
constexpr size_t kMaxPageNameBytes = 128;
constexpr size_t kMaxPageValueBytes = 4096;

struct PageRequest {
  enum class Kind { Set, Pick };
  Kind kind = Kind::Set;
  bool hasAttrs = false;  // set: the page's values replace all earlier ones
  std::vector<std::pair<std::string, std::string>> attrs;  // name, value as --set writes it
  bool hasSeed = false;
  uint64_t seed = 0;
  uint32_t instance = 0;  // pick
};

// False with a short reason (no text of the message quoted beyond 60 bytes).
bool parsePageRequest(const std::string& text, PageRequest& out, std::string& reason);

// The deepest nesting of [ and { outside strings is at most `limit` (a linear scan).
bool jsonNestingWithin(const std::string& text, int limit);

}  // namespace fgsg::cli
