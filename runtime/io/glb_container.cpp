#include "runtime/io/glb_container.h"

#include <bit>
#include <cstdint>
#include <limits>

namespace fgsg::rt::io::gltf {

static_assert(std::endian::native == std::endian::little, "GLB lengths are little endian");

bool glbPrefix(std::string& json, size_t binBytes, std::string& prefix, std::string& error) {
  json.resize(padded4(json.size()), ' ');
  const size_t total = 12 + 8 + json.size() + (binBytes ? 8 + binBytes : 0);
  if (total > std::numeric_limits<uint32_t>::max()) {
    error = "the GLB file would be " + std::to_string(total) + " bytes, past the format's 4 GiB limit";
    return false;
  }
  const auto u32 = [&](uint32_t v) { prefix.append(reinterpret_cast<const char*>(&v), 4); };
  prefix.clear();
  prefix.reserve(12 + 8 + json.size() + 8);
  prefix.append("glTF", 4);
  u32(2);
  u32(uint32_t(total));
  u32(uint32_t(json.size()));
  prefix.append("JSON", 4);
  prefix += json;
  if (binBytes) {
    u32(uint32_t(binBytes));
    prefix.append("BIN\0", 4);
  }
  return true;
}

}  // namespace fgsg::rt::io::gltf
