#include "runtime/marching/image_cache.h"

#include "runtime/io/atomic_file.h"
#include "runtime/io/content_hash.h"
#include "runtime/io/read_input.h"
#include "runtime/marching/geometry_image.h"
#include "runtime/random.h"

#include <cstring>
#include <filesystem>
#include <type_traits>

namespace fgsg::rt::marching {

namespace {

constexpr char kMagic[8] = {'F', 'G', 'S', 'G', 'M', 'I', 'M', 'G'};
constexpr uint32_t kByteOrderMark = 0x01020304;  // read back swapped on a machine of the other order
constexpr size_t kKeyDigits = 32;
// magic, version, byte order mark, key, payload length; the checksum after the payload.
constexpr size_t kHeaderBytes = sizeof kMagic + 4 + 4 + kKeyDigits + 8;
constexpr size_t kChecksumBytes = 16;
// The largest file read: an 8192^2 image at 6 bytes per texel and its atlas, with room.
constexpr uint64_t kMaxCacheBytes = uint64_t(1) << 31;

template <class T>
void put(std::string& out, const T& value) {
  static_assert(std::is_trivially_copyable_v<T>);
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}
template <class T>
void putArray(std::string& out, const std::vector<T>& values) {
  static_assert(std::is_trivially_copyable_v<T>);
  out.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

// Reads values off the payload, failing (never reading past the end) once it is short.
class Cursor {
 public:
  Cursor(const char* data, size_t size) : p_(data), left_(size) {}
  template <class T>
  bool get(T& value) {
    if (left_ < sizeof value) return false;
    std::memcpy(&value, p_, sizeof value);
    p_ += sizeof value, left_ -= sizeof value;
    return true;
  }
  template <class T>
  bool getArray(std::vector<T>& values, uint64_t count) {
    if (count > left_ / sizeof(T)) return false;
    values.resize(count);
    std::memcpy(values.data(), p_, count * sizeof(T));
    p_ += count * sizeof(T), left_ -= count * sizeof(T);
    return true;
  }
  size_t left() const { return left_; }

 private:
  const char* p_;
  size_t left_;
};

}  // namespace

std::string imageCacheKey(const surface::SurfaceMesh& mesh, const MarchingOptions& options) {
  io::ContentHash h;
  h.word(kImageCacheVersion);
  // Eigen's fixed-size vectors are their coordinates, contiguous and unpadded.
  static_assert(sizeof(Vec3) == 3 * sizeof(double) && sizeof(Vec2) == 2 * sizeof(double));
  h.bytes(mesh.vertices.data(), mesh.vertices.size() * sizeof(Vec3));
  h.bytes(mesh.faces.data(), mesh.faces.size() * sizeof(mesh.faces[0]));
  h.bytes(mesh.textureUV.data(), mesh.textureUV.size() * sizeof(mesh.textureUV[0]));
  h.word(uint64_t(int64_t(options.resolution)));
  return h.hex();
}

std::string imageCachePath(const std::string& cacheDir, const std::string& key) {
  return cacheDir + "/marching-" + key + ".fgsgimage";
}

bool writeImageCache(const std::string& path, const std::string& key, const MarchingSurface& surface,
                     std::string& error) {
  if (key.size() != kKeyDigits) {
    error = "a marching cache key has " + std::to_string(kKeyDigits) + " digits";
    return false;
  }
  const atlas::Atlas& a = surface.atlas();
  const ImageTexels& t = surface.image().texels();
  std::string payload;
  put(payload, int32_t(a.chartCount));
  put(payload, int32_t(a.resolution));
  put(payload, uint64_t(a.faceChart.size()));
  putArray(payload, a.faceChart);
  std::vector<double> uv;
  uv.reserve(a.cornerUV.size() * 6);
  for (const auto& corners : a.cornerUV)
    for (const Vec2& c : corners) uv.insert(uv.end(), {c.x(), c.y()});
  putArray(payload, uv);
  put(payload, int32_t(t.size));
  putArray(payload, t.kind);
  putArray(payload, t.face);
  putArray(payload, t.pointerCount);
  put(payload, uint64_t(t.pointers.size()));
  putArray(payload, t.pointers);

  std::string file;
  file.reserve(kHeaderBytes + payload.size() + kChecksumBytes);
  file.append(kMagic, sizeof kMagic);
  put(file, kImageCacheVersion);
  put(file, kByteOrderMark);
  file += key;
  put(file, uint64_t(payload.size()));
  file += payload;
  io::ContentHash check;
  check.bytes(payload.data(), payload.size());
  put(file, check.first());
  put(file, check.second());

  std::error_code ec;
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  if (!folder.empty()) std::filesystem::create_directories(folder, ec);
  if (ec) {
    error = "cannot create the folder '" + folder.string() + "': " + ec.message();
    return false;
  }
  return io::writeFileAtomically(path, file, error);
}

std::shared_ptr<const MarchingSurface> readImageCache(const std::string& path, const std::string& key,
                                                      const surface::SurfaceMesh& mesh,
                                                      const MarchingOptions& options, std::string& why) {
  std::string file, error;
  if (!io::readInputFile(path, "a marching cache file", file, error, kMaxCacheBytes)) {
    why = error;
    return nullptr;
  }
  if (file.size() < kHeaderBytes + kChecksumBytes || std::memcmp(file.data(), kMagic, sizeof kMagic) != 0) {
    why = "not a marching cache file";
    return nullptr;
  }
  Cursor header(file.data() + sizeof kMagic, kHeaderBytes - sizeof kMagic);
  uint32_t version = 0, mark = 0;
  uint64_t payloadBytes = 0;
  header.get(version);
  header.get(mark);
  if (mark != kByteOrderMark) {
    why = "written on a machine of the other byte order";
    return nullptr;
  }
  if (version != kImageCacheVersion) {
    why = "format version " + std::to_string(version) + ", this build reads " + std::to_string(kImageCacheVersion);
    return nullptr;
  }
  if (file.compare(sizeof kMagic + 8, kKeyDigits, key) != 0 || key.size() != kKeyDigits) {
    why = "made for another mesh or other options";
    return nullptr;
  }
  std::memcpy(&payloadBytes, file.data() + kHeaderBytes - 8, 8);
  if (payloadBytes != file.size() - kHeaderBytes - kChecksumBytes) {
    why = "truncated (or padded): its length does not match its header";
    return nullptr;
  }
  const char* payload = file.data() + kHeaderBytes;
  io::ContentHash check;
  check.bytes(payload, payloadBytes);
  uint64_t stored[2];
  std::memcpy(stored, payload + payloadBytes, sizeof stored);
  if (stored[0] != check.first() || stored[1] != check.second()) {
    why = "corrupt: its checksum does not match";
    return nullptr;
  }

  Cursor in(payload, payloadBytes);
  atlas::Atlas a;
  ImageTexels t;
  int32_t chartCount = 0, resolution = 0, size = 0;
  uint64_t faces = 0, pointers = 0;
  std::vector<double> uv;
  bool ok = in.get(chartCount) && in.get(resolution) && in.get(faces) && faces == mesh.faceCount() &&
            in.getArray(a.faceChart, faces) && in.getArray(uv, faces * 6) && in.get(size) &&
            size >= kMinImageResolution && size <= kMaxImageResolution;
  const uint64_t texels = ok ? uint64_t(size) * uint64_t(size) : 0;
  ok = ok && in.getArray(t.kind, texels) && in.getArray(t.face, texels) && in.getArray(t.pointerCount, texels) &&
       in.get(pointers) && in.getArray(t.pointers, pointers) && in.left() == 0;
  if (!ok) {
    why = "inconsistent: its sizes do not fit the mesh or each other";
    return nullptr;
  }
  a.chartCount = chartCount;
  a.resolution = resolution;
  a.cornerUV.resize(faces);
  for (size_t f = 0; f < faces; ++f)
    for (int k = 0; k < 3; ++k) a.cornerUV[f][k] = Vec2(uv[6 * f + 2 * k], uv[6 * f + 2 * k + 1]);
  t.size = size;
  auto surface = MarchingSurface::fromStoredImage(mesh, a, std::move(t), options, error);
  if (!surface) why = "inconsistent: " + error;
  return surface;
}

}  // namespace fgsg::rt::marching
