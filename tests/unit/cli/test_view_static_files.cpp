// fgsg view serves its page's files by exact name from memory (cli/view_static_files.h):
// the traversal forms of issue 41 find nothing.
#include "cli/view_static_files.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <vector>

#include <unistd.h>

namespace fs = std::filesystem;

TEST_CASE("view static files: the page's own files and nothing else") {
  const fs::path dir = fs::path(FGSG_BINARY_DIR) / "test-scratch" / "view_static" / std::to_string(::getpid());
  fs::remove_all(dir);
  fs::create_directories(dir / "page" / "three" / "build");
  std::ofstream(dir / "page" / "index.html") << "<html>page</html>";
  std::ofstream(dir / "page" / "viewer.js") << "js";
  std::ofstream(dir / "page" / "three" / "build" / "three.module.js") << "three";
  std::ofstream(dir / "page" / "notes.txt") << "not a page's file";
  std::ofstream(dir / "secret.js") << "secret";
  fs::create_symlink(dir / "secret.js", dir / "page" / "linked.js");
  fs::create_symlink("/etc", dir / "page" / "etc");

  fgsg::cli::ViewStaticFiles files;
  std::string error;
  REQUIRE(files.load((dir / "page").string(), error));
  CHECK(files.count() == 3);
  REQUIRE(files.find("/"));
  CHECK(files.find("/")->body == "<html>page</html>");
  CHECK(files.find("/?token=abc")->body == "<html>page</html>");
  CHECK(files.find("/index.html")->contentType == "text/html; charset=utf-8");
  CHECK(files.find("/three/build/three.module.js")->body == "three");
  CHECK(files.find("/viewer.js#x")->body == "js");
  for (const std::string& bad : std::vector<std::string>{"//etc/passwd", "/etc/passwd", "/../secret.js", "/%2e%2e/secret.js", "/linked.js", "/etc/hostname",
        "/notes.txt", "/three//build/three.module.js", "/./index.html", "/index.html%00.js",
        std::string("/index.html\0.js", 15), "index.html", "/three/build/../../secret.js", "/" + std::string(5000, 'a')})
    CHECK_FALSE(files.find(bad));
  fs::remove_all(dir);
}

TEST_CASE("view static files: a folder that is not the page is refused") {
  fgsg::cli::ViewStaticFiles files;
  std::string error;
  CHECK_FALSE(files.load("/nonexistent-folder-of-fgsg", error));
  CHECK_FALSE(error.empty());
}
