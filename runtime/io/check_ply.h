// PLY files are read by OpenMesh, which sizes its buffers by the counts in the file (the
// header's element counts, each face's list length). This walk over the file checks every
// such count against the bytes that are actually there first.
#pragma once

#include <string>
#include <string_view>

namespace fgsg::rt::io {

// True when the header is well formed and the body holds every element it declares (text
// or binary); otherwise one message naming the file and, for the header, the line.
bool checkPlyStructure(const std::string& path, std::string_view bytes, std::string& error);

}  // namespace fgsg::rt::io
