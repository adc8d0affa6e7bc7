// A float as its shortest round-trip text, byte for byte what std::to_chars(float)
// writes (the fewest digits that read back as the same float; fixed or scientific,
// whichever is shorter, fixed on a tie), at about a third of libstdc++'s cost: the
// digits come from {fmt}'s Dragonbox. The OBJ writer's numbers are most of its cost
// (issue #18).
#pragma once

namespace fgsg::rt::io {

// At most 15 characters ("-1.2345678e-38"); `v` must be finite.
constexpr int kMaxFloatText = 15;
char* putShortestFloat(char* p, float v);

}  // namespace fgsg::rt::io
