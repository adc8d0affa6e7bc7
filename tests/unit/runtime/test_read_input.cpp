// Bounded input reading: what is not a regular file is refused by what it is, before any
// read can block or run without end; files above the cap are refused by their size.
#include "runtime/io/read_input.h"
#include "scratch_files.h"

#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <fstream>

using namespace fgsg::rt::io;
namespace fs = std::filesystem;

namespace {
std::string refusal(const std::string& path, uint64_t cap = kMaxInputBytes) {
  std::string text, error;
  CHECK_FALSE(readInputFile(path, "a grammar file", text, error, cap));
  CHECK(text.empty());
  return error;
}
}  // namespace

TEST_CASE("input files: regular files are read whole", "[read_input]") {
  const fs::path dir = fgsg::test::scratchDir("read_input", "regular");
  std::string content(100000, 'x');
  content[5] = '\0';  // bytes, not a C string
  std::ofstream(dir / "a.fgsg", std::ios::binary) << content;
  std::string text, error;
  REQUIRE(readInputFile((dir / "a.fgsg").string(), "a grammar file", text, error));
  CHECK(text == content);
  std::ofstream(dir / "empty.fgsg", std::ios::binary).flush();
  REQUIRE(readInputFile((dir / "empty.fgsg").string(), "a grammar file", text, error));
  CHECK(text.empty());
  // Through a link to a regular file: read like the file.
  fs::create_symlink(dir / "a.fgsg", dir / "link.fgsg");
  REQUIRE(readInputFile((dir / "link.fgsg").string(), "a grammar file", text, error));
  CHECK(text == content);
}

TEST_CASE("input files: what is not a regular file is named", "[read_input]") {
  const fs::path dir = fgsg::test::scratchDir("read_input", "kinds");
  const std::string fifo = (dir / "pipe.fgsg").string();
  REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
  CHECK(refusal(fifo) == fifo + ": is a FIFO (named pipe), not a grammar file");
  CHECK(refusal("/dev/zero") == "/dev/zero: is a character device, not a grammar file");
  CHECK(refusal(dir.string()) == dir.string() + ": is a directory, not a grammar file");
  CHECK(refusal((dir / "none.fgsg").string()) == (dir / "none.fgsg").string() + ": no such file");
  CHECK(refusal((dir / "none" / "x.fgsg").string()) ==
        (dir / "none" / "x.fgsg").string() + ": no such file");

  fs::create_symlink("/dev/zero", dir / "zero.fgsg");
  fs::create_symlink(fifo, dir / "pipe-link.fgsg");
  fs::create_symlink(dir / "gone.fgsg", dir / "dangling.fgsg");
  const std::string zero = (dir / "zero.fgsg").string(), pipe = (dir / "pipe-link.fgsg").string(),
                    dangling = (dir / "dangling.fgsg").string();
  CHECK(refusal(zero) == zero + ": is a symbolic link to '/dev/zero', a character device, not a grammar file");
  CHECK(refusal(pipe) == pipe + ": is a symbolic link to '" + fifo +
                             "', a FIFO (named pipe), not a grammar file");
  CHECK(refusal(dangling) ==
        dangling + ": is a symbolic link to '" + (dir / "gone.fgsg").string() + "', which does not exist");
  std::string error;
  CHECK_FALSE(checkInputFile(zero, "a mesh file", error));
  CHECK(withoutPath(error, zero) ==
        "is a symbolic link to '/dev/zero', a character device, not a mesh file");
}

TEST_CASE("input files: the size cap", "[read_input]") {
  const fs::path dir = fgsg::test::scratchDir("read_input", "cap");
  const std::string path = (dir / "big.fgsg").string();
  std::ofstream(path, std::ios::binary) << std::string(3 << 20, 'x');
  CHECK(refusal(path, uint64_t(2) << 20) ==
        path + ": is larger than 2 MiB (3145728 bytes; the limit for input files), not read");
  std::string text, error;
  CHECK(readInputFile(path, "a grammar file", text, error, uint64_t(3) << 20));
  CHECK(text.size() == size_t(3) << 20);
  CHECK(kMaxInputBytes == uint64_t(256) << 20);
}
