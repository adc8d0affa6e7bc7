// The memory a derivation may hold (--max-memory): how much it holds is the process's
// resident memory (read from /proc/self/statm, a few microseconds, so at most every
// 10 ms) plus what the instances placed so far will need once assembled and written
// (their assets' vertices and triangles, counted when they are placed). A derivation
// over its budget stops like one over any other limit, keeping what it has, rather than
// dying on std::bad_alloc later, when assembling.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace fgsg::rt {

// "2G", "512M", "64k", "1.5G", "1000000" (bytes); binary units (K = 1024), an optional
// trailing "B" or "iB", any case. nullopt for anything else, zero, or over 2^62.
std::optional<uint64_t> parseMemorySize(const std::string& text);
// 512M, 2G, 1.5G: the shortest of these forms for messages.
std::string formatMemorySize(uint64_t bytes);

// Physical memory (or the cgroup's limit when it is lower), in bytes; 0 if unknown.
uint64_t availableMemoryBytes();
// The default budget: half of availableMemoryBytes() (4 GiB when that is unknown).
uint64_t defaultMemoryBudget();
// The memory a reader may build from one input file (a mesh file's nodes expanded, its
// meshes placed): `maxMemoryBytes` (--max-memory) when not 0, else defaultMemoryBudget();
// never more than three quarters of the address-space limit (`ulimit -v`) when one is set.
// Readers refuse a file whose declared content needs more, before reading it.
uint64_t readerMemoryLimit(uint64_t maxMemoryBytes = 0);
// The process's resident set, in bytes; 0 if it cannot be read.
uint64_t residentMemoryBytes();

// Bytes an assembled and written instance of an asset with this many vertices and
// triangles takes at the peak: float positions, normals and colours and uint32 indices
// once in the mesh, and about three times over while the file is encoded in memory (a
// growing buffer, then its copy); measured: a 1.2 M-triangle .glb peaks at 4.3 times.
constexpr uint64_t outputBytes(uint64_t vertices, uint64_t triangles) {
  return 4 * (vertices * 9 * sizeof(float) + triangles * 3 * sizeof(uint32_t));
}

}  // namespace fgsg::rt
