// Discrete model synthesis (Merrell, "Model Synthesis", ch. 3): given an example model (or
// adjacency rules), generate a larger model of labels whose every pair of neighbouring
// labels also occurs in the example (the adjacency constraint, eq. 3.3).
//
//   Example ex;  Diagnostics diags;
//   if (!loadExample("castle.txt", ex, diags)) print(formatDiagnostics(diags));
//   SynthesisOptions o;  o.size = {40, 40, 10};  o.block = {10, 10, 10};  o.seed = 7;
//   SynthesisResult r = synthesize(ex, o);
//   if (!r.ok) print(r.failure.message);                // where and why
//   auto pieces = piecePlacements(r.labels, ex, {});    // asset, quarter turns, box per cell
//
// The public entry points are noexcept: failures come back in the result, never as
// exceptions (they may be called from JIT-compiled grammar code).
#pragma once

#include "runtime/deadline.h"
#include "runtime/synthesis/constraints.h"
#include "runtime/synthesis/diagnostic.h"
#include "runtime/synthesis/example.h"
#include "runtime/synthesis/label_grid.h"
#include "runtime/synthesis/placements.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace fgsg::rt::synthesis {

enum class CellOrder { kScanline, kMinEntropy };

struct SynthesisOptions {
  GridSize size{16, 16, 1};
  uint64_t seed = 1;
  // Modifying in blocks (Algorithm 3.4). {0,0,0}: one pass over the whole grid
  // (Algorithm 3.1). Blocks overlap by half; an extent larger than the grid is clipped.
  std::array<int, 3> block{0, 0, 0};
  int blockRetries = 2;   // extra tries of a block that failed before it is left as it was
  int blockPasses = 1;    // sweeps over all blocks
  int attempts = 1;       // whole-grid mode: restarts after a contradiction
  CellOrder order = CellOrder::kScanline;
  bool uniformWeights = false;  // ignore example frequencies (the thesis's equal chance)
  std::array<bool, 3> periodic{false, false, false};
  std::optional<BorderSpec> border;  // unset: the example's own border declarations
  std::vector<SymmetrySpec> symmetry;
  PositionWeights weights;           // per-position probabilities / masks
  ConnectivitySpec connectivity;
  // Limits: a run never hangs. 0 assignments = 64 x (cells) x (passes).
  uint64_t maxAssignments = 0;
  double timeLimitSeconds = 30.0;
  // A caller's own clock as well (fgsg run's --max-seconds for Synthesize): the solver
  // also stops, with kTimeLimit, when it expires. Null: timeLimitSeconds alone.
  Deadline* deadline = nullptr;
};

struct SynthesisFailure {
  enum Kind { kNone, kBadOptions, kNoInitialModel, kContradiction, kStepLimit, kTimeLimit } kind = kNone;
  Cell cell;                   // where the catalog became empty
  uint64_t assignments = 0;    // assignments made before it happened (whole run)
  int block = -1;              // block index, -1 for whole-grid synthesis
  Cell blockOrigin, blockSize;
  std::string message;         // "contradiction at cell (3,4,0) after 812 assignments in block #5 ..."
};

struct SynthesisStats {
  uint64_t assignments = 0;
  uint64_t propagationSteps = 0;   // sites popped by propagation
  uint64_t supportMisses = 0;      // pops whose support was not memoised (catalog.h)
  int blocks = 0, blocksFailed = 0, blockRetries = 0;
  uint64_t backtracks = 0;         // minimum-entropy order: decisions undone
  uint64_t repairs = 0;            // minimum-entropy order: neighbourhoods reopened
  int attempts = 0;
  double seconds = 0;
  size_t catalogBytes = 0;         // catalog + site graph + transition rows
};

struct SynthesisResult {
  // ok: finished as asked. consistent: `labels` is a complete model satisfying every
  // constraint (true also when some blocks were left unmodified after failing).
  bool ok = false;
  bool consistent = false;
  LabelGrid labels;
  std::vector<Piece> pieces;       // label id -> piece (the example's mapping)
  SynthesisFailure failure;        // kind kNone when ok; the last block failure otherwise
  std::vector<SynthesisFailure> blockFailures;  // first few block failures (reverted)
  SynthesisStats stats;
};

SynthesisResult synthesize(const Example& ex, const SynthesisOptions& options) noexcept;

}  // namespace fgsg::rt::synthesis
