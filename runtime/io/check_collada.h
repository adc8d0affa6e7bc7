// COLLADA files (.dae) are read by assimp, which builds a copy of a node for every
// <instance_node> naming it: 30 nodes that each instance the next one twice become 2^30
// nodes from a 3 KB file. This scan over the XML counts what the node graph expands to,
// before assimp sees the file, and refuses a cycle or an expansion past kMaxColladaNodes
// with the line of the node. assimp also reads an <accessor>'s elements from its source
// array without comparing them with the array's size (count="0": a null pointer, a crash):
// an accessor reading past its array is refused with its line.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace fgsg::rt::io {

// More nodes than this, once every <instance_node> is expanded, is no surface.
constexpr size_t kMaxColladaNodes = size_t(1) << 20;

// True when no node expands past kMaxColladaNodes, no node instances itself (directly or
// through others) and every accessor lies within its array; otherwise "PATH:LINE: ..."
// naming the node or the accessor.
bool checkColladaNodes(const std::string& path, std::string_view text, std::string& error);

}  // namespace fgsg::rt::io
