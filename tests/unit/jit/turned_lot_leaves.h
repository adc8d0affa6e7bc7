#pragma once
// Deriving a test grammar on a lot that is turned and moved in the world (so that the
// scope, pivot, object and world systems all differ) with the interpreter and the JIT,
// which must place every leaf bit for bit alike; the leaves are read back as frames.
// Shared by the setPivot and the translate/rotate-systems tests.
#include "backend/interp/interpreter.h"
#include "backend/jit/jit.h"
#include "backend/native/object_cache.h"
#include "frontend/diagnostics.h"
#include "ir/pipeline.h"

#include <catch2/catch.hpp>

#include <Eigen/Core>

#include <cstring>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace fgsg::turned_lot {

// In the lots' plane (x east, y north): first corner (10, 20), first edge 5 m along
// (0.6, 0.8), 10 m deep to its left. In the world (x east, y up, z south) its corners are
// (10, 0, -20), (13, 0, -24), (5, 0, -30), (2, 0, -26).
inline rt::Lot lot() {
  rt::Lot lot;
  lot.outer = {{10, 20}, {13, 24}, {5, 30}, {2, 26}};
  lot.id = "turned";
  return lot;
}

// A leaf's scope: origin P, unit axes X Y Z, size S, and its geometry's vertices in the
// world (the unit cube's eight corners for a whole box leaf).
struct Leaf {
  Eigen::Vector3d P, X, Y, Z, S;
  std::vector<Eigen::Vector3d> corners;
};

inline ir::Module compile(const std::string& text, const std::string& name) {
  auto file = frontend::SourceFile::make(name, text);
  frontend::Diagnostics diags(&file);
  ir::Module m;
  if (!ir::compileSource(file, m, diags)) {
    std::ostringstream out;
    diags.print(out);
    FAIL("the test grammar does not compile:\n" << out.str());
  }
  return m;
}

// The leaves by symbol (the last of a symbol's leaves wins: tests name each leaf apart).
inline std::map<std::string, Leaf> leavesOf(const rt::DeriveResult& r) {
  REQUIRE(r.ok);
  std::map<std::string, Leaf> out;
  for (const rt::Instance& inst : r.instances.instances) {
    const Eigen::Matrix4d m = Eigen::Map<const Eigen::Matrix4d>(inst.transform.data());
    Leaf leaf;
    leaf.P = m.block<3, 1>(0, 3);
    leaf.S = Eigen::Vector3d(m.col(0).head<3>().norm(), m.col(1).head<3>().norm(), m.col(2).head<3>().norm());
    leaf.X = m.col(0).head<3>() / leaf.S.x();
    leaf.Y = m.col(1).head<3>() / leaf.S.y();
    leaf.Z = m.col(2).head<3>() / leaf.S.z();
    if (inst.geometry != UINT32_MAX) {
      const rt::Mesh& mesh = r.instances.geometries[inst.geometry];
      for (size_t i = 0; i < mesh.vertexCount(); ++i) {
        const Eigen::Vector4d u(mesh.positions[3 * i], mesh.positions[3 * i + 1], mesh.positions[3 * i + 2], 1.0);
        leaf.corners.push_back((m * u).head<3>());
      }
    } else if (r.instances.assets[inst.asset] == "cube") {
      for (int k = 0; k < 8; ++k)
        leaf.corners.push_back((m * Eigen::Vector4d(k & 1, (k >> 1) & 1, k >> 2, 1.0)).head<3>());
    }
    out[r.instances.symbols[inst.symbol]] = leaf;
  }
  return out;
}

// Derives `text` with both engines, on the turned lot or (onLot false) without lots: the
// axiom's unit box at the origin.
inline std::map<std::string, Leaf> deriveBothEngines(const std::string& text, const std::string& name,
                                                     bool onLot = true) {
  const ir::Module m = compile(text, name);
  rt::DeriveOptions options;
  if (onLot) {
    options.lots = {lot()};
    options.lotsName = "lots.geojson";
  }
  rt::AssetLibrary assets;
  const rt::DeriveResult interp = backend::interpret(m, options, assets);
  backend::jit::Jit jit;
  const auto code = jit.compileProgram(m, text, backend::native::ObjectCache{std::string()});
  const rt::DeriveResult jitted = backend::deriveCompiled(m, code.program(), options, assets);
  REQUIRE(interp.ok);
  REQUIRE(jitted.ok);
  REQUIRE(interp.instances.instances.size() == jitted.instances.instances.size());
  for (size_t i = 0; i < interp.instances.instances.size(); ++i)
    CHECK(std::memcmp(interp.instances.instances[i].transform.data(), jitted.instances.instances[i].transform.data(),
                      sizeof(double) * 16) == 0);
  return leavesOf(interp);
}

}  // namespace fgsg::turned_lot
