#include "runtime/io/read_mesh_file.h"

#include "runtime/io/check_ply.h"
#include "runtime/io/file_extension.h"
#include "runtime/io/openmesh_quiet.h"
#include "runtime/io/quoted_text.h"
#include "runtime/io/read_input.h"
#include "runtime/io/read_off.h"

// OpenMesh requires its IO header before the mesh kernel so the readers get registered.
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/IO/importer/ImporterT.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <new>
#include <sstream>

namespace fgsg::rt::io {

namespace {

// A mesh kernel would silently split non-manifold faces off (ImporterT duplicates their
// vertices), so faces are caught raw and the caller sees the file as it is.
struct DoubleTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;  // keep the file's precision where it has more than float
  using Normal = OpenMesh::Vec3d;
};
using RawMesh = OpenMesh::PolyMesh_ArrayKernelT<DoubleTraits>;

class RawImporter : public OpenMesh::IO::ImporterT<RawMesh> {
 public:
  RawImporter(RawMesh& vertices, MeshFileContent& out, Deadline* deadline)
      : ImporterT(vertices), out_(out), deadline_(deadline) {}

  // Asked at every vertex and face: OpenMesh's readers cannot be stopped otherwise.
  using ImporterT::add_vertex;
  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3f& p) override {
    if (deadline_) deadline_->check();  // TimeLimitReached, caught around the read
    return ImporterT::add_vertex(p);
  }
  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3d& p) override {
    if (deadline_) deadline_->check();
    return ImporterT::add_vertex(p);
  }

  // Vertices go to the kernel (readers may attach properties to them); faces stay here.
  OpenMesh::FaceHandle add_face(const VHandles& corners) override {
    if (deadline_) deadline_->check();
    for (auto v : corners) out_.corners.push_back(v.idx());
    out_.polygonStart.push_back(out_.corners.size());
    return OpenMesh::FaceHandle(int(out_.polygonCount() - 1));
  }
  size_t n_faces() const override { return out_.polygonCount(); }
  // The OBJ reader hands over a face's texture coordinates right after the face, one per
  // corner in corner order (the base class would walk the kernel's absent faces).
  void add_face_texcoords(OpenMesh::FaceHandle face, OpenMesh::VertexHandle,
                          const std::vector<OpenMesh::Vec2f>& uv) override {
    // Counted only while every face so far had them, and only as one per corner.
    const size_t f = size_t(face.idx());
    if (f != facesWithUV_ || f + 1 != out_.polygonCount() || uv.size() != out_.cornerCount(f)) return;
    for (const auto& t : uv) faceUV_.push_back({double(t[0]), double(t[1])});
    ++facesWithUV_;
  }
  void add_face_texcoords(OpenMesh::FaceHandle, OpenMesh::VertexHandle,
                          const std::vector<OpenMesh::Vec3f>&) override {}
  void set_status(OpenMesh::FaceHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  // The OBJ reader numbers the images of the `.mtl`'s map_Kd from 1 and gives each face
  // the number of its `usemtl` material's image (0: none).
  void set_face_texindex(OpenMesh::FaceHandle face, int id) override {
    const size_t f = size_t(face.idx());
    if (faceTexture_.size() <= f) faceTexture_.resize(f + 1, 0);
    faceTexture_[f] = id;
  }
  void add_texture_information(int id, std::string name) override {
    if (id <= 0 || id >= 1 << 16) return;
    if (textureNames_.size() <= size_t(id)) textureNames_.resize(size_t(id) + 1);
    textureNames_[size_t(id)] = std::move(name);
  }

  // Each polygon's image as an index into `files` (the images the faces use), -1 for none;
  // empty when no face has an image.
  std::vector<int> polygonTexture(std::vector<std::string>& files) const {
    std::vector<int> out(out_.polygonCount(), -1), index(textureNames_.size(), -1);
    bool any = false;
    for (size_t f = 0; f < out.size() && f < faceTexture_.size(); ++f) {
      const int id = faceTexture_[f];
      if (id <= 0 || size_t(id) >= textureNames_.size() || textureNames_[size_t(id)].empty()) continue;
      if (index[size_t(id)] < 0) index[size_t(id)] = int(files.size()), files.push_back(textureNames_[size_t(id)]);
      out[f] = index[size_t(id)];
      any = true;
    }
    return any ? out : std::vector<int>{};
  }

  // The corners' coordinates when every face had them, in face order; else empty.
  std::vector<std::array<double, 2>> faceUV() const {
    return facesWithUV_ == out_.polygonCount() ? faceUV_ : std::vector<std::array<double, 2>>{};
  }

 private:
  MeshFileContent& out_;
  Deadline* deadline_ = nullptr;
  std::vector<int> faceTexture_;
  std::vector<std::string> textureNames_;
  std::vector<std::array<double, 2>> faceUV_;
  size_t facesWithUV_ = 0;  // the leading faces, all with coordinates
};

// OpenMesh's OBJ reader asserts (aborting the process) on a face corner that names no
// vertex, such as `f /1 /2 /3`: every corner must start with a vertex index.
bool checkObjFaces(const std::string& path, std::string_view bytes, std::string& error, Deadline* deadline) {
  size_t lineNo = 0, pos = 0;
  while (pos < bytes.size()) {
    if (deadline && deadline->expired()) {
      error = readStoppedMessage(path, *deadline);
      return false;
    }
    size_t end = bytes.find('\n', pos);
    if (end == std::string_view::npos) end = bytes.size();
    std::istringstream tokens{std::string(bytes.substr(pos, end - pos))};
    pos = end + 1;
    ++lineNo;
    std::string first, corner;
    if (!(tokens >> first) || first != "f") continue;
    while (tokens >> corner) {
      const size_t sign = corner[0] == '-';
      if (corner.size() <= sign || !std::isdigit(static_cast<unsigned char>(corner[sign]))) {
        error = path + ":" + std::to_string(lineNo) + ": face corner " + quoteText(corner) +
                " names no vertex (a corner is v, v/vt, v//vn or v/vt/vn)";
        return false;
      }
    }
  }
  return true;
}

// OBJ, PLY and STL through OpenMesh (by path: the STL reader tells binary from text by the
// file's size, and welds coincident corners).
bool readWithOpenMesh(const std::string& path, const std::string& ext, MeshFileContent& out,
                      std::string& error, Deadline* deadline) {
  RawMesh vertices;
  RawImporter importer(vertices, out, deadline);
  OpenMesh::IO::Options opt;
  // Texture coordinates: OBJ's per face corner (seams keep both sides), PLY's per vertex.
  if (ext == ".obj") opt += OpenMesh::IO::Options::FaceTexCoord;
  if (ext == ".ply") {
    vertices.request_vertex_texcoords2D();
    opt += OpenMesh::IO::Options::VertexTexCoord;
  }
  bool ok = false;
  {
    QuietOpenMesh quiet;
    try {
      ok = OpenMesh::IO::IOManager().read(path, importer, opt);
    } catch (const TimeLimitReached&) {
      error = readStoppedMessage(path, *deadline);
      return false;
    } catch (const std::exception&) {
      ok = false;  // a count the checks above did not foresee: still the file's fault
    }
  }
  if (!ok) {
    error = path + ": cannot read the file (not a valid " + ext.substr(1) + " file?)";
    return false;
  }
  out.vertices.reserve(vertices.n_vertices());
  for (auto v : vertices.vertices()) {
    const auto& p = vertices.point(v);
    out.vertices.push_back({p[0], p[1], p[2]});
  }
  const long long nv = (long long)out.vertices.size();
  for (size_t f = 0; f < out.polygonCount(); ++f) {
    // OpenMesh hands over such faces when it misreads a line (face colours it does not
    // expect); what follows them cannot be trusted.
    if (out.cornerCount(f) < 3) {
      error = path + ": face " + std::to_string(f) + " has " + std::to_string(out.cornerCount(f)) +
              " corners (the file is malformed, or in a variant of the format OpenMesh cannot "
              "read)";
      return false;
    }
    for (size_t c = out.polygonStart[f]; c < out.polygonStart[f + 1]; ++c)
      if (out.corners[c] < 0 || out.corners[c] >= nv) {
        // OBJ counts vertices from 1: name the index as the file spells it.
        const bool obj = ext == ".obj";
        error = path + ": face " + std::to_string(f) + " refers to vertex " +
                std::to_string(out.corners[c] + (obj ? 1 : 0)) + ", but there are only " +
                std::to_string(nv) + " vertices" + (obj ? " (counting from 1)" : "");
        return false;
      }
  }
  if (ext == ".obj") {
    out.cornerUV = importer.faceUV();
    out.polygonTexture = importer.polygonTexture(out.textureFiles);
  }
  if (ext == ".ply" && opt.vertex_has_texcoord()) {
    out.cornerUV.reserve(out.corners.size());
    for (int v : out.corners) {
      const auto& t = vertices.texcoord2D(OpenMesh::VertexHandle(v));
      out.cornerUV.push_back({double(t[0]), double(t[1])});
    }
  }
  for (size_t c = 0; c < out.cornerUV.size(); ++c)
    if (!std::isfinite(out.cornerUV[c][0]) || !std::isfinite(out.cornerUV[c][1])) {
      // Binary PLY carries them through; a writer must never see one.
      error = path + ": vertex " + std::to_string(out.corners[c]) + " has a texture coordinate "
              "that is not a finite number";
      return false;
    }
  return true;
}

}  // namespace

std::string readStoppedMessage(const std::string& path, const Deadline& deadline) {
  std::ostringstream seconds;
  seconds << deadline.seconds();
  return path + ": stopped by the time limit (" + seconds.str() + " s) while reading the file";
}

bool findNonFiniteText(const std::string& path, const std::string& ext, std::string_view bytes,
                       std::string& error, Deadline* deadline) {
  size_t lineNo = 0, pos = 0;
  bool data = ext != ".ply";  // PLY: only after the header, and only when it is ASCII
  std::string line;
  while (pos < bytes.size()) {
    if (deadline && deadline->expired()) {
      error = readStoppedMessage(path, *deadline);
      return false;
    }
    size_t end = bytes.find('\n', pos);
    if (end == std::string_view::npos) end = bytes.size();
    line.assign(bytes.substr(pos, end - pos));
    pos = end + 1;
    ++lineNo;
    std::istringstream tokens(line);
    std::string first;
    if (!(tokens >> first)) continue;
    if (ext == ".ply" && !data) {
      if (first == "format" && line.find("ascii") == std::string::npos) return true;
      data = first == "end_header";
      continue;
    }
    if (lineNo == 1 && ext == ".stl" && first != "solid") return true;  // binary STL
    const bool obj = ext == ".obj";
    if ((obj && first != "v" && first != "vt") || (ext == ".stl" && first != "vertex") || first[0] == '#')
      continue;
    for (std::string t = first; !t.empty(); t.clear(), tokens >> t) {
      std::string lower = t;
      std::transform(lower.begin(), lower.end(), lower.begin(),
                     [](unsigned char c) { return char(std::tolower(c)); });
      const size_t sign = lower[0] == '-' || lower[0] == '+';
      if (lower.compare(sign, 3, "nan") == 0 || lower.compare(sign, 3, "inf") == 0) {
        error = path + ":" + std::to_string(lineNo) + ": " +
                (obj && first == "vt" ? "texture" : "vertex") + " coordinate " + quoteText(t) +
                " is not a finite number";
        return false;
      }
    }
  }
  return true;
}

bool readMeshFile(const std::string& path, MeshFileContent& out, std::string& error, Deadline* deadline) {
  out = MeshFileContent{};
  std::string bytes;
  if (!readInputFile(path, "a mesh file", bytes, error)) return false;
  if (bytes.empty()) {
    error = path + ": the file is empty (no faces)";
    return false;
  }
  const std::string ext = lowerExtension(path);
  bool ok = false;
  if (ext == ".off") {
    ok = parseOff(path, bytes, out, error, deadline);
  } else {
    ok = (ext != ".ply" || checkPlyStructure(path, bytes, error)) &&
         (ext != ".obj" || checkObjFaces(path, bytes, error, deadline)) &&
         findNonFiniteText(path, ext, bytes, error, deadline);
    bytes = std::string();  // OpenMesh reads the file itself
    ok = ok && readWithOpenMesh(path, ext, out, error, deadline);
  }
  if (!ok) out = MeshFileContent{};
  return ok;
}

}  // namespace fgsg::rt::io
