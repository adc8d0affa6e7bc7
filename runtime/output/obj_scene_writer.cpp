#include "runtime/output/obj_scene_writer.h"

#include "runtime/io/float_text.h"
#include "runtime/io/mesh_attributes.h"
#include "runtime/io/obj_writer.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <set>
#include <vector>

namespace fgsg::rt::output {

namespace {

// The longest line: "v" and six floats, or "f" and three corners of three indices.
constexpr size_t kMaxLine = 128;

// A name as one OBJ token: white space (and nothing at all) made '_'.
std::string token(const std::string& name) {
  std::string t = name.empty() ? "_" : name;
  for (char& c : t)
    if (std::isspace(static_cast<unsigned char>(c)) || std::iscntrl(static_cast<unsigned char>(c))) c = '_';
  return t;
}

char* putFloats(char* p, const float* v, int n) {
  for (int d = 0; d < n; ++d) {
    *p++ = ' ';
    p = io::putShortestFloat(p, std::isfinite(v[d]) ? v[d] : 0.0f);
  }
  return p;
}

char* putIndex(char* p, uint64_t i) { return std::to_chars(p, p + 24, i).ptr; }

bool anyVertexColors(const Scene& scene) {
  for (const StartNode& s : scene.starts)
    for (const GroupNode& g : s.groups)
      for (const BakedPart& p : g.baked)
        if (scene.materials[p.materials.back()].vertexColors && io::hasColors(p.mesh)) return true;
  return false;
}

// The material of the triangles of `run` (a run on an image the part has no material for
// is untextured).
uint32_t runMaterial(const BakedPart& part, size_t run) {
  const int32_t image = part.mesh.textureRuns[run].texture;
  return image >= 0 && size_t(image) + 1 < part.materials.size() ? part.materials[size_t(image)] : part.materials.back();
}

// The materials the OBJ's faces and lines use, in the order of their first use.
std::vector<uint32_t> usedMaterials(const Scene& scene) {
  std::vector<uint32_t> used;
  std::set<uint32_t> seen;
  const auto use = [&](uint32_t m) {
    if (seen.insert(m).second) used.push_back(m);
  };
  for (const StartNode& s : scene.starts)
    for (const GroupNode& g : s.groups)
      for (const BakedPart& p : g.baked) {
        const Mesh& m = p.mesh;
        if (m.textured()) {
          size_t begin = 0;
          for (size_t r = 0; r < m.textureRuns.size(); ++r) {
            const size_t end = r + 1 == m.textureRuns.size() ? m.triangleCount()
                                                             : std::clamp<size_t>(m.runEnd(r), begin, m.triangleCount());
            if (end > begin) use(runMaterial(p, r));
            begin = end;
          }
        } else if (m.triangleCount()) {
          use(p.materials.back());
        }
        if (!m.lines.empty()) use(p.materials.back());
      }
  return used;
}

class ObjWriter {
 public:
  ObjWriter(const Scene& scene, io::ByteSink& out) : scene_(scene), out_(out), colored_(anyVertexColors(scene)) {}

  void part(const BakedPart& part) {
    const Mesh& m = part.mesh;
    const size_t n = m.vertexCount();
    const bool normals = io::hasNormals(m), texcoords = m.hasTexcoords(), colors = io::hasColors(m);
    for (size_t v = 0; v < n; ++v) {
      char* p = out_.room(kMaxLine);
      *p++ = 'v';
      p = putFloats(p, &m.positions[3 * v], 3);
      if (colored_) {
        float rgb[3] = {1, 1, 1};
        if (colors)
          for (int d = 0; d < 3; ++d) rgb[d] = io::clamp01(m.colors[3 * v + d]);
        p = putFloats(p, rgb, 3);
      }
      *p++ = '\n';
      out_.advance(p);
    }
    if (texcoords)
      for (size_t v = 0; v < n; ++v) {
        char* p = out_.room(kMaxLine);
        *p++ = 'v', *p++ = 't';
        p = putFloats(p, &m.texcoords[2 * v], 2);
        *p++ = '\n';
        out_.advance(p);
      }
    if (normals)
      for (size_t v = 0; v < n; ++v) {
        char* p = out_.room(kMaxLine);
        *p++ = 'v', *p++ = 'n';
        p = putFloats(p, &m.normals[3 * v], 3);
        *p++ = '\n';
        out_.advance(p);
      }
    const auto face = [&](size_t t) {
      char* p = out_.room(kMaxLine);
      *p++ = 'f';
      for (int k = 0; k < 3; ++k) {
        // OBJ counts from 1, over the whole file, each list on its own: a part without
        // texture coordinates or normals writes no vt or vn for the next part to count.
        const uint64_t i = m.indices[3 * t + k] + 1;
        *p++ = ' ';
        p = putIndex(p, vertices_ + i);
        if (texcoords) *p++ = '/', p = putIndex(p, texcoords_ + i);
        if (normals) {
          *p++ = '/';
          if (!texcoords) *p++ = '/';
          p = putIndex(p, normals_ + i);
        }
      }
      *p++ = '\n';
      out_.advance(p);
    };
    const auto use = [&](uint32_t material) {
      if (material != current_) out_.append("usemtl " + token(scene_.materials[material].name) + "\n"), current_ = material;
    };
    // Triangles by image, as the runs say (a run on an image the part has no material for
    // is untextured).
    const size_t triangles = m.triangleCount();
    if (!m.textured()) {
      if (triangles) use(part.materials.back());
      for (size_t t = 0; t < triangles; ++t) face(t);
    } else {
      size_t begin = 0;
      for (size_t r = 0; r < m.textureRuns.size(); ++r) {
        const size_t end = r + 1 == m.textureRuns.size() ? triangles : std::clamp<size_t>(m.runEnd(r), begin, triangles);
        if (end == begin) continue;
        use(runMaterial(part, r));
        for (size_t t = begin; t < end; ++t) face(t);
        begin = end;
      }
    }
    if (!m.lines.empty()) use(part.materials.back());
    for (size_t l = 0; l < m.lineCount(); ++l) {
      char* p = out_.room(kMaxLine);
      *p++ = 'l';
      for (int k = 0; k < 2; ++k) *p++ = ' ', p = putIndex(p, vertices_ + m.lines[2 * l + k] + 1);
      *p++ = '\n';
      out_.advance(p);
    }
    vertices_ += n;
    if (texcoords) texcoords_ += n;
    if (normals) normals_ += n;
  }

  void write(const std::string& mtlFileName) {
    out_.append("# fgsg\n");
    if (!mtlFileName.empty()) out_.append("mtllib " + mtlFileName + "\n");
    for (const StartNode& s : scene_.starts) {
      out_.append("o " + token(s.info.name) + "\n");
      for (const GroupNode& g : s.groups) {
        if (scene_.groupBy != GroupBy::None) out_.append("g " + token(g.name) + "\n");
        for (const BakedPart& p : g.baked) part(p);
      }
    }
  }

 private:
  const Scene& scene_;
  io::ByteSink& out_;
  const bool colored_;
  uint64_t vertices_ = 0, texcoords_ = 0, normals_ = 0;  // the v, vt and vn lines so far
  uint32_t current_ = UINT32_MAX;
};

}  // namespace

bool writeObjScene(const Scene& scene, io::ByteSink& out, const std::string& mtlFileName, std::string& error) {
  for (const StartNode& s : scene.starts)
    for (const GroupNode& g : s.groups)
      for (const BakedPart& p : g.baked)
        if (!std::all_of(p.mesh.positions.begin(), p.mesh.positions.end(), [](float x) { return std::isfinite(x); }))
          return error = "a vertex of '" + s.info.name + "' is not finite", false;
  if (!scene.meshes.empty() &&
      std::any_of(scene.starts.begin(), scene.starts.end(), [](const StartNode& s) {
        return std::any_of(s.groups.begin(), s.groups.end(),
                           [](const GroupNode& g) { return !g.instanced.empty() || !g.mirrored.empty(); });
      }))
    return error = "an OBJ has no instances: build its scene with --instancing off", false;
  ObjWriter(scene, out).write(mtlFileName);
  return true;
}

std::string mtlSceneText(const Scene& scene, const std::string& mtlFolder) {
  std::string text = "# fgsg\n";
  const auto number = [](float x) {
    char buf[io::kMaxFloatText + 1];
    return std::string(buf, io::putShortestFloat(buf, io::clamp01(x)));
  };
  for (uint32_t k : usedMaterials(scene)) {
    const Material& m = scene.materials[k];
    const std::array<float, 3> kd = m.vertexColors ? std::array<float, 3>{1, 1, 1} : m.color;
    text += "\nnewmtl " + token(m.name) + "\nKd " + number(kd[0]) + " " + number(kd[1]) + " " + number(kd[2]) +
            "\nKa 0 0 0\nKs 0 0 0\nd " + number(m.opacity) + "\nillum 1\nPr " + number(m.roughness) + "\nPm " +
            number(m.metallic) + "\n";
    if (m.image >= 0) text += "map_Kd " + io::pathFrom(mtlFolder, scene.images[size_t(m.image)]) + "\n";
    // The normal map (the PBR extension's `norm`), on the colour image's coordinates as in glTF.
    if (m.image >= 0 && m.normalImage() >= 0) text += "norm " + io::pathFrom(mtlFolder, scene.images[size_t(m.normalImage())]) + "\n";
    // CityEngine's emissive colour, and its other layers by their usual .mtl statements,
    // on the colour image's coordinates too (the OBJ's one vt set is uv set 0). The dirt
    // and occlusion maps have none (cmd_run warns, R034).
    if (m.emissive != std::array<float, 3>{0, 0, 0})
      text += "Ke " + number(m.emissive[0]) + " " + number(m.emissive[1]) + " " + number(m.emissive[2]) + "\n";
    static const std::pair<uint32_t, const char*> kMtlMaps[] = {
        {Finish::kBumpMap, "map_bump"},    {Finish::kSpecularMap, "map_Ks"},  {Finish::kOpacityMap, "map_d"},
        {Finish::kEmissiveMap, "map_Ke"}, {Finish::kRoughnessMap, "map_Pr"}, {Finish::kMetallicMap, "map_Pm"}};
    for (const auto& [layer, statement] : kMtlMaps)
      if (m.image >= 0 && m.maps[layer] >= 0)
        text += std::string(statement) + " " + io::pathFrom(mtlFolder, scene.images[size_t(m.maps[layer])]) + "\n";
  }
  return text;
}

bool stageObjScene(const Scene& scene, const std::string& path, io::OutputTransaction& outputs, std::string& error) {
  namespace fs = std::filesystem;
  const fs::path mtlPath = fs::path(path).replace_extension(".mtl");
  std::error_code ec;
  const fs::path mtlFolder = fs::absolute(mtlPath, ec).parent_path();
  if (!outputs.stage(mtlPath.string(), mtlSceneText(scene, mtlFolder.string()), error)) return false;
  const std::string mtlFileName = mtlPath.filename().string();
  return outputs.stage(
      path, [&](io::ByteSink& out, std::string& writeError) { return writeObjScene(scene, out, mtlFileName, writeError); },
      error);
}

}  // namespace fgsg::rt::output
