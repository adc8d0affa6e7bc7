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
  // Appended piece by piece, not "..." + string: GCC 12 warns falsely (-Wrestrict) on a prepend.
  std::string text = "# seeds of ";
  text += grammarName + " placed in fgsg view: x y z [dx dy dz] (fgsg run --seed-points)\n";
  const auto appendVector = [&text](const auto& v) {
    for (int k = 0; k < 3; ++k) {
      if (k) text += " ";
      text += number(v[k]);
    }
  };
  for (const auto& s : seeds) {
    appendVector(s.point);
    if (s.hasDirection) {
      text += " ";
      appendVector(s.direction);
    }
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
