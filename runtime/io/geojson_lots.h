// Building lots from GeoJSON: every Polygon and MultiPolygon of a FeatureCollection, a
// single Feature or a bare geometry becomes a lot (one per polygon of a MultiPolygon) with
// its rings validated and oriented and its feature's properties alongside.
//
// Units. RFC 7946 coordinates are longitude/latitude in degrees (WGS84). When the file's
// top-level "crs" member names a CRS that is not longitude/latitude (its properties.name
// contains neither "CRS84" nor "4326", e.g. "urn:fgsg:local-metres" or "EPSG:25832"), the
// coordinates are taken as metres, x east and y north, and used as they are. Otherwise
// (no "crs", a null one, or a lon/lat one) they must be degrees and are projected to local
// metres with an equirectangular projection about the centre (lon0, lat0) of the bounding
// box of all lots read:
//     x = R cos(lat0) (lon - lon0),  y = R (lat - lat0),  angles in radians, R = 6371008.8 m,
// so the lots lie around (0, 0). Good to well under 1 % across a few kilometres; a
// collection that straddles the antimeridian (longitude +-180) is not supported.
//
// Validation: anything that is not a sound lot is an error naming the file, the feature
// (index and id), the polygon of a MultiPolygon, the ring (0 the outer ring, 1... the
// holes, as in the file) and the offending coordinates as written in the file. Rings may
// be closed (first point repeated) or open; consecutive duplicate points are dropped. A
// ring needs 3 distinct points and a non-zero area; no two edges of a lot may touch or
// cross except neighbours at their shared point (so holes lie strictly inside the outer
// ring, and strictly outside each other).
#pragma once

#include "runtime/io/lot_rings.h"  // kMaxLotPoints
#include "runtime/lot.h"

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace fgsg::rt {

// Reads the lots of the GeoJSON file at `path` (see above). `skipped` counts the
// geometries of other types (Point, LineString, GeometryCollection, null, ...) passed
// over. False with `error` set and `lots` empty when the file cannot be read, is not
// valid GeoJSON, holds an invalid polygon, or holds no Polygon or MultiPolygon at all.
bool readGeoJsonLots(const std::string& path, std::vector<Lot>& lots, size_t& skipped, std::string& error);

// readGeoJsonLots on the text of a file; `nameForMessages` starts each error message.
bool parseGeoJsonLots(const std::string& text, const std::string& nameForMessages, std::vector<Lot>& lots,
                      size_t& skipped, std::string& error);

}  // namespace fgsg::rt
