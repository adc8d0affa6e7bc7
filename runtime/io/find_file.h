// Where a file a grammar names (a synthesis example, a surface mesh, a field file, a
// picture) is read from: the first search folder holding it, the grammar's own first.
#pragma once

#include <string>
#include <vector>

namespace fgsg::rt::io {

// The path of `name` in the first of `dirs` that holds it as a regular file, else `name`
// as given (so the error names what the grammar wrote).
std::string findFile(const std::string& name, const std::vector<std::string>& dirs);

}  // namespace fgsg::rt::io
