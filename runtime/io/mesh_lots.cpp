// Building lots from mesh faces: the faces read as polygons, projected to the ground and
// checked as lot rings.
#include "runtime/io/mesh_lots.h"

#include "runtime/io/file_extension.h"
#include "runtime/io/lot_rings.h"
#include "runtime/io/read_input.h"
#include "runtime/io/read_mesh_file.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <new>
#include <sstream>
#include <string_view>
#include <unordered_map>

namespace fgsg::rt {

namespace {

// OpenMesh's OBJ reader mends faces without a word: it drops a vertex a face names twice
// (`f 1 2 3 1 4` becomes the square 1 2 3 4), then a face left with fewer than three
// (`f 1 2 1`), which also renumbers the faces after it. A lot is what the file says, so
// such faces are refused here by their line. A vertex repeated right after itself, or the
// last corner repeating the first, only pads or closes the outline (as in GeoJSON) and
// passes. `faces` is the number of `f` lines.
bool checkObjFaceCorners(const std::string& path, std::string_view bytes, size_t& faces, std::string& error) {
  long long vertices = 0;  // so far, for corners counted back from the last one
  size_t lineNo = 0;
  faces = 0;
  for (size_t pos = 0; pos < bytes.size();) {
    const size_t end = std::min(bytes.find('\n', pos), bytes.size());
    std::istringstream words{std::string(bytes.substr(pos, end - pos))};
    pos = end + 1;
    ++lineNo;
    std::string word;
    if (!(words >> word)) continue;
    if (word == "v") ++vertices;
    if (word != "f") continue;
    const size_t face = faces++;
    // Vertex numbers (from 1) and the corners naming them, repeats in a row dropped.
    std::vector<long long> vertex;
    std::vector<size_t> corner;
    bool readable = true;
    size_t c = 0;
    for (std::string text; words >> text; ++c) {
      long long v = 0;
      const auto [stop, status] = std::from_chars(text.data(), text.data() + text.size(), v);  // "v/vt/vn"
      readable = readable && status == std::errc() && (stop == text.data() + text.size() || *stop == '/');
      if (v < 0) v += vertices + 1;
      if (vertex.empty() || vertex.back() != v) vertex.push_back(v), corner.push_back(c);
    }
    if (!readable) continue;  // readMeshFile has read the corners, so this is a form it knows
    if (vertex.size() > 1 && vertex.front() == vertex.back()) vertex.pop_back(), corner.pop_back();
    std::vector<long long> distinct = vertex;
    std::sort(distinct.begin(), distinct.end());
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    const std::string where = path + ":" + std::to_string(lineNo) + ": face " + std::to_string(face) + ": ";
    if (distinct.size() < 3) {
      error = where + std::to_string(distinct.size()) + " distinct vertices; a lot needs at least 3";
      return false;
    }
    if (distinct.size() == vertex.size()) continue;
    std::unordered_map<long long, size_t> firstCorner;
    for (size_t j = 0; j < vertex.size(); ++j)
      if (const auto [first, added] = firstCorner.try_emplace(vertex[j], corner[j]); !added) {
        error = where + "corners " + std::to_string(first->second) + " and " + std::to_string(corner[j]) +
                " are both vertex " + std::to_string(vertex[j]) + ", so its outline touches itself";
        return false;
      }
  }
  return true;
}

// OBJ and PLY positions come through single precision: 12.3 arrives as 12.3000001907. The
// shortest decimal that reads back to the same float is what the file wrote whenever it
// wrote 7 significant digits or fewer, and never further from it than the float.
double asWritten(double v) {
  const float f = float(v);
  if (double(f) != v) return v;  // a double the reader kept (OFF)
  char text[32];
  const char* end = std::to_chars(text, text + sizeof text, f).ptr;
  double written = v;
  std::from_chars(text, end, written);
  return written;
}

// As the ring checks write a corner, and the GeoJSON reader its limits.
std::string lotText(const Eigen::Vector3d& p) {
  std::ostringstream s;
  s << std::setprecision(12) << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return s.str();
}

std::string lotText(double v) {
  std::ostringstream s;
  s << std::setprecision(12) << v;
  return s.str();
}

// The faces of `mesh` as lots (see the header); false at the first unsound one.
bool facesToLots(const std::string& path, const io::MeshFileContent& mesh, std::vector<Lot>& lots,
                 std::string& error) {
  LotMessages messages;
  messages.namesRings = false;  // a face is one ring
  messages.pointNoun = "corner";
  messages.coordinates = 3;
  messages.view = " seen from above";
  for (size_t f = 0; f < mesh.polygonCount(); ++f) {
    messages.place = path + ": face " + std::to_string(f);
    if (mesh.cornerCount(f) > kMaxLotPoints) {
      error = messages.place + ": more than " + std::to_string(kMaxLotPoints) + " corners; a lot has fewer";
      return false;
    }
    LotRing ring;
    for (size_t k = 0; k < mesh.cornerCount(f); ++k) {
      const std::array<double, 3>& v = mesh.vertices[size_t(mesh.corners[mesh.polygonStart[f] + k])];
      const Eigen::Vector3d q(asWritten(v[0]), asWritten(v[1]), asWritten(v[2]));
      const std::string where = messages.place + ", corner " + std::to_string(k) + ": ";
      if (!q.allFinite()) {
        error = where + lotText(q) + " is not a finite position";
        return false;
      }
      if (std::abs(q.x()) > kMaxLotMetres || std::abs(q.z()) > kMaxLotMetres) {
        error = where + lotText(q) + " is more than " + lotText(kMaxLotMetres) + " m from the origin";
        return false;
      }
      // North is -z; 0 - z, not -z, so that z = 0 gives y = +0.
      const Eigen::Vector2d xy(q.x(), 0.0 - q.z());
      if (!ring.xy.empty() && xy == ring.xy.back()) continue;
      ring.xy.push_back(xy);
      ring.index.push_back(k);
      ring.file.push_back(q);
    }
    if (ring.xy.size() > 1 && ring.xy.front() == ring.xy.back()) {
      ring.xy.pop_back();
      ring.index.pop_back();
      ring.file.pop_back();
    }
    std::vector<LotRing> rings{std::move(ring)};
    Lot lot;
    lot.feature = f;
    if (!checkAndOrientRings(rings, messages, lot, error)) return false;
    lots.push_back(std::move(lot));
  }
  return true;
}

}  // namespace

bool isMeshLotsPath(const std::string& path) {
  const std::string ext = io::lowerExtension(path);
  return ext == ".obj" || ext == ".ply" || ext == ".off";
}

bool readMeshLots(const std::string& path, std::vector<Lot>& lots, std::string& error) {
  lots.clear();
  if (!isMeshLotsPath(path)) {
    error = path + ": lots are read from .obj, .ply or .off meshes, not from " +
            (io::lowerExtension(path).empty() ? std::string("a file without an extension")
                                              : "'" + io::lowerExtension(path) + "' files");
    return false;
  }
  try {
    io::MeshFileContent mesh;
    if (!io::readMeshFile(path, mesh, error)) return false;
    if (io::lowerExtension(path) == ".obj") {
      std::string bytes;
      size_t faces = 0;
      if (!io::readInputFile(path, "a mesh file", bytes, error) ||
          !checkObjFaceCorners(path, bytes, faces, error))
        return false;
      if (faces != mesh.polygonCount()) {  // the reader passed over a face the check above did not foresee
        error = path + ": " + std::to_string(mesh.polygonCount()) + " faces read from " +
                std::to_string(faces) + " 'f' lines, so faces cannot be named by their number";
        return false;
      }
    }
    if (mesh.polygonCount() == 0) {
      error = path + ": no faces of three or more corners to take lots from";
      return false;
    }
    std::vector<Lot> out;
    out.reserve(mesh.polygonCount());
    if (!facesToLots(path, mesh, out, error)) return false;
    lots = std::move(out);
    return true;
  } catch (const std::bad_alloc&) {
    error = path + ": out of memory reading the lots";
  }
  return false;
}

}  // namespace fgsg::rt
