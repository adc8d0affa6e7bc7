// --seed-points: where on-mesh marching's plants start. Either inline, seeds separated
// by ';' ("0,1,0;0.2,0.9,0" or with a heading "0,1,0:1,0,0"), or a text file with one
// seed per line: "x y z" or "x y z dx dy dz" (commas also accepted), '#' comments.
#pragma once

#include "runtime/derivation.h"

#include <string>
#include <vector>

namespace fgsg::rt::io {

// Reads the seeds of `spec` (a file when no such inline list parses as one, see above).
// False with a message naming the file and line, or the inline seed, on a bad entry.
bool readSeedPoints(const std::string& spec, std::vector<DeriveOptions::Seed>& seeds, std::string& error);

}  // namespace fgsg::rt::io
