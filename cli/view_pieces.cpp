#include "cli/view_pieces.h"

#include "backend/scene_starts.h"
#include "cli/view_scene.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstring>
#include <filesystem>

namespace fgsg::cli {
namespace {

// Instances [begin, end) of `all` as a list of their own: the shared tables (assets,
// symbols, strings, images) whole, params, curves, geometries and finishes renumbered
// from 0 in the instances' order.
rt::InstanceList pieceInstances(const rt::InstanceList& all, uint32_t begin, uint32_t end, bool withLines) {
  rt::InstanceList out;
  out.assets = all.assets;
  out.symbols = all.symbols;
  out.paramKinds = all.paramKinds;
  out.strings = all.strings;
  out.textures = all.textures;
  if (withLines) out.lines = all.lines;
  out.instances.reserve(end - begin);
  for (uint32_t i = begin; i < end; ++i) {
    rt::Instance inst = all.instances[i];
    const auto params = all.params.begin() + inst.firstParam;
    inst.firstParam = static_cast<uint32_t>(out.params.size());
    out.params.insert(out.params.end(), params, params + inst.paramCount);
    if (inst.curve != UINT32_MAX) {
      out.curves.push_back(all.curves.at(inst.curve));
      inst.curve = static_cast<uint32_t>(out.curves.size() - 1);
    }
    if (inst.geometry != UINT32_MAX) {
      out.geometries.push_back(all.geometries.at(inst.geometry));
      inst.geometry = static_cast<uint32_t>(out.geometries.size() - 1);
    }
    if (const rt::Finish* f = all.finishOf(i)) {
      auto at = std::find(out.finishes.begin(), out.finishes.end(), *f);
      if (at == out.finishes.end()) at = out.finishes.insert(at, *f);
      out.finishIndex.resize(out.instances.size() + 1, 0);
      out.finishIndex.back() = static_cast<uint32_t>(at - out.finishes.begin() + 1);
    }
    if (i < all.origins.size()) out.origins.push_back(all.origins[i]);
    out.instances.push_back(inst);
  }
  return out;
}

template <class V>
bool pieceSameBytes(const V& a, const V& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0);
}

bool pieceSameLines(const std::vector<rt::LinePath>& a, const std::vector<rt::LinePath>& b) {
  if (a.size() != b.size()) return false;
  for (size_t k = 0; k < a.size(); ++k)
    if (!pieceSameBytes(a[k].points, b[k].points) || std::memcmp(&a[k].width, &b[k].width, sizeof(double)) != 0 ||
        a[k].merge != b[k].merge || a[k].symbol != b[k].symbol)
      return false;
  return true;
}

bool pieceSameReports(const std::vector<rt::Report>& a, const std::vector<rt::Report>& b) {
  if (a.size() != b.size()) return false;
  for (size_t k = 0; k < a.size(); ++k)
    if (a[k].key != b[k].key || a[k].value.kind != b[k].value.kind || a[k].value.text != b[k].value.text ||
        std::memcmp(&a[k].value.number, &b[k].value.number, sizeof(double)) != 0)
      return false;
  return true;
}

// Byte for byte: the same instances give the same scene (Instance has no padding).
// Kept in the derivation's order, so a plant taken as it was compares equal at once.
bool samePiece(const ViewPiece& a, const rt::InstanceList& list, const std::vector<rt::Report>& reports) {
  const rt::InstanceList& b = a.list;
  if (!pieceSameBytes(b.instances, list.instances) || !pieceSameBytes(b.params, list.params) ||
      !pieceSameBytes(b.curves, list.curves) || !pieceSameBytes(b.finishIndex, list.finishIndex) ||
      b.finishes != list.finishes || !pieceSameBytes(b.origins, list.origins) || b.assets != list.assets ||
      b.symbols != list.symbols || b.paramKinds != list.paramKinds || b.strings != list.strings ||
      b.textures != list.textures || !pieceSameLines(b.lines, list.lines) || !pieceSameReports(a.reports, reports))
    return false;
  return b.geometries.empty() && list.geometries.empty();  // own geometry (CGA leaves): built again
}

}  // namespace

bool viewPiecesEmbedAny(const ViewPieces& pieces, const std::vector<std::string>& files) {
  for (const std::string& file : files) {
    const std::filesystem::path name = std::filesystem::path(file).filename();
    for (const auto& piece : pieces.pieces)
      for (const std::string& texture : piece->list.textures)
        if (std::filesystem::path(texture).filename() == name) return true;
  }
  return false;
}

bool viewByPieces(const rt::DeriveOptions& options, const rt::DeriveResult& result) {
  const auto& bounds = result.instances.startBounds;
  return options.seeds.size() > 1 && options.seedCount == 0 && options.lots.empty() &&
         bounds.size() == options.seeds.size() + 1;
}

bool buildViewPieces(const ir::Module& module, const rt::DeriveOptions& options, const rt::DeriveResult& result,
                     const rt::AssetLibrary& assets, const std::vector<int>& meshOf, const ViewPieces& last,
                     ViewPieces& out, std::string& error) {
  out = ViewPieces{};
  const rt::InstanceList& all = result.instances;
  const std::vector<uint32_t>& bounds = all.startBounds;
  const size_t seeds = bounds.size() - 1, count = seeds + 1;  // and the rest
  std::vector<rt::output::StartInfo> starts = backend::sceneStarts(module, options, result);
  starts.resize(seeds);
  std::vector<std::vector<rt::Report>> reports(count);
  for (const rt::Report& r : result.reports) {
    rt::Report own = r;
    own.start = 0;
    reports[std::min<size_t>(r.start, seeds)].push_back(std::move(own));
  }
  out.pieces.resize(count);
  std::vector<std::shared_ptr<ViewPiece>> fresh(count);
  for (size_t k = 0; k < count; ++k) {
    const uint32_t begin = std::min<uint32_t>(bounds[k], uint32_t(all.instances.size()));
    const uint32_t end = k < seeds ? std::min<uint32_t>(bounds[k + 1], uint32_t(all.instances.size()))
                                   : uint32_t(all.instances.size());
    out.bases.push_back(begin);
    rt::InstanceList list = pieceInstances(all, begin, end, k == seeds);
    if (k < last.pieces.size() && samePiece(*last.pieces[k], list, reports[k])) {
      out.pieces[k] = last.pieces[k];
      continue;
    }
    fresh[k] = std::make_shared<ViewPiece>();
    fresh[k]->list = std::move(list);
    fresh[k]->reports = std::move(reports[k]);
  }
  // The changed pieces assembled and encoded side by side (most edits change one).
  std::vector<std::string> errors(count);
  tbb::parallel_for(size_t(0), count, [&](size_t k) {
    if (!fresh[k]) return;
    ViewPiece& p = *fresh[k];
    std::vector<rt::output::StartInfo> info;
    if (k < seeds) {
      info.push_back(starts[k]);  // its name ("seed k"), the attrs' values, its reports
    } else {
      info.push_back(rt::output::StartInfo{"(surface and lines)", {}, {}, {}, {}});
    }
    ViewScene scene;
    if (!buildViewSceneOf(p.list, std::move(info), assets, meshOf, scene, errors[k])) return;
    p.glb = std::move(scene.glb);
    p.placing = std::move(scene.placing);
    p.ids = std::move(scene.ids);
    p.triangles = scene.triangles;
  });
  for (size_t k = 0; k < count; ++k) {
    if (!errors[k].empty()) return error = errors[k], false;
    if (fresh[k]) out.pieces[k] = std::move(fresh[k]), ++out.built;
    out.triangles += out.pieces[k]->triangles;
  }
  return true;
}

}  // namespace fgsg::cli
