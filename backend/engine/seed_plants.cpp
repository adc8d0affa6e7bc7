// Seeds whose plants cannot meet (Derivation::seedsGrowApart: no collisions, merges,
// lines or occlusion queries) are derived apart: each seed's plant by a derivation of its
// own, all of them concurrently (Buron et al. §7: one GPU thread per seed), sharing the
// surface, its marching layout, the textures and the assets, which they only read. The
// plants are then put together in seed order, so the output is the same bytes whatever
// the number of threads — the output of deriving the seeds one after another.
// In fgsg view (a SurfaceReuse in effect) each plant is kept with what it depended on: a
// seed dragged or a texture painted derives again only the plants whose seed moved or
// whose texels read changed; the others are taken as they were, which is exact, since a
// plant reads nothing else that such an edit changes (#49, item 5).
#include "backend/engine/derivation.h"

#include "backend/engine/surface_reuse.h"
#include "runtime/stack_budget.h"
#include "runtime/texture/texture_map.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <iterator>
#include <memory>
#include <new>
#include <optional>
#include <stdexcept>

namespace fgsg::backend {

// What one plant's derivation left: its instances (numbered by the shared tables), its
// counts, and how it ended.
struct Derivation::Plant {
  rt::InstanceList out;
  rt::DeriveStats stats;
  std::vector<uint64_t> shapesAtInstance;  // stats.shapesCreated when each was placed
  std::vector<uint64_t> ruleUses;
  std::vector<std::pair<uint32_t, uint32_t>> overlaps;  // rules met applying together (R029)
  MarchTally marching;                                   // how its marches ended (R030)
  std::vector<rt::Report> reports;  // start 0: the plant's own
  std::vector<rt::PrintLine> prints;
  std::optional<rt::DeriveMessage> depthWarning;
  std::optional<LimitReached> limit;  // a limit ended it: what it derived is kept
  std::optional<DeriveError> error;   // an error ended it
  bool outOfMemory = false;
};

// A plant kept by fgsg view and what it was derived from: its seed as the options gave it,
// its random key, the surface, and per texture the map it read and the tiles of texels read.
struct SeedPlantCache {
  struct Entry {
    bool valid = false;
    rt::DeriveOptions::Seed seed;
    uint64_t key = 0;
    std::shared_ptr<const SurfaceWorld> world;
    std::vector<std::shared_ptr<const rt::texture::TextureMap>> textures;
    std::vector<MarchingCommands::TextureTiles> reads;
    std::shared_ptr<const Derivation::Plant> plant;
  };
  std::vector<Entry> entries;  // by seed index

  static bool sameSeed(const rt::DeriveOptions::Seed& a, const rt::DeriveOptions::Seed& b) {
    return std::equal(a.point, a.point + 3, b.point) && a.hasDirection == b.hasDirection &&
           (!a.hasDirection || std::equal(a.direction, a.direction + 3, b.direction));
  }
  // The texels of each tile `e` read are the same in `now` as in the maps it read.
  static bool sameTexels(const Entry& e, const std::vector<std::shared_ptr<const rt::texture::TextureMap>>& now) {
    const int tile = MarchingCommands::kTextureTile;
    for (size_t env = 0; env < e.reads.size(); ++env) {
      const MarchingCommands::TextureTiles& tiles = e.reads[env];
      if (tiles.bits.empty()) continue;
      if (env >= e.textures.size() || env >= now.size() || !e.textures[env] || !now[env]) return false;
      const rt::texture::TextureMap &was = *e.textures[env], &is = *now[env];
      if (&was == &is) continue;
      if (was.width() != is.width() || was.height() != is.height()) return false;
      for (size_t bit = 0; bit < size_t(tiles.columns) * size_t(tiles.rows); ++bit) {
        if (!(tiles.bits[bit / 64] >> (bit % 64) & 1)) continue;
        const int c0 = int(bit % size_t(tiles.columns)) * tile, r0 = int(bit / size_t(tiles.columns)) * tile;
        for (int r = r0; r < std::min(r0 + tile, is.height()); ++r)
          for (int c = c0; c < std::min(c0 + tile, is.width()); ++c)
            if (was.texel(c, r) != is.texel(c, r)) return false;
      }
    }
    return true;
  }
};

void Derivation::deriveSeedsApart(const std::vector<rt::Scope>& starts, uint64_t root) {
  // What the plants share is made ready here, so that they only read it: every asset
  // resolved (and its output size known), the surface laid out for marching.
  if (!out_.assets.empty()) assetOutputBytes(static_cast<uint32_t>(out_.assets.size() - 1));
  if (usesMarchingSurface()) marching_.prepareSurface();
  std::vector<Plant> plants(starts.size());
  // fgsg view: the plants kept from the last derivation that are still what this one
  // would derive (seeds given as points only: --seed-density draws them from a texture).
  SurfaceReuse* reuse = SurfaceReuseScope::current();
  std::shared_ptr<SeedPlantCache> cache;
  if (reuse) {
    std::lock_guard<std::mutex> lock(reuse->mutex);
    if (!reuse->plants) reuse->plants = std::make_shared<SeedPlantCache>();
    cache = reuse->plants;
  }
  const auto keyOf = [root](size_t k) { return rt::childKey(root, static_cast<uint32_t>(k)); };
  std::vector<uint8_t> reused(starts.size(), 0);
  if (cache && opt_.seedCount == 0) {
    for (size_t k = 0; k < starts.size() && k < cache->entries.size() && k < opt_.seeds.size(); ++k) {
      const SeedPlantCache::Entry& e = cache->entries[k];
      if (!e.valid || e.key != keyOf(k) || e.world != surface_ || !SeedPlantCache::sameSeed(e.seed, opt_.seeds[k]) ||
          e.plant->out.assets != out_.assets || e.plant->out.symbols != out_.symbols ||
          !SeedPlantCache::sameTexels(e, marching_.textures()))
        continue;
      plants[k] = *e.plant;  // merging takes its instances: the kept one stays whole
      reused[k] = 1;
    }
  }
  std::vector<SeedPlantCache::Entry> fresh(cache ? starts.size() : 0);
  tbb::parallel_for(size_t(0), starts.size(), [&](size_t k) {
    if (reused[k]) return;
    auto plant = std::make_unique<Derivation>(m_, opt_, assets_, eval_.attrSlots(), program_, false);
    plant->adoptParent(*this);
    if (cache) plant->marching_.recordTextureReads();
    plants[k] = plant->derivePlant(starts[k], keyOf(k), static_cast<uint32_t>(k));
    const Plant& p = plants[k];
    // Kept only when nothing but its inputs decided it (no limit, error or memory).
    if (!cache || k >= opt_.seeds.size() || opt_.seedCount != 0 || p.limit || p.error || p.outOfMemory) return;
    SeedPlantCache::Entry& e = fresh[k];
    e.valid = true;
    e.seed = opt_.seeds[k];
    e.key = keyOf(k);
    e.world = surface_;
    e.textures = plant->marching_.textures();
    e.reads = plant->marching_.textureReads();
    e.plant = std::make_shared<const Plant>(p);
  });
  if (cache) {
    cache->entries.resize(starts.size());
    for (size_t k = 0; k < starts.size(); ++k)
      if (!reused[k]) cache->entries[k] = std::move(fresh[k]);
    std::lock_guard<std::mutex> lock(reuse->mutex);
    reuse->plantsReused = reused;
  }
  mergePlants(plants);
}

void Derivation::adoptParent(const Derivation& parent) {
  surface_ = parent.surface_;
  marching_.shareFrom(parent.marching_);
  textures_.shareFrom(parent.textures_);
  assetHasTexcoords_ = parent.assetHasTexcoords_;
  assetFlatAxes_ = parent.assetFlatAxes_;
  assetSourceBox_ = parent.assetSourceBox_;
  assetHasImages_ = parent.assetHasImages_;
  assetMesh_ = parent.assetMesh_;
  readInserts_ = parent.readInserts_;
  deadline_ = parent.deadline_;  // the same end, with a countdown of its own
  memoryBudget_ = parent.memoryBudget_;
  assetBytes_ = parent.assetBytes_;
  if (parent.sequentialString_) startSequentialString();  // each plant's string is its own
}

// The seed's axiom (seed `index`, random stream `key`: as in one queue) and everything
// it leads to; ended like run(), but the surface is not appended.
Derivation::Plant Derivation::derivePlant(const rt::Scope& start, uint64_t key, uint32_t index) {
  Plant p;
  stackFloor_ = rt::stackFloor();  // this thread's stack
  recordShapesAtInstances_ = true;
  try {
    initOutput();
    std::vector<double> none;
    execRoot(0, m_.axiom, start, rt::GeomRef{}, key, 0, index, none.data(), UINT32_MAX);
    deriveWaitingShapes();
  } catch (const LimitReached& limit) {
    p.limit = limit;
  } catch (const rt::TimeLimitReached&) {
    p.limit = timeLimit();
  } catch (const std::bad_alloc&) {
    p.outOfMemory = true;
  } catch (const DeriveError& e) {
    p.error = e;
  }
  try {
    if (!p.error && !p.outOfMemory) appendCurves();
  } catch (const std::bad_alloc&) {
    p.outOfMemory = true;
  }
  if (depthLimitHit_) p.depthWarning = depthWarning_;
  out_.finishes = textures_.finishes();
  p.out = std::move(out_);
  p.stats = stats_;
  p.shapesAtInstance = std::move(shapesAtInstance_);
  p.ruleUses = std::move(ruleUses_);
  p.overlaps = std::move(overlaps_);
  p.marching = marching_.tally();
  p.reports = reports_.takeReports();
  p.prints = reports_.takePrints();
  return p;
}

// In seed order, as if derived one after another: the first plant that failed fails the
// derivation; --max-shapes counts the shapes of all plants, so a plant may create only
// what the earlier ones left (its instances placed beyond are cut), and a plant a limit
// ended is the last one kept.
void Derivation::mergePlants(std::vector<Plant>& plants) {
  size_t instances = 0, params = 0, curves = 0;
  for (const Plant& p : plants)
    instances += p.out.instances.size(), params += p.out.params.size(), curves += p.out.curves.size();
  out_.instances.reserve(out_.instances.size() + instances + 1);  // and the surface
  out_.params.reserve(out_.params.size() + params);
  out_.curves.reserve(out_.curves.size() + curves);
  for (Plant& p : plants) {
    // Its reports and prints (also those before an error) under the start shape it opens.
    reports_.adopt(std::move(p.reports), std::move(p.prints), static_cast<uint32_t>(out_.startBounds.size()));
    if (p.error) throw *p.error;
    if (p.outOfMemory) throw std::bad_alloc();
    if (p.out.assets.size() != out_.assets.size() || p.out.symbols.size() != out_.symbols.size())
      throw std::logic_error("a seed plant numbered its assets or symbols apart from the derivation");
    for (size_t r = 0; r < ruleUses_.size(); ++r) ruleUses_[r] += p.ruleUses[r];
    for (const auto& rules : p.overlaps) noteOverlap(rules);
    marching_.addTally(p.marching);
    if (p.depthWarning && !depthLimitHit_) depthLimitHit_ = true, depthWarning_ = *p.depthWarning;

    const uint64_t left = opt_.maxShapes - std::min(opt_.maxShapes, stats_.shapesCreated);
    size_t keep = p.out.instances.size();
    std::optional<LimitReached> limit = p.limit;
    if (p.stats.shapesCreated > left) {
      keep = static_cast<size_t>(std::upper_bound(p.shapesAtInstance.begin(), p.shapesAtInstance.end(), left) -
                                 p.shapesAtInstance.begin());
      p.stats.shapesCreated = left;
      limit = shapeLimitReached(ir::Loc{});
    }

    const size_t paramBase = out_.params.size(), curveBase = out_.curves.size(),
                 geometryBase = out_.geometries.size();
    const size_t params = keep == 0 ? 0
                                    : size_t(p.out.instances[keep - 1].firstParam) + p.out.instances[keep - 1].paramCount;
    out_.params.insert(out_.params.end(), p.out.params.begin(), p.out.params.begin() + params);
    out_.curves.insert(out_.curves.end(), p.out.curves.begin(), p.out.curves.end());
    std::move(p.out.geometries.begin(), p.out.geometries.end(), std::back_inserter(out_.geometries));
    out_.startBounds.push_back(static_cast<uint32_t>(out_.instances.size()));
    for (size_t i = 0; i < keep; ++i) {
      rt::Instance inst = p.out.instances[i];
      inst.firstParam = static_cast<uint32_t>(inst.firstParam + paramBase);
      if (inst.curve != UINT32_MAX) inst.curve = static_cast<uint32_t>(inst.curve + curveBase);
      if (inst.geometry != UINT32_MAX) inst.geometry = static_cast<uint32_t>(inst.geometry + geometryBase);
      if (i < p.out.origins.size()) out_.origins.push_back(p.out.origins[i]);
      if (const rt::Finish* f = p.out.finishOf(i)) {  // the plant's finish, numbered as the parent's
        out_.finishIndex.resize(out_.instances.size() + 1, 0);
        out_.finishIndex.back() = textures_.internFinish(*f);
      }
      out_.instances.push_back(inst);
    }
    p.out = rt::InstanceList{};  // freed as soon as it is copied

    rt::DeriveStats& s = stats_;
    const rt::DeriveStats& q = p.stats;
    s.shapesCreated += q.shapesCreated;
    s.rewrites += q.rewrites;
    s.terminals += q.terminals;
    s.collisionTests += q.collisionTests;
    s.collisions += q.collisions;
    s.merges += q.merges;
    s.lineSegments += q.lineSegments;
    s.linesJoined += q.linesJoined;
    s.locksRemoved += q.locksRemoved;
    s.cellsFaceArea += q.cellsFaceArea;
    s.cellsCoveredArea += q.cellsCoveredArea;
    if (limit) throw *limit;
  }
}

}  // namespace fgsg::backend
