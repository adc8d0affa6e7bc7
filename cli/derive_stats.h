// The derivation figures `fgsg run --stats` and the REPL's `:derive` / `:stats` print,
// one `name value` per line (docs/cli.md, `--stats`); fgsg view shows them in its page.
#pragma once

#include "runtime/derivation.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace fgsg::cli {

// The figures in print order, as name and value.
std::vector<std::pair<std::string, uint64_t>> deriveStatFigures(const rt::DeriveStats& s, size_t triangles,
                                                                size_t lines = 0);
void printDeriveStats(const rt::DeriveStats& s, size_t triangles, size_t lines = 0);

}  // namespace fgsg::cli
