// A building lot: a footprint polygon on the ground with its own properties, as a GIS
// file gives it (runtime/io/geojson_lots.h). `fgsg run --lots` derives the axiom once on
// each (DeriveOptions::lots).
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace fgsg::rt {

// Corners in metres, x east and y north.
struct Lot {
  std::vector<Eigen::Vector2d> outer;               // counter-clockwise, not closed (no repeated first point)
  std::vector<std::vector<Eigen::Vector2d>> holes;  // clockwise, not closed
  std::string id;                                   // the feature's "id" (a number as its JSON text), else ""
  size_t feature = 0;                               // index of the feature in the collection (0-based)
  size_t part = 0;                                  // index of the polygon within a MultiPolygon (0 for a Polygon)
  bool isFace = false;                              // a mesh face (runtime/io/mesh_lots.h): `feature` is its index
  // The feature's properties in file order: numbers, and booleans as 0/1, in `numbers`;
  // strings in `strings`; null, arrays and objects are left out.
  std::vector<std::pair<std::string, double>> numbers;
  std::vector<std::pair<std::string, std::string>> strings;
  // CityEngine's "streetWidth" property (an array, one number per edge of the outer ring
  // as the file wrote it): each edge of `outer`'s street width, edge i running from
  // outer[i] to outer[i + 1]; 0 where no street runs along it. Empty: the file gave none.
  std::vector<double> streetWidth;
};

// How messages name a lot: as the GeoJSON reader names features, "lots.geojson:
// feature 6 (id "L0007")", with the polygon of a MultiPolygon when it is not the first;
// a mesh's face as its reader does, "lots.obj: face 6".
inline std::string lotName(const std::string& file, const Lot& lot) {
  std::string name = file + (lot.isFace ? ": face " : ": feature ") + std::to_string(lot.feature);
  if (!lot.id.empty()) name += " (id \"" + lot.id + "\")";
  if (lot.part > 0) name += ", polygon " + std::to_string(lot.part);
  return name;
}

}  // namespace fgsg::rt
