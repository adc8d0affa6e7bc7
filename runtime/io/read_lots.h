// `--lots FILE`: building lots from a GeoJSON file or from the polygon faces of a mesh
// (OBJ, PLY, OFF), chosen by the file's extension.
#pragma once

#include "runtime/lot.h"

#include <cstddef>
#include <string>
#include <vector>

namespace fgsg::rt {

// Reads the lots of `path`: a mesh's faces (runtime/io/mesh_lots.h) for .obj, .ply and
// .off, GeoJSON (runtime/io/geojson_lots.h) otherwise. `skipped` counts GeoJSON geometries
// that are not polygons (0 for a mesh). False with `error` set, as each reader says.
bool readLots(const std::string& path, std::vector<Lot>& lots, size_t& skipped, std::string& error);

}  // namespace fgsg::rt
