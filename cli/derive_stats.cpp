#include "cli/derive_stats.h"

#include <cstdint>
#include <cstdio>
#include <utility>

namespace fgsg::cli {

void printDeriveStats(const rt::DeriveStats& s, size_t triangles, size_t lines) {
  std::printf("shapes %llu\nrewrites %llu\nterminals %llu\ninstances %llu\ntriangles %zu\n",
              (unsigned long long)s.shapesCreated, (unsigned long long)s.rewrites,
              (unsigned long long)s.terminals, (unsigned long long)s.instances, triangles);
  if (lines) std::printf("lines %zu\n", lines);  // turtle segments "lines"
  // Collision figures only for grammars that test, merge or draw lines (FGSG §4.4).
  const std::pair<const char*, uint64_t> placement[] = {
      {"collision.tests", s.collisionTests}, {"collision.hits", s.collisions},
      {"merges", s.merges},                  {"line.segments", s.lineSegments},
      {"line.joined", s.linesJoined},        {"lock.removed", s.locksRemoved}};
  for (const auto& [name, value] : placement)
    if (value > 0) std::printf("%s %llu\n", name, (unsigned long long)value);
}

}  // namespace fgsg::cli
