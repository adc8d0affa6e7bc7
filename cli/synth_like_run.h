// What both forms of `fgsg synth` share with `fgsg run`, so that the two commands agree
// (#47): the time limit's name, the output written when none is named, the --stats format.
#pragma once

#include "cli/command_line.h"

#include <cstdint>
#include <string>

namespace fgsg::cli {

// --max-seconds S, as run spells it: seconds greater than 0, at most 1e9. --time-limit S,
// synth's old name, still works and says once on stderr that it is deprecated.
void synthMaxSecondsFlag(CommandLine& cl, double& seconds);

// As run: with no model output named, the mesh goes to EXAMPLE's stem + ".glb" in the
// current directory (a preview alone does not replace it) — never exit 0 having written nothing.
std::string defaultModelOutput(const std::string& example);

// --stats lines as run prints them on stdout: `name value`, and timings `time.NAME seconds`.
void printStat(const char* name, uint64_t value);
void printStatSeconds(const char* name, double seconds);

}  // namespace fgsg::cli
