// Synthesize("example.obj", nx, ny, nz [, "Part"]): continuous model synthesis (Merrell
// ch. 4, runtime/synthesis/continuous/) in the shape's scope. The lattice is nx x ny x nz
// plane spacings along the scope's X, Y and Z (Y up, as the example mesh); the solid
// stands on the scope's floor. Each connected part of the result becomes a shape of the
// symbol "Part" with the part's whole faces as its geometry (so Comp("f") splits it into
// walls and roofs), or, without a symbol, the whole solid is output as one mesh.
#include "backend/commands/synthesis_command.h"

#include "backend/engine/derivation.h"
#include "backend/synthesis_examples.h"
#include "runtime/synthesis/continuous/continuous.h"

#include <algorithm>

namespace fgsg::backend {

namespace cs = rt::synthesis::continuous;

void SynthesisCommand::applyContinuous(const ir::Op& op, const int n[3], State& st, Exec& ex) {
  const ir::Module& m = d_.module();
  const std::string& name = m.strings[op.str];
  for (int k = 0; k < 3; ++k)
    if (n[k] < 2)
      throw DeriveError{op.loc, "R012", "Synthesize(\"" + name + "\"): continuous synthesis needs at least 2 plane "
                                        "spacings along each axis (a solid lies between the box's sides)"};
  const cs::ExampleSolid& solid = loadSolid(name, op.loc);
  cs::ContinuousOptions o;
  o.size = {double(n[0]), double(n[1]), double(n[2])};
  o.spacing = 1;
  o.onGround = true;
  o.seed = rt::childKey(ex.key, 0x8000000000000000ull | (uint64_t(op.loc.line) << 20) | op.loc.col);
  o.timeLimitSeconds = std::max(1.0, d_.options().maxSeconds);
  o.deadline = &d_.deadline();
  const cs::ContinuousResult r = cs::synthesizeContinuous(solid, o);
  if (!r.ok && d_.deadline().expiredNow()) throw d_.timeLimit();
  if (!r.ok) throw DeriveError{op.loc, "R013", "Synthesize(\"" + name + "\"): " + r.error};

  // Lattice units to the scope's own coordinates.
  const rt::Vec3 unit(st.scope.S.x() / n[0], st.scope.S.y() / n[1], st.scope.S.z() / n[2]);
  auto local = [&](const std::array<double, 3>& p) { return rt::Vec3(p[0] * unit.x(), p[1] * unit.y(), p[2] * unit.z()); };
  if (op.index == 0) {
    rt::Mesh world = r.mesh;
    for (size_t v = 0; v < world.vertexCount(); ++v) {
      const rt::Vec3 p = st.scope.P + st.scope.axes * local({world.positions[3 * v], world.positions[3 * v + 1], world.positions[3 * v + 2]});
      for (int c = 0; c < 3; ++c) world.positions[3 * v + size_t(c)] = float(p[c]);
    }
    if (world.triangleCount() == 0) return;
    rt::Scope box;
    const uint32_t asset = d_.addGeneratedAsset("<synthesized " + std::to_string(++synthesized_) + ">", world, &box);
    box.colored = st.scope.colored, box.color = st.scope.color;
    d_.placeInstance(asset, box, d_.placingSymbol(ex), nullptr, 0, op.loc);
    return;
  }
  const std::string& part = m.strings[op.index - 1];
  const int sym = m.findSymbolFrom(d_.placingSymbol(ex), part);
  if (sym < 0) throw DeriveError{op.loc, "R013", "Synthesize(\"" + name + "\"): '" + part + "' is no symbol of this grammar"};
  std::vector<std::vector<size_t>> facesOf(r.stats.parts);
  for (size_t f = 0; f < r.faces.size(); ++f) facesOf[r.facePart[f]].push_back(f);
  for (const auto& faces : facesOf) {
    if (faces.empty()) continue;
    rt::Vec3 lo = local(r.faces[faces[0]][0]), hi = lo;
    for (size_t f : faces)
      for (const auto& p : r.faces[f]) {
        lo = lo.cwiseMin(local(p));
        hi = hi.cwiseMax(local(p));
      }
    const rt::Vec3 size = hi - lo;
    // The part's faces in its own scope's unit box (runtime/geometry.h).
    std::vector<std::vector<rt::Vec3>> unitFaces;
    for (size_t f : faces) {
      std::vector<rt::Vec3> pts;
      for (const auto& p : r.faces[f]) {
        const rt::Vec3 q = local(p) - lo;
        pts.emplace_back(size.x() > 0 ? q.x() / size.x() : 0, size.y() > 0 ? q.y() / size.y() : 0,
                         size.z() > 0 ? q.z() / size.z() : 0);
      }
      unitFaces.push_back(std::move(pts));
    }
    rt::Scope scope = st.scope;
    scope.P = st.scope.P + st.scope.axes * lo;
    scope.S = size;
    d_.emitShape(uint32_t(sym), scope, ex, op.loc, d_.arena().addPolyhedron(unitFaces));
  }
}

const rt::synthesis::continuous::ExampleSolid& SynthesisCommand::loadSolid(const std::string& name, ir::Loc at) {
  auto it = solids_.find(name);
  if (it != solids_.end()) return it->second;
  cs::ExampleSolid solid;
  std::string message;
  // --max-seconds counts the reading of a large example too.
  if (!loadContinuousExample(name, d_.options().assetDirs, solid, message, &d_.deadline())) {
    if (d_.deadline().expiredNow()) throw d_.timeLimit();
    throw DeriveError{at, "R013", message};
  }
  return solids_.emplace(name, std::move(solid)).first->second;
}

}  // namespace fgsg::backend
