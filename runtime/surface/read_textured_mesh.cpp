#include "runtime/surface/read_textured_mesh.h"

#include "runtime/io/check_collada.h"
#include "runtime/io/check_fbx.h"
#include "runtime/io/check_gltf.h"
#include "runtime/io/check_ply.h"
#include "runtime/io/quoted_text.h"
#include "runtime/io/read_input.h"
#include "runtime/io/read_mesh_file.h"
#include "runtime/memory_budget.h"

#include <assimp/DefaultIOSystem.h>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <charconv>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <unordered_map>

namespace fgsg::rt::surface {

namespace {

// The lines of `bytes` as views, without their line ends.
template <class Visit>
void forEachLine(std::string_view bytes, Visit&& visit) {
  size_t pos = 0;
  while (pos < bytes.size()) {
    size_t end = bytes.find('\n', pos);
    if (end == std::string_view::npos) end = bytes.size();
    std::string_view line = bytes.substr(pos, end - pos);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    pos = end + 1;
    if (!visit(line)) return;
  }
}

std::string_view firstWord(std::string_view line) {
  const size_t b = line.find_first_not_of(" \t");
  if (b == std::string_view::npos) return {};
  const size_t e = line.find_first_of(" \t", b);
  return line.substr(b, e == std::string_view::npos ? std::string_view::npos : e - b);
}

// OBJ: `vt` lines, and a first face whose corners name them (v/vt or v/vt/vn).
bool objHasTextureCoordinates(std::string_view bytes) {
  bool vt = false, sawFace = false, faceUsesVt = false;
  forEachLine(bytes, [&](std::string_view line) {
    const std::string_view word = firstWord(line);
    if (word == "vt") {
      vt = true;
    } else if (word == "f" && !sawFace) {
      sawFace = true;
      const std::string_view corner = firstWord(line.substr(line.find('f') + 1));
      const size_t slash = corner.find('/');
      faceUsesVt = slash != std::string_view::npos && slash + 1 < corner.size() && corner[slash + 1] != '/';
    }
    return !(vt && sawFace);
  });
  return vt && faceUsesVt;
}

// The next word of `line` from `pos` on (empty at the end), `pos` moved past it.
std::string_view nextWord(std::string_view line, size_t& pos) {
  const size_t b = line.find_first_not_of(" \t", pos);
  if (b == std::string_view::npos) return pos = line.size(), std::string_view();
  const size_t e = std::min(line.find_first_of(" \t", b), line.size());
  pos = e;
  return line.substr(b, e - b);
}

// "nan", "inf", "-inf", "+NaN(...)", "infinity": what text readers misread.
bool spellsNonFinite(std::string_view word) {
  const size_t sign = !word.empty() && (word[0] == '-' || word[0] == '+');
  if (word.size() < sign + 3) return false;
  char lower[3];
  for (int i = 0; i < 3; ++i) lower[i] = char(std::tolower(static_cast<unsigned char>(word[sign + i])));
  return std::string_view(lower, 3) == "nan" || std::string_view(lower, 3) == "inf";
}

// assimp's OBJ reader reads "nan" as a number and takes a corner naming a texture
// coordinate that does not exist without a word. So every `v` and `vt` line is checked
// for non-finite numbers, and every face corner's indices against the counts, first.
bool checkObjText(const std::string& path, std::string_view bytes, std::string& error) {
  long long total[2] = {0, 0};  // vertices, texture coordinates
  forEachLine(bytes, [&](std::string_view line) {
    const std::string_view word = firstWord(line);
    total[0] += word == "v";
    total[1] += word == "vt";
    return true;
  });
  long long seen[2] = {0, 0}, lineNo = 0;
  const char* const noun[2] = {"vertex", "texture coordinate"};
  bool ok = true;
  forEachLine(bytes, [&](std::string_view line) {
    ++lineNo;
    auto fail = [&](const std::string& message) {
      error = path + ":" + std::to_string(lineNo) + ": " + message;
      return ok = false;
    };
    size_t pos = 0;
    const std::string_view word = nextWord(line, pos);
    if (word == "v" || word == "vt") {
      const int kind = word == "vt";
      ++seen[kind];
      for (std::string_view t = nextWord(line, pos); !t.empty(); t = nextWord(line, pos))
        if (spellsNonFinite(t))
          return fail(std::string(kind ? "texture" : "vertex") + " coordinate " + io::quoteText(t) +
                      " is not a finite number");
    } else if (word == "f") {
      // v, v/vt, v//vn or v/vt/vn: the first two checked (negative: counted back from the
      // last one so far).
      for (std::string_view t = nextWord(line, pos); !t.empty(); t = nextWord(line, pos)) {
        const size_t slash = t.find('/');
        const std::string_view part[2] = {
            t.substr(0, slash),
            slash == std::string_view::npos ? std::string_view()
                                            : t.substr(slash + 1, t.find('/', slash + 1) - slash - 1)};
        for (int kind = 0; kind < 2; ++kind) {
          if (kind == 1 && part[1].empty()) continue;
          long long index = 0;
          const auto [end, status] = std::from_chars(part[kind].data(), part[kind].data() + part[kind].size(), index);
          const bool valid = !part[kind].empty() && status == std::errc() && end == part[kind].data() + part[kind].size() &&
                             (index > 0 ? index <= total[kind] : index < 0 && -index <= seen[kind]);
          if (!valid)
            return fail("face corner " + io::quoteText(t) + " names " + noun[kind] + " " +
                        io::quoteText(part[kind]) + ", but there are " +
                        std::to_string(index < 0 ? seen[kind] : total[kind]) + (index < 0 ? " so far" : "") +
                        " (counting from 1)");
        }
      }
    }
    return true;
  });
  return ok;
}

// PLY: per-vertex properties named like texture coordinates, in the header.
bool plyHasTextureCoordinates(std::string_view bytes) {
  bool inVertex = false, u = false, v = false;
  forEachLine(bytes, [&](std::string_view line) {
    std::istringstream words{std::string(line)};
    std::string word, last;
    words >> word;
    if (word == "end_header") return false;
    if (word == "element") {
      words >> last;
      inVertex = last == "vertex";
    } else if (word == "property" && inVertex) {
      while (words >> word) last = word;
      u |= last == "u" || last == "s" || last == "texture_u";
      v |= last == "v" || last == "t" || last == "texture_v";
    }
    return true;
  });
  return u && v;
}

// assimp opens the main file and whatever it refers to (a glTF's buffers, an OBJ's
// materials) through this: names that are not regular files or are too large are refused
// the way fgsg refuses them everywhere (a buffer named "/dev/zero" must not hang the read).
class CheckedIOSystem : public Assimp::DefaultIOSystem {
 public:
  bool Exists(const char* file) const override {
    std::string ignored;
    return io::checkInputFile(file, "a mesh file", ignored);
  }
  Assimp::IOStream* Open(const char* file, const char* mode) override {
    if (std::strchr(mode, 'w') || std::strchr(mode, 'a')) return nullptr;  // read only
    std::string ignored;
    if (!io::checkInputFile(file, "a mesh file", ignored)) return nullptr;
    return DefaultIOSystem::Open(file, mode);
  }
};

// More triangles than this (meshes instanced by many nodes multiply) is not a surface
// anyone grows a grammar on, and would exhaust memory first.
constexpr size_t kMaxTriangles = size_t(1) << 26;

struct PositionKey {
  double x, y, z;
  bool operator==(const PositionKey& o) const { return x == o.x && y == o.y && z == o.z; }
};
struct PositionHash {
  size_t operator()(const PositionKey& k) const {
    auto bits = [](double d) {
      uint64_t b;
      std::memcpy(&b, &d, sizeof b);
      return b;
    };
    uint64_t h = bits(k.x) * 0x9E3779B97F4A7C15ull;
    h = (h ^ (h >> 29) ^ bits(k.y)) * 0xBF58476D1CE4E5B9ull;
    h = (h ^ (h >> 31) ^ bits(k.z)) * 0x94D049BB133111EBull;
    return size_t(h ^ (h >> 32));
  }
};

}  // namespace

bool readsThroughAssimp(const std::string& ext, std::string_view bytes) {
  if (ext == ".gltf" || ext == ".glb" || ext == ".fbx" || ext == ".dae") return true;
  if (ext == ".obj") return objHasTextureCoordinates(bytes);
  if (ext == ".ply") return plyHasTextureCoordinates(bytes);
  return false;
}

bool readTexturedMesh(const std::string& path, std::string_view bytes, SurfaceMesh& mesh, bool& polygonal,
                      std::string& error, uint64_t maxMemoryBytes) {
  mesh = SurfaceMesh{};
  polygonal = false;
  if (bytes.empty()) {
    error = path + ": the file is empty (no faces)";
    return false;
  }
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  // assimp's PLY reader trusts the header's counts and reads "nan": the same checks as for
  // OpenMesh's.
  if (ext == ".ply" && !(io::checkPlyStructure(path, bytes, error) && io::findNonFiniteText(path, ext, bytes, error)))
    return false;
  if (ext == ".obj" && !checkObjText(path, bytes, error)) return false;
  // assimp copies a node for every time it is listed as a child or instanced, and
  // allocates what the file declares: the node graph and counts are checked first.
  if ((ext == ".gltf" || ext == ".glb") &&
      !io::checkGltfBounds(path, bytes, readerMemoryLimit(maxMemoryBytes), error))
    return false;
  if (ext == ".dae" && !io::checkColladaNodes(path, bytes, error)) return false;
  if (ext == ".fbx" && !io::checkFbxNodes(path, bytes, readerMemoryLimit(maxMemoryBytes), error)) return false;

  Assimp::Importer importer;
  importer.SetIOHandler(new CheckedIOSystem);  // the importer owns it
  const aiScene* scene = nullptr;
  try {
    // Only structural validation: triangulation is a fan, as for the other formats, and
    // vertices are welded below by position (assimp's own joining also compares normals).
    scene = importer.ReadFile(path, aiProcess_ValidateDataStructure);
  } catch (const std::exception& e) {
    error = path + ": cannot read the file: " + e.what();
    return false;
  } catch (...) {
    error = path + ": cannot read the file";
    return false;
  }
  if (!scene || !scene->mRootNode || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE)) {
    const std::string why = importer.GetErrorString();
    error = path + ": cannot read the file" + (why.empty() ? std::string() : " (" + why + ")");
    return false;
  }

  // Which meshes carry coordinates decides whether the surface has them.
  unsigned withUV = 0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m)
    withUV += scene->mMeshes[m]->HasTextureCoords(0) && scene->mMeshes[m]->mNumUVComponents[0] >= 2;
  const bool textured = withUV > 0;
  if (textured && withUV != scene->mNumMeshes) {
    for (unsigned m = 0; m < scene->mNumMeshes; ++m)
      if (!scene->mMeshes[m]->HasTextureCoords(0) || scene->mMeshes[m]->mNumUVComponents[0] < 2) {
        error = path + ": mesh " + std::to_string(m) + " ('" + scene->mMeshes[m]->mName.C_Str() +
                "') has no texture coordinates, but " + std::to_string(withUV) +
                " others have: a surface has them everywhere or nowhere";
        return false;
      }
  }

  std::unordered_map<PositionKey, int, PositionHash> welded;
  struct Visit {
    const aiNode* node;
    aiMatrix4x4 transform;
  };
  std::vector<Visit> stack{{scene->mRootNode, scene->mRootNode->mTransformation}};
  while (!stack.empty()) {
    const Visit visit = stack.back();
    stack.pop_back();
    const aiNode* node = visit.node;
    const aiMatrix4x4& t = visit.transform;
    // The linear part's determinant: a mirroring transform turns the faces over.
    const double det = double(t.a1) * (double(t.b2) * t.c3 - double(t.b3) * t.c2) -
                       double(t.a2) * (double(t.b1) * t.c3 - double(t.b3) * t.c1) +
                       double(t.a3) * (double(t.b1) * t.c2 - double(t.b2) * t.c1);
    for (unsigned i = 0; i < node->mNumMeshes; ++i) {
      if (node->mMeshes[i] >= scene->mNumMeshes) {
        error = path + ": a node refers to mesh " + std::to_string(node->mMeshes[i]) +
                ", but there are only " + std::to_string(scene->mNumMeshes);
        return false;
      }
      const aiMesh* m = scene->mMeshes[node->mMeshes[i]];
      const std::string where = path + ": mesh " + std::to_string(node->mMeshes[i]);
      // Positions placed by the node, each welded to the first corner at the same place.
      std::vector<int> vertexOf(m->mNumVertices);
      for (unsigned v = 0; v < m->mNumVertices; ++v) {
        const aiVector3D& p = m->mVertices[v];
        const Vec3 q(t.a1 * double(p.x) + t.a2 * double(p.y) + t.a3 * double(p.z) + t.a4,
                     t.b1 * double(p.x) + t.b2 * double(p.y) + t.b3 * double(p.z) + t.b4,
                     t.c1 * double(p.x) + t.c2 * double(p.y) + t.c3 * double(p.z) + t.c4);
        if (!q.allFinite()) {
          error = where + ": vertex " + std::to_string(v) + " has a non-finite coordinate";
          return false;
        }
        const PositionKey key{q.x() + 0.0, q.y() + 0.0, q.z() + 0.0};  // -0 welds with +0
        const auto [it, added] = welded.try_emplace(key, int(mesh.vertices.size()));
        if (added) mesh.vertices.push_back(q);
        vertexOf[v] = it->second;
      }
      for (unsigned f = 0; f < m->mNumFaces; ++f) {
        const aiFace& face = m->mFaces[f];
        if (face.mNumIndices < 3) continue;  // points and lines carry no surface
        for (unsigned k = 0; k < face.mNumIndices; ++k)
          if (face.mIndices[k] >= m->mNumVertices) {
            error = where + ": face " + std::to_string(f) + " refers to vertex " +
                    std::to_string(face.mIndices[k]) + ", but the mesh has only " +
                    std::to_string(m->mNumVertices);
            return false;
          }
        polygonal |= face.mNumIndices > 3;
        if (mesh.faces.size() + face.mNumIndices > kMaxTriangles) {
          error = path + ": more than " + std::to_string(kMaxTriangles) +
                  " triangles once every node's meshes are placed";
          return false;
        }
        for (unsigned k = 1; k + 1 < face.mNumIndices; ++k) {
          std::array<unsigned, 3> c = {face.mIndices[0], face.mIndices[k], face.mIndices[k + 1]};
          if (det < 0) std::swap(c[1], c[2]);
          mesh.faces.push_back({vertexOf[c[0]], vertexOf[c[1]], vertexOf[c[2]]});
          if (!textured) continue;
          std::array<Eigen::Vector2d, 3> uv;
          for (int j = 0; j < 3; ++j) {
            const aiVector3D& w = m->mTextureCoords[0][c[j]];
            uv[j] = Eigen::Vector2d(w.x, w.y);
            if (!uv[j].allFinite()) {
              error = where + ": vertex " + std::to_string(c[j]) + " has a non-finite texture coordinate";
              return false;
            }
          }
          mesh.textureUV.push_back(uv);
        }
      }
    }
    // Children in reverse, so the first child is visited first.
    for (unsigned c = node->mNumChildren; c-- > 0;)
      if (node->mChildren[c]) stack.push_back({node->mChildren[c], t * node->mChildren[c]->mTransformation});
  }
  if (mesh.faces.empty()) {
    error = path + ": the file has no faces";
    mesh = SurfaceMesh{};
    return false;
  }
  return true;
}

}  // namespace fgsg::rt::surface
