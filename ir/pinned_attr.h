// A .cga string attr whose default names the file of a texture() or i() (`texture(wallTexture)`):
// the file is found and loaded when the grammar is compiled, so the attr carries this
// annotation, with the line and column of the first such use, and a derivation whose --set
// or lot gives it another value stops with an error there instead of ignoring the value.
#pragma once

namespace fgsg::ir {

inline constexpr const char* kPinnedAttrAnnotation = "fgsg.fileFixedAtCompile";

}  // namespace fgsg::ir
