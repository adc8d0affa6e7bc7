#include "backend/commands/synthesis_command.h"

#include "backend/engine/derivation.h"
#include "backend/synthesis_examples.h"

#include <algorithm>
#include <cmath>

namespace fgsg::backend {

// The grid's z runs along the scope's Y, its y against the scope's Z.
void SynthesisCommand::apply(const ir::Op& op, const double* a, uint32_t, State& st, Exec& ex, Frame&) {
  const ir::Module& m = d_.module();
  const std::string& name = m.strings[op.str];
  int n[3];
  for (int k = 0; k < 3; ++k) {
    const double v = a[k];
    if (!(v >= 1) || v > 4096 || v != std::floor(v))
      throw DeriveError{op.loc, "R012", "Synthesize: grid sizes must be whole numbers from 1 to 4096"};
    n[k] = static_cast<int>(v);
  }
  if (rt::synthesis::continuous::isPolygonalExampleFile(name)) return applyContinuous(op, n, st, ex);
  const rt::synthesis::Example& example = loadExample(name, op.loc);
  rt::synthesis::SynthesisOptions so;
  so.size = {n[0], n[1], n[2]};
  so.seed = rt::childKey(ex.key, 0x8000000000000000ull | (uint64_t(op.loc.line) << 20) | op.loc.col);
  so.attempts = 10;  // whole-grid synthesis restarts after a contradiction
  so.timeLimitSeconds = std::max(1.0, d_.options().maxSeconds);
  so.deadline = &d_.deadline();  // and with the derivation's own clock
  const rt::synthesis::SynthesisResult result = rt::synthesis::synthesize(example, so);
  if (!result.ok && d_.deadline().expiredNow()) throw d_.timeLimit();
  if (!result.ok) throw DeriveError{op.loc, "R013", "Synthesize(\"" + name + "\"): " + result.failure.message};
  rt::synthesis::PlacementFrame frame;
  frame.cellSize = {st.scope.S.x() / n[0], st.scope.S.z() / n[1], st.scope.S.y() / n[2]};
  // The frame's grid y runs towards -Z: shift it back into the scope box.
  rt::Mat4 toScope = rt::Mat4::Identity();
  toScope.block<3, 3>(0, 0) = st.scope.axes;
  toScope.block<3, 1>(0, 3) = st.scope.P + st.scope.axes * rt::Vec3(0, 0, st.scope.S.z());
  for (const auto& place : rt::synthesis::piecePlacements(result.labels, example, frame)) {
    const rt::Mat4 local = Eigen::Map<const rt::Mat4>(place.transform.data());
    const rt::Mat4 world = toScope * local;
    const int sym = m.findSymbolFrom(d_.placingSymbol(ex), example.labels[place.label].name);
    rt::Scope cell;
    cell.P = world.block<3, 1>(0, 3);
    for (int k = 0; k < 3; ++k) {
      cell.S[k] = world.block<3, 1>(0, k).norm();
      cell.axes.col(k) = cell.S[k] > 0 ? rt::Vec3(world.block<3, 1>(0, k) / cell.S[k]) : st.scope.axes.col(k);
    }
    if (sym >= 0 && !m.symbols[sym].rules.empty() && m.symbols[sym].slotCount == 0) {
      d_.emitShape(static_cast<uint32_t>(sym), cell, ex, op.loc);
    } else if (!place.asset.empty()) {
      d_.placeInstance(pieceAsset(place.asset, op.loc), cell, d_.placingSymbol(ex), nullptr, 0, op.loc);
      d_.output().instances.back().color = place.color;
    }
  }
}

const rt::synthesis::Example& SynthesisCommand::loadExample(const std::string& name, ir::Loc at) {
  auto it = examples_.find(name);
  if (it != examples_.end()) return it->second;
  rt::synthesis::Example example;
  std::string message;
  if (!loadSynthesisExample(name, d_.options().assetDirs, example, message)) throw DeriveError{at, "R013", message};
  return examples_.emplace(name, std::move(example)).first->second;
}

// A piece's asset joins the output's asset table the first time it is placed.
uint32_t SynthesisCommand::pieceAsset(const std::string& asset, ir::Loc at) {
  rt::InstanceList& out = d_.output();
  for (uint32_t i = 0; i < out.assets.size(); ++i)
    if (out.assets[i] == asset) return i;
  std::string error;
  if (d_.assets().resolve(asset, error) < 0) throw DeriveError{at, "R003", error};
  out.assets.push_back(asset);
  return static_cast<uint32_t>(out.assets.size() - 1);
}

}  // namespace fgsg::backend
