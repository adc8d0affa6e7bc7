// cpfg's and lpfg's query modules (Prusinkiewicz, James and Mech 1994, "Synthetic
// topiary"; lpfg's ?P ?H ?U ?L): modules of a parallel derivation's string whose
// arguments the turtle fills with its state where it reads them — after the axiom and
// after each step (with its decomposition), so the next step's contexts and guards read
// where the plant is. The pass draws nothing (Derivation::answerQueries,
// query_modules.cpp); the symbols are ordinary symbols of the grammar otherwise. The
// environmental query ?E (Mech and Prusinkiewicz 1996) is answered the same way, by the
// grammar's first field where the turtle stands (SurfaceWorld::environmentQuery).
#pragma once

#include <string>

namespace fgsg::backend {

enum class QueryModule : int8_t {
  None = -1,
  Position,  // ?P: the turtle's position
  Heading,   // ?H: H (the scope's Y)
  Up,        // ?U: U (the scope's Z)
  Left,      // ?L: L (the scope's -X)
  Environment,  // ?E: the first field at the surface point closest to the turtle
};

inline QueryModule queryModuleNamed(const std::string& name) {
  if (name == "?P") return QueryModule::Position;
  if (name == "?H") return QueryModule::Heading;
  if (name == "?U") return QueryModule::Up;
  if (name == "?L") return QueryModule::Left;
  if (name == "?E") return QueryModule::Environment;
  return QueryModule::None;
}

}  // namespace fgsg::backend
