// The derivation figures `fgsg run --stats` and the REPL's `:derive` / `:stats` print,
// one `name value` per line (docs/cli.md, `--stats`).
#pragma once

#include "runtime/derivation.h"

#include <cstddef>

namespace fgsg::cli {

void printDeriveStats(const rt::DeriveStats& s, size_t triangles, size_t lines = 0);

}  // namespace fgsg::cli
