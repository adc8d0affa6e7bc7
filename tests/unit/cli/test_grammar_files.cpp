// The files fgsg view watches besides the grammar's folder: every name the grammar writes
// that is a file, found where a run finds it; names that are no file are left out.
#include "cli/grammar_files.h"
#include "frontend/diagnostics.h"
#include "ir/pipeline.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include <unistd.h>

namespace fs = std::filesystem;

TEST_CASE("the data files a grammar names, where a run looks them up") {
  const fs::path dir = fs::path(FGSG_BINARY_DIR) / "test-scratch" / "grammar_files" / std::to_string(::getpid());
  fs::remove_all(dir);
  fs::create_directories(dir / "meshes");
  fs::create_directories(dir / "assets");
  std::ofstream(dir / "meshes" / "ground.off") << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  std::ofstream(dir / "assets" / "brick.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  std::ofstream(dir / "bark.png") << "not read here";
  const std::string text =
      "surface \"meshes/ground.off\";\n"
      "Axiom ~> Texture(\"bark.png\") I(\"brick.obj\") I(\"cube\") I(\"gone.obj\");\n";
  auto file = fgsg::frontend::SourceFile::make((dir / "g.fgsg").string(), text);
  fgsg::frontend::Diagnostics diags(&file);
  fgsg::ir::Module m;
  REQUIRE(fgsg::ir::compileSource(file, m, diags));
  const auto files = fgsg::cli::grammarDataFiles(m, (dir / "g.fgsg").string(), {(dir / "bark.png").string()});
  CHECK(files == std::vector<std::string>{(dir / "assets" / "brick.obj").string(), (dir / "bark.png").string(),
                                          (dir / "meshes" / "ground.off").string()});
  fs::remove_all(dir);
}
