#include "cli/check_data_files.h"

#include "backend/declared_tiles.h"
#include "backend/synthesis_examples.h"

#include <filesystem>
#include <set>

namespace fgsg::cli {

void checkDataFiles(const ir::Module& module, const std::string& grammarPath, frontend::Diagnostics& diags) {
  const auto grammarDir = std::filesystem::path(grammarPath).parent_path();
  const std::vector<std::string> dirs = {(grammarDir.empty() ? std::filesystem::path(".") : grammarDir).string(),
                                         (grammarDir / "assets").string()};
  std::set<std::string> seen;  // each file once, at its first call (run stops there too)
  for (const auto& call : backend::synthesizeCalls(module)) {
    if (!seen.insert(call.example).second) continue;
    std::string message;
    bool ok;
    if (rt::synthesis::continuous::isPolygonalExampleFile(call.example)) {
      rt::synthesis::continuous::ExampleSolid solid;
      ok = backend::loadContinuousExample(call.example, dirs, solid, message);
    } else {
      rt::synthesis::Example example;
      ok = backend::loadSynthesisExample(call.example, dirs, example, message);
    }
    if (!ok) diags.error("R013", {{call.at.line, call.at.col}, {call.at.line, call.at.col}}, message);
  }
  // Declared tilesets, checked as Evolve will check them.
  for (const ir::TileSetSpec& spec : module.tileSets) {
    rt::evolve::TileSet tiles;
    std::string message;
    ir::Loc at;
    if (!backend::declaredTileSet(spec, tiles, message, at))
      diags.error("R025", {{at.line, at.col}, {at.line, at.col}}, "Evolve: " + message);
  }
}

}  // namespace fgsg::cli
