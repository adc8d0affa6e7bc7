#include "cli/derive_stats.h"

#include <cstdio>

namespace fgsg::cli {

std::vector<std::pair<std::string, uint64_t>> deriveStatFigures(const rt::DeriveStats& s, size_t triangles,
                                                                size_t lines) {
  std::vector<std::pair<std::string, uint64_t>> out = {
      {"shapes", s.shapesCreated}, {"rewrites", s.rewrites}, {"terminals", s.terminals},
      {"instances", s.instances},  {"triangles", triangles}};
  if (lines) out.push_back({"lines", lines});  // turtle segments "lines"
  // Collision figures only for grammars that test, merge or draw lines (FGSG §4.4).
  const std::pair<const char*, uint64_t> placement[] = {
      {"collision.tests", s.collisionTests}, {"collision.hits", s.collisions},
      {"merges", s.merges},                  {"line.segments", s.lineSegments},
      {"line.joined", s.linesJoined},        {"lock.removed", s.locksRemoved}};
  for (const auto& [name, value] : placement)
    if (value > 0) out.push_back({name, value});
  return out;
}

void printDeriveStats(const rt::DeriveStats& s, size_t triangles, size_t lines) {
  for (const auto& [name, value] : deriveStatFigures(s, triangles, lines))
    std::printf("%s %llu\n", name.c_str(), (unsigned long long)value);
  // The share of the textured faces' area their cells cover (docs/cells.md "Coverage").
  if (s.cellsFaceArea > 0) std::printf("cells.coverage %.6f\n", s.cellsCoveredArea / s.cellsFaceArea);
}

}  // namespace fgsg::cli
