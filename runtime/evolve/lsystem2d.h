// 2D L-systems of Chan & Hui 2013 (§3.1.2, Figs. 2-3; §6.2).
//
// The string form is the paper's: parts separated by dots, the rules first (one per
// symbol, in the tile set's symbol order) and the axiom last:
//   {ABAA.ABBA.A}      rules A -> AB/AA, B -> AB/BA; axiom A
// Each part is a square array of alleles written row by row, top row first, so a part of
// k*k alleles is a k x k array ("ABAA" is the 2 x 2 array AB over AA). An allele is a
// symbol letter with an optional orientation in degrees counter-clockwise: A, A0, A90,
// A180, A270 (A_90 is read too). Spaces are ignored; the braces are optional.
// All rules share one size k; the axiom may have another size a (the paper allows 1x1,
// 2x2, ...).
//
// Rewriting (our reading of §3.1.2 and Fig. 3, where rotated alleles appear in rules):
// one generation replaces every cell, in parallel, by its symbol's k x k rule array; a
// cell holding a rotated allele X_t is replaced by X's rule array turned by t as a
// picture: the array is rotated by t and every allele in it gains t. So a rotated tile
// subdivides into the rotated subdivision, and generation g of the axiom X_t is
// generation g of X turned by t. Generation 0 is the axiom itself; generation g is an
// (a k^g) x (a k^g) array, k^g x k^g for a 1x1 axiom (Fig. 2: {ABAA.ABBA.A} gives
// 2x2, 4x4, 8x8, 16x16 for generations 1-4).
#pragma once

#include "runtime/evolve/tiles.h"

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace fgsg::rt::evolve {

// A square array of alleles, row-major, row 0 at the top (y up inside each tile; cell
// (r, c) covers x in [c, c+1], y in [n-1-r, n-r] in cell units).
struct AlleleGrid {
  int side = 0;
  std::vector<Allele> cells;

  AlleleGrid() = default;
  explicit AlleleGrid(int n, Allele fill = {}) : side(n), cells(size_t(n) * size_t(n), fill) {}
  Allele& at(int r, int c) { return cells[size_t(r) * size_t(side) + size_t(c)]; }
  const Allele& at(int r, int c) const { return cells[size_t(r) * size_t(side) + size_t(c)]; }
  friend bool operator==(const AlleleGrid&, const AlleleGrid&) = default;
};

// The grid turned `quarterTurns` x 90 degrees counter-clockwise as a picture: one turn
// moves cell (r, c) to (n-1-c, r) and adds one quarter turn to its allele.
AlleleGrid turnGrid(const AlleleGrid& g, int quarterTurns);

struct LSystem2D {
  std::vector<AlleleGrid> rules;  // rules[s]: the array symbol s rewrites to; all k x k
  AlleleGrid axiom;

  int ruleSide() const { return rules.empty() ? 0 : rules.front().side; }
  // Alleles in the string: every rule then the axiom, each row by row. Crossover and
  // mutation (genetic.h) index this sequence.
  size_t length() const;
  Allele& allele(size_t position);
  const Allele& allele(size_t position) const;
  friend bool operator==(const LSystem2D&, const LSystem2D&) = default;
};

// A string that is not a 2D L-system. `column` is 1-based in the parsed text.
struct LSystemSyntaxError : std::runtime_error {
  size_t column = 0;
  LSystemSyntaxError(size_t column, const std::string& message);
};

// Parses the string form. `letters` are the symbols in rule order (TileSet::letters());
// the string must have one rule per letter and the axiom. Throws LSystemSyntaxError
// ("column 7: unknown symbol 'C' (symbols: AB)", "part 2 (column 6) has 3 alleles, not a
// square k x k array", ...).
LSystem2D parseLSystem(std::string_view text, std::string_view letters);
// The same with the letters A, B, C, ... one per rule: {ABAA.ABBA.A} has symbols A, B.
LSystem2D parseLSystem(std::string_view text);

// The string form: "{ABAA.ABBA.A90}" (orientation 0 written without a suffix).
std::string formatLSystem(const LSystem2D& ls, std::string_view letters);
std::string formatGrid(const AlleleGrid& g, std::string_view letters);  // "ABAA" row by row

// Side of generation g: axiom side x k^g. Throws std::length_error when it would exceed
// `maxSide` (default 2^15).
int expandedSide(const LSystem2D& ls, int generation, int maxSide = 1 << 15);

// Generation g (>= 0) of the L-system. Throws std::invalid_argument for a negative
// generation or a rule missing for a symbol in use, std::length_error when the array
// would have more than `maxCells` cells.
AlleleGrid expand(const LSystem2D& ls, int generation, size_t maxCells = size_t(1) << 26);

// Checks the structure: at least one rule, all rules the same size k >= 1, a non-empty
// axiom, symbols below rules.size() and turns 0..3. Throws std::invalid_argument.
void checkLSystem(const LSystem2D& ls);

}  // namespace fgsg::rt::evolve
