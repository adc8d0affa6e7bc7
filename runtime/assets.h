// Assets that I() places: built-in primitives (cube cylinder sphere torus ico quad disc,
// the marching terminals bark leaf, and none) and mesh files (OBJ, PLY, OFF, STL via OpenMesh).
// Every asset is normalised into the unit cube [0,1]^3 (its bounding box stretched to fit;
// flat axes stay flat) so an instance fills its scope box. Texture coordinates are kept
// as they are: bark and leaf have them, and files that give them (OBJ vt, PLY u v).
#pragma once

#include "runtime/instances.h"
#include "runtime/mesh.h"

#include <array>
#include <string>
#include <unordered_map>
#include <vector>

namespace fgsg::rt {

// The names of the built-in primitives, in a stable order.
const std::vector<std::string>& builtinPrimitiveNames();

// Builds a built-in primitive in the unit cube ("none": an empty mesh). Cylinder: axis along Y. Torus, disc
// and quad: lying in the XY plane (normal +Z). Bark: an open tube along X (24 sides x 9
// rings, u around, v along X). Leaf: the XY unit square facing +Z (u = x, v = y). Only
// bark and leaf have texture coordinates. Returns false for an unknown name.
bool makeBuiltinPrimitive(const std::string& name, Mesh& out);

class AssetLibrary {
 public:
  // Directories searched, in order, for asset files (the grammar's directory first).
  void addSearchDir(const std::string& dir) { searchDirs_.push_back(dir); }

  // Returns the index of the asset named as in the grammar, loading it on first use.
  // A name is a built-in primitive, or a file found in the search directories; an
  // unknown name or an unreadable file gives -1 and a message in `error`.
  int resolve(const std::string& name, std::string& error);
  const Mesh& mesh(int index) const { return meshes_[index]; }
  // The bounding box (lo x y z, hi x y z) an asset file gave before it was normalised (a
  // built-in's, and generated geometry's: the unit box): CityEngine's insert modes keep it.
  std::array<double, 6> sourceBox(int index) const {
    return size_t(index) < sourceBoxes_.size() ? sourceBoxes_[size_t(index)] : std::array<double, 6>{0, 0, 0, 1, 1, 1};
  }

  // Registers geometry the derivation built itself (a swept line) under `name`: it is
  // normalised into the unit box like every asset, and `unitBoxToWorld` (column-major
  // 4x4) receives the transform that puts it back where it was built.
  int addGenerated(const std::string& name, const Mesh& world, std::array<double, 16>& unitBoxToWorld);

 private:
  std::vector<std::string> searchDirs_;
  std::vector<Mesh> meshes_;
  std::vector<std::array<double, 6>> sourceBoxes_;  // per mesh, see sourceBox
  std::unordered_map<std::string, int> byName_;
};

// Registers geometry the derivation built (the surface, a swept line) in `library` under
// `name` and places it once in `out`, where it was built, for `symbol` in `color`.
void placeGenerated(AssetLibrary& library, InstanceList& out, const std::string& name,
                    const Mesh& world, uint32_t symbol, const std::array<float, 3>& color);

}  // namespace fgsg::rt
