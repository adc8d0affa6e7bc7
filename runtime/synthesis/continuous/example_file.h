// Which example files continuous synthesis reads: meshes (.obj .ply .off .stl .glb
// .gltf, any case).
// Header-only: the checker (frontend), the loader (backend) and fgsg synth all ask.
#pragma once

#include <cctype>
#include <string>

namespace fgsg::rt::synthesis::continuous {

inline bool isPolygonalExampleFile(const std::string& path) {
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos) return false;
  std::string ext = path.substr(dot);
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".obj" || ext == ".ply" || ext == ".off" || ext == ".stl" || ext == ".glb" || ext == ".gltf";
}

}  // namespace fgsg::rt::synthesis::continuous
