// A file's extension as the readers compare it: `.OBJ` and `.obj` are one format.
#pragma once

#include <string>

namespace fgsg::rt::io {

// The extension of `path` with its dot, lower-cased (ASCII): "scene.OBJ" -> ".obj";
// "" when it has none.
std::string lowerExtension(const std::string& path);

}  // namespace fgsg::rt::io
