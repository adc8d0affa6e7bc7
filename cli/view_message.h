// The messages a page may send to `fgsg view` (cli/view_session.h), checked before they
// change anything: a size cap, a nesting cap before any recursive parse, then a strict
// schema. A message that fails gets a {"type":"rejected"} reply and is otherwise ignored.
//   {"type":"set", "attrs":{"name": "text" | number | boolean, ...}, "seed": N, "step": N}
//                                  ("step": an L-system's derivation step, fgsg view --steps)
//   {"type":"pick", "instance": N}
//   {"type":"seeds", "seeds":[[x,y,z] | [x,y,z,dx,dy,dz], ...]}   (the whole list, #49)
//   {"type":"paint", "texture":"NAME", "stroke":N, "dabs":[[x,y,z], ...], "radius":R,
//    "strength":S, "value":G, "erase":false}                       (a brush stroke, #49)
//   {"type":"undo"}, {"type":"redo"}                               (the last paint stroke)
//   {"type":"undo", "history":"field"}, {"type":"redo", "history":"field"}
//                                    (the last field design edit, view_field_history.h)
//   {"type":"field"}                                   (the field overlay, view_field.h)
//   {"type":"resend"}              (the model again, every piece of it: the page lost some)
//   {"type":"fieldElement", "op":"add", "kind":"wedge", "position":[x,y,z],
//    "direction":[dx,dy,dz] (regular only), "strength":S}     (a design element added, #49)
//   {"type":"fieldElement", "op":"move", "index":N, "position":[x,y,z], "drag":D}
//                                    (the moves of one drag share D: one undo step)
//   {"type":"fieldElement", "op":"strength", "index":N, "strength":S}
//   {"type":"fieldElement", "op":"delete", "index":N}         (view_field_edit.h)
// Whether each name is an attribute of the grammar, and each value one of its kind, the
// session checks against the grammar it has compiled.
#pragma once

#include <array>
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
constexpr size_t kMaxPageSeeds = 1024;   // a seed file the page edits by hand
constexpr size_t kMaxPageDabs = 256;     // brush positions in one paint message
constexpr double kMaxPageCoordinate = 1e9;  // |x|, beyond any surface's size
constexpr uint32_t kMaxPageStep = 2147483647;  // `derive parallel N;`'s largest N
constexpr double kMaxPageElementStrength = 1000;  // |strength| of a field design element
constexpr uint32_t kMaxPageElementIndex = 1000000;  // beyond any design block's elements
constexpr uint64_t kMaxPageDrag = (uint64_t(1) << 53) - 1;  // a drag's number: a JavaScript safe integer

struct PageSeed {
  double point[3] = {0, 0, 0};
  bool hasDirection = false;
  double direction[3] = {1, 0, 0};
};

// One piece of a brush stroke: every texel whose surface point lies within `radius` of a
// dab moves `strength` of the way to `value` (erase: to the texture as it was loaded).
struct PagePaint {
  std::string texture;  // the grammar's texture name, not a file
  uint64_t stroke = 0;  // pieces of one stroke share it: one undo step
  std::vector<std::array<double, 3>> dabs;
  double radius = 0, strength = 1, value = 1;
  bool erase = false;
};

// One edit of the design elements of the grammar's first field (view_field_edit.h). Which
// words each operation takes is checked here; the index and the position against the
// grammar and its surface by the session.
struct PageFieldElement {
  enum class Op { Add, Move, Delete, Strength };
  Op op = Op::Add;
  uint32_t index = 0;        // move, delete, strength: the element's place among the design's elements
  std::string kind;          // add: regular wedge trisector node centre saddle
  double position[3] = {0, 0, 0};  // add, move
  bool hasDirection = false;       // add, a regular element only: its direction
  double direction[3] = {1, 0, 0};
  bool hasStrength = false;        // add (optional), strength
  double strength = 1;
  uint64_t drag = 0;               // move (optional, 1 to kMaxPageDrag): the moves of one drag
};

struct PageRequest {
  enum class Kind { Set, Pick, Seeds, Paint, Undo, Redo, Field, FieldElement, Resend };
  Kind kind = Kind::Set;
  enum class History { Paint, Field };
  History history = History::Paint;  // undo, redo: whose last edit
  bool hasAttrs = false;  // set: the page's values replace all earlier ones
  std::vector<std::pair<std::string, std::string>> attrs;  // name, value as --set writes it
  bool hasSeed = false;
  uint64_t seed = 0;
  bool hasStep = false;  // set: the derivation step to show (the session checks its length)
  uint32_t step = 0;
  uint32_t instance = 0;  // pick
  std::vector<PageSeed> seeds;  // seeds
  PagePaint paint;              // paint
  PageFieldElement element;     // fieldElement
};

// False with a short reason (no text of the message quoted beyond 60 bytes).
bool parsePageRequest(const std::string& text, PageRequest& out, std::string& reason);

// The deepest nesting of [ and { outside strings is at most `limit` (a linear scan).
bool jsonNestingWithin(const std::string& text, int limit);

}  // namespace fgsg::cli
