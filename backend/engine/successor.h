// What one running successor works on: its scope and [ ] stack (State), what it knows
// about itself (Exec), and room for one op's evaluated arguments. The core and every
// command module (backend/commands/) pass these along.
#pragma once

#include "runtime/geometry.h"
#include "runtime/lines/line_network.h"
#include "runtime/random.h"
#include "runtime/scope.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace fgsg::backend {

// The turtle's tropism (ABOP eq. 2.4, `@Tp`, `@Ts`): after each F the heading turns by
// elasticity |H x T| towards the direction T. Saved and restored by [ ] as L-Py does.
struct Tropism {
  rt::Vec3 direction = -rt::Vec3::UnitY();  // ABOP's gravitropism, T = (0, -1, 0)
  double elasticity = 0;
};

// The scope a successor works on. Its [ ] stack lives in one shared vector above
// `stackBase`, so pushing allocates nothing once the vector has grown.
struct Saved {
  rt::Scope scope;
  rt::GeomRef geom;
  double width;
  rt::LineCursor line;
  uint32_t bracket = UINT32_MAX;  // its '[' in the sequential string (grammars with contexts)
  Tropism tropism;
  int32_t cylinder = -1;
};
struct State {
  rt::Scope scope;
  rt::GeomRef geom;
  double width = 0.1;
  size_t stackBase = 0;
  rt::LineCursor line;  // the line LineSeg extends (a ']' returns to the '[' point)
  const rt::Scope* origin = nullptr;  // the scope the successor or body started with (Center)
  Tropism tropism;
  int32_t cylinder = -1;  // the generalized cylinder open here (`@Gs`), TurtleCommands' index; -1: none
};

// What one running successor knows: its random stream, key and parameters, the
// children it has written so far, and whether a collision culled its rest.
struct Exec {
  rt::RandomStream* rng;
  uint64_t key;
  uint32_t depth;   // depth of the shapes this successor creates
  uint32_t symbol;  // the shape being rewritten (UINT32_MAX for the axiom)
  const double* params;
  uint32_t childCount;
  bool culled = false;    // the rest of this production is dropped (FGSG §4.4)
  bool collided = false;  // ... because something in it collided
  uint32_t bodyCount = 0; // split and comp parts run so far (context queries' shape tree)
};

// Room for one op's evaluated arguments: on the stack unless a split has many sizes.
struct ArgBuffer {
  double small[16];
  std::vector<double> big;
  double* reserve(uint32_t n) {
    if (n <= 16) return small;
    big.resize(n);
    return big.data();
  }
};

}  // namespace fgsg::backend
