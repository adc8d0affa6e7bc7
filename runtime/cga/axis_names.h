// The scope axes as messages name them ("split along X: ..."): one definition for every
// cga file that names an axis, where private copies would clash in a unity batch (#47).
#pragma once

namespace fgsg::rt::cga {

// The name of scope axis 0, 1 or 2: kAxisNames[axis].
inline constexpr char kAxisNames[] = "XYZ";

}  // namespace fgsg::rt::cga
