#include "runtime/io/read_lots.h"

#include "runtime/io/geojson_lots.h"
#include "runtime/io/mesh_lots.h"

namespace fgsg::rt {

bool readLots(const std::string& path, std::vector<Lot>& lots, size_t& skipped, std::string& error) {
  skipped = 0;
  if (!isMeshLotsPath(path)) return readGeoJsonLots(path, lots, skipped, error);
  if (!readMeshLots(path, lots, error)) return false;
  for (Lot& lot : lots) lot.isFace = true;
  return true;
}

}  // namespace fgsg::rt
