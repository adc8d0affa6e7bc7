#include "cli/view_seed_file.h"

#include "runtime/io/atomic_file.h"
#include "runtime/io/seed_points.h"

#include <charconv>
#include <filesystem>

namespace fgsg::cli {

namespace fs = std::filesystem;

namespace {

std::string number(double v) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, v).ptr;
  return std::string(text, end);
}

}  // namespace

std::string defaultSeedFile(const std::string& grammarPath) {
  return fs::path(grammarPath).replace_extension(".seeds").string();
}

std::string seedFileText(const ViewSeeds& seeds, const std::string& grammarName) {
  std::string text = "# seeds of " + grammarName + " placed in fgsg view: x y z [dx dy dz] (fgsg run --seed-points)\n";
  for (const auto& s : seeds) {
    text += number(s.point[0]) + " " + number(s.point[1]) + " " + number(s.point[2]);
    if (s.hasDirection)
      text += " " + number(s.direction[0]) + " " + number(s.direction[1]) + " " + number(s.direction[2]);
    text += "\n";
  }
  return text;
}

bool writeSeedFile(const std::string& path, const ViewSeeds& seeds, const std::string& grammarName, std::string& error) {
  if (seeds.empty()) {
    std::error_code ec;
    fs::remove(path, ec);
    if (ec) error = "cannot remove " + path + ": " + ec.message();
    return !ec;
  }
  return rt::io::writeFileAtomically(path, seedFileText(seeds, grammarName), error);
}

bool readSeedFile(const std::string& path, ViewSeeds& seeds, std::string& error) {
  seeds.clear();
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(path, ec))) return true;
  return rt::io::readSeedPoints(path, seeds, error);
}

}  // namespace fgsg::cli
