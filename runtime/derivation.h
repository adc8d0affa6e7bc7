// What every engine (interpreter, JIT, compiled library) takes and returns for one
// derivation: options with the seed and limits, and the instances plus statistics.
#pragma once

#include "runtime/instances.h"
#include "runtime/lot.h"
#include "runtime/reports.h"

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

namespace fgsg::rt {

struct DeriveOptions {
  uint64_t seed = 1;
  uint64_t maxShapes = 20'000'000;  // shapes created in all
  uint32_t maxDepth = 100'000;      // derivation depth of one shape
  // --step N: an L-system (`derive parallel`) is rewritten N steps instead of its length,
  // at most its length (backend::parallelDerivationLength; lpfg's animate mode stops
  // there too); -1: its whole length. Sequential derivations ignore it.
  int32_t parallelStep = -1;
  double maxSeconds = 120.0;  // wall clock, from `startedAt` (runtime/deadline.h)
  // When the --max-seconds clock started; the default: when the derivation starts. A
  // derivation run twice (the JIT's direct derivation, then the engine's order) shares it.
  std::chrono::steady_clock::time_point startedAt{};
  // --max-memory: resident memory plus the instances' future mesh (runtime/memory_budget.h);
  // 0: rt::defaultMemoryBudget().
  uint64_t maxMemoryBytes = 0;
  std::vector<std::pair<std::string, std::string>> attrOverrides;  // --set name=value
  std::vector<std::string> assetDirs;  // where asset files are looked up
  bool collideAll = false;  // --collide-all: every I() is collision-tested, as IC
  // Each instance's rule and depth (Instance::origin): fgsg view shows them on picking.
  bool recordOrigins = false;
  // --surface FILE: a mesh file replacing the grammar's surface (empty: the grammar's);
  // the CLI makes the path absolute (it is relative to the working directory).
  std::string surfaceOverride;
  bool repairSurface = false;  // --repair-surface: repair the mesh's repairable problems
  // --start x,y,z: the axiom's scope starts at the surface point closest to `start`
  // (without it: the point closest to the centre of the surface's bounding box).
  bool hasStart = false;
  double start[3] = {0, 0, 0};
  // --surface-size S: the surface is centred at the origin and scaled uniformly so its
  // largest bounding-box extent is S (0: as it is). Meshes come in any unit; a grammar's
  // steps do not.
  double surfaceSize = 0.0;

  // --seed-points: the axiom starts once per seed (on-mesh marching grows one plant per
  // seed), on the surface point closest to `point`, X along `direction` when given. Empty:
  // one start, as --start says.
  struct Seed {
    double point[3] = {0, 0, 0};
    bool hasDirection = false;
    double direction[3] = {1, 0, 0};
  };
  std::vector<Seed> seeds;
  // --seed-density NAME --seed-count N: N more seeds drawn on the surface with a density
  // proportional to the grammar's texture NAME (times the area), from the run's seed.
  std::string seedDensity;
  uint32_t seedCount = 0;
  // Marching (Buron et al. §5, §8): when the condition fails straight ahead, this many
  // other directions are tried, spread evenly over the half circle ahead (half on each
  // side, nearest first); 0: none.
  int marchCandidates = 8;
  int atlasResolution = 1024;   // --atlas-resolution: the geometry image's side in texels
  bool marchInTexels = false;   // --march-units texels: Marching's length in texels (the paper's)
  std::string atlasCacheDir;    // prepared surfaces are kept here ("": not kept)
  // --lots FILE: the axiom derives once per lot, its shape the lot's footprint polygon on
  // the XZ plane (north is -Z), with a random stream of its own and the attrs named like
  // the lot's properties set to their values (over --set). `lotsName` names the file in
  // messages.
  std::vector<Lot> lots;
  std::string lotsName;
};

struct DeriveStats {
  uint64_t shapesCreated = 0;  // every shape, the axiom's included
  uint64_t rewrites = 0;       // shapes replaced by a rule
  uint64_t terminals = 0;      // shapes no rule replaced
  uint64_t instances = 0;      // instances placed
  uint64_t stringLength = 0;   // parallel derivations: modules in the final string
  uint64_t stringBytes = 0;    // ... and the bytes it holds (16 per module, 8 per argument)
  uint64_t collisionTests = 0; // instances tested by IC (or under `collision all`)
  uint64_t collisions = 0;     // of those, rejected: the rest of their production culled
  uint64_t merges = 0;         // IM instances merged into an earlier one
  uint64_t lineSegments = 0;   // LineSeg segments kept
  uint64_t linesJoined = 0;    // lines ended at an intersection (merged or stopped)
  uint64_t locksRemoved = 0;   // Lock sets removed whole because one of their shapes collided
  // Cells (docs/cells.md "Coverage"): the area of the faces a generator laid cells on,
  // and the part of it their cells claim (joints included).
  double cellsFaceArea = 0.0, cellsCoveredArea = 0.0;
  double deriveSeconds = 0.0;
  // Of deriveSeconds: making the surface ready — loading it, designing its fields,
  // laying it out for marching (Buron et al. Table 1's preprocessing).
  double surfaceSeconds = 0.0;
  // Of deriveSeconds, a parallel derivation's rewriting steps (the rest is mostly the
  // turtle reading the string).
  double rewriteSeconds = 0.0;
};

// A problem found while deriving, located in the grammar source.
struct DeriveMessage {
  bool isError = true;
  std::string code;  // "R001"
  int line = 0, col = 0;
  std::string message;
};

struct DeriveResult {
  bool ok = false;  // false: an error stopped the derivation (a limit is only a warning)
  InstanceList instances;
  DeriveStats stats;
  std::vector<DeriveMessage> messages;
  // Report(key, value) and Print(value), in the order the derivation ran them (also when
  // an error or a limit stopped it: what ran before).
  std::vector<Report> reports;
  std::vector<PrintLine> prints;
};

}  // namespace fgsg::rt
