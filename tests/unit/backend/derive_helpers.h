// Test helpers: compile grammar text and derive it with the interpreter.
#pragma once

#include "backend/interp/interpreter.h"
#include "frontend/diagnostics.h"
#include "ir/pipeline.h"

#include <Eigen/Core>
#include <sstream>
#include <stdexcept>
#include <string>

namespace fgsg::test {

inline ir::Module compileText(const std::string& text) {
  auto file = frontend::SourceFile::make("test.fgsg", text);
  frontend::Diagnostics diags(&file);
  ir::Module m;
  if (!ir::compileSource(file, m, diags)) {
    std::ostringstream out;
    diags.print(out);
    throw std::runtime_error("grammar does not compile:\n" + out.str());
  }
  return m;
}

inline rt::DeriveResult deriveText(const std::string& text, rt::DeriveOptions opt = {}) {
  ir::Module m = compileText(text);
  rt::AssetLibrary assets;
  assets.addSearchDir(std::string(FGSG_SOURCE_DIR) + "/examples/assets");
  return backend::interpret(m, opt, assets);
}

inline Eigen::Matrix4d transformOf(const rt::Instance& inst) {
  return Eigen::Map<const Eigen::Matrix4d>(inst.transform.data());
}

// World position of a point given in the instance's unit box.
inline Eigen::Vector3d unitPoint(const rt::Instance& inst, double u, double v, double w) {
  Eigen::Vector4d p = transformOf(inst) * Eigen::Vector4d(u, v, w, 1.0);
  return p.head<3>();
}

inline size_t countAsset(const rt::DeriveResult& r, const std::string& asset) {
  size_t n = 0;
  for (const auto& inst : r.instances.instances)
    if (r.instances.assets[inst.asset] == asset) ++n;
  return n;
}

}  // namespace fgsg::test
