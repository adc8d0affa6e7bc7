// FBX files (.fbx, binary or ASCII) are read by assimp, which builds a node for every
// connection of a model to a parent that it follows down from the root: a model connected
// twice to its parent is copied twice with everything below it, so 20 models each
// connected twice to the next become 2^19 nodes (a 3 KB file: 4.5 GB and 44 s; 26 models
// exhaust any machine), and a cycle of connections recurses until the stack overflows (a
// crash). assimp's parsers also recurse once per level of nesting of the file's records.
// This scan reads the file's structure, its models (Objects: Model) and their connections
// (Connections: C "OO") before assimp sees it, and refuses, naming the model and where it
// is (the line in an ASCII file, the byte offset in a binary one):
//  * records nested deeper than kMaxFbxNesting (real files nest about 6 deep);
//  * a model that is its own ancestor through its connections;
//  * a hierarchy deeper than kMaxFbxDepth, or that expands to more than kMaxFbxNodes nodes
//    or to more than the memory limit holds (about 4 KiB a node).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace fgsg::rt::io {

constexpr uint64_t kMaxFbxNodes = uint64_t(1) << 20;
constexpr size_t kMaxFbxDepth = 1024;
constexpr size_t kMaxFbxNesting = 256;

// True when `bytes` (the whole file `path`) passes the checks above, or is not an FBX file
// whose structure can be walked (assimp then reports it); otherwise one message
// "PATH:LINE: ..." (ASCII) or "PATH: byte N: ..." (binary). `memoryLimit`: bytes the
// reader may hold (memory_budget.h's readerMemoryLimit()).
bool checkFbxNodes(const std::string& path, std::string_view bytes, uint64_t memoryLimit, std::string& error);

}  // namespace fgsg::rt::io
