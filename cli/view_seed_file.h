// The seed file fgsg view keeps for on-mesh marching (#49): the seeds the page places
// (click, drag, heading), written in the format `fgsg run --seed-points FILE` reads
// (runtime/io/seed_points.h), so that what is grown in the viewer is grown by a run.
// The file is the one --seed-points names, else GRAMMAR.seeds beside the grammar; the
// page never names a path.
#pragma once

#include "runtime/derivation.h"

#include <string>
#include <vector>

namespace fgsg::cli {

using ViewSeeds = std::vector<rt::DeriveOptions::Seed>;

// GRAMMAR's path with its extension replaced by ".seeds" (g.fgsg -> g.seeds).
std::string defaultSeedFile(const std::string& grammarPath);

// One seed a line, "x y z" or "x y z dx dy dz", each number the shortest text that reads
// back as the same double (std::to_chars), after a '#' comment naming the grammar.
std::string seedFileText(const ViewSeeds& seeds, const std::string& grammarName);

// Writes the seeds atomically (a temporary file renamed over `path`). No seeds: the file
// is removed, since a run refuses a seed file without seeds. False with a message.
bool writeSeedFile(const std::string& path, const ViewSeeds& seeds, const std::string& grammarName, std::string& error);

// The seeds of `path`; a missing file holds none. False with a message naming the line.
bool readSeedFile(const std::string& path, ViewSeeds& seeds, std::string& error);

}  // namespace fgsg::cli
