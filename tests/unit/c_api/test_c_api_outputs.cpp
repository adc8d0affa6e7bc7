// What the C API lets reach a file: a generation whose instances reach past a 32-bit
// float's range fails (R005 at the op), so fgsg_write has nothing to write and an
// existing file is kept.
#include "backend/aot/fgsg_api.h"
#include "runtime/abi.h"

#include <catch2/catch.hpp>

#include <dlfcn.h>
#include <stdlib.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace {

namespace fs = std::filesystem;

std::string readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace

TEST_CASE("fgsg_generate refuses coordinates past a float's range and fgsg_write keeps the old file", "[c_api][outputs]") {
  std::string tmpl = (fs::temp_directory_path() / "fgsg-c-api-outputs-XXXXXX").string();
  REQUIRE(::mkdtemp(tmpl.data()) != nullptr);
  const fs::path dir = tmpl;
  const fs::path grammar = dir / "huge.fgsg";
  std::ofstream(grammar) << "axiom: S(1e308, 1, 1) I(\"cube\");\n";
  const fs::path lib = dir / "libhuge.so";
  const std::string cmd = std::string(FGSG_EXE) + " compile '" + grammar.string() + "' -o '" + lib.string() +
                          "' --quiet > '" + (dir / "compile.log").string() + "' 2>&1";
  REQUIRE(std::system(cmd.c_str()) == 0);
  void* handle = ::dlopen(lib.c_str(), RTLD_NOW | RTLD_LOCAL);
  REQUIRE(handle != nullptr);
  auto* program = static_cast<const FgsgProgram*>(::dlsym(handle, "fgsg_program_huge"));
  REQUIRE(program != nullptr);

  fgsg_generator* g = fgsg_generator_create(program);
  REQUIRE(g != nullptr);
  CHECK(fgsg_generate(g) != 0);
  const std::string error = fgsg_last_error(g);
  CHECK_THAT(error, Catch::Contains("huge.fgsg:1:23"));
  CHECK_THAT(error, Catch::Contains("R005"));
  CHECK_THAT(error, Catch::Contains("reaches coordinate 1e+308"));
  std::ofstream(dir / "old.glb") << "old";
  CHECK(fgsg_write(g, (dir / "old.glb").c_str()) != 0);
  CHECK(readText(dir / "old.glb") == "old");
  fgsg_generator_free(g);
  std::error_code ec;
  fs::remove_all(dir, ec);
}
