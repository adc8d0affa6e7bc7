// Building lots from GeoJSON: reading and unit handling (runtime/io/lot_rings.h checks and
// orients the rings).
#include "runtime/io/geojson_lots.h"

#include "runtime/io/read_input.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iomanip>
#include <numbers>
#include <sstream>

namespace fgsg::rt {

namespace {

// Ordered, so that a lot's properties keep the order of the file.
using Json = nlohmann::ordered_json;

constexpr double kEarthRadius = 6371008.8;  // mean radius of the WGS84 ellipsoid, metres

struct GeoJsonError {
  std::string message;
};

[[noreturn]] void fail(const std::string& message) { throw GeoJsonError{message}; }

std::string fmt(double v) {
  std::ostringstream s;
  s << std::setprecision(12) << v;
  return s.str();
}

std::string fmt(const Eigen::Vector2d& p) {
  std::ostringstream s;
  s << std::setprecision(12) << "(" << p.x() << ", " << p.y() << ")";
  return s.str();
}

const char* typeName(const Json& j) {
  switch (j.type()) {
    case Json::value_t::null: return "null";
    case Json::value_t::object: return "an object";
    case Json::value_t::array: return "an array";
    case Json::value_t::string: return "a string";
    case Json::value_t::boolean: return "a boolean";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float: return "a number";
    default: return "binary data";
  }
}

// A polygon read but not yet checked: its lot (properties filled in) and the text that
// places it in messages, "lots.geojson: feature 3 (id "L4"), polygon 1". Its rings hold
// the points kept as the file wrote them (longitude, latitude, 0), `xy` filled by project.
struct Pending {
  Lot lot;
  std::string place;
  std::vector<LotRing> rings;
};

// 1-based line and column of byte `offset` of `text`.
std::string lineColumn(const std::string& text, size_t offset) {
  size_t line = 1, column = 1;
  for (size_t i = 0; i < std::min(offset, text.size()); ++i) {
    if (text[i] == '\n') ++line, column = 1;
    else ++column;
  }
  return std::to_string(line) + ":" + std::to_string(column);
}

Json parseJson(const std::string& text, const std::string& name) {
  try {
    return Json::parse(text);
  } catch (const Json::parse_error& e) {
    std::string what = e.what();
    // nlohmann's text: "[json.exception.parse_error.101] parse error at line 1, column 5: syntax error ..."
    if (const size_t colon = what.find(": "); colon != std::string::npos) what = what.substr(colon + 2);
    // e.byte: 1-based offset of the character where parsing failed.
    fail(name + ":" + lineColumn(text, e.byte > 0 ? size_t(e.byte - 1) : 0) + ": not valid JSON: " + what);
  } catch (const Json::exception& e) {
    // A number too large for a double ("number overflow parsing '1e999'") carries no
    // position; the first place the number's text occurs is where it is.
    std::string what = e.what();
    if (const size_t close = what.find("] "); close != std::string::npos) what = what.substr(close + 2);
    std::string where = name;
    const size_t open = what.find('\''), close = what.rfind('\'');
    if (open != std::string::npos && close > open)
      if (const size_t at = text.find(what.substr(open + 1, close - open - 1)); at != std::string::npos)
        where += ":" + lineColumn(text, at);
    fail(where + ": not valid JSON: " + what);
  }
}

// Whether "4326" stands in `name` as a number of its own, not inside a longer one.
bool namesEpsg4326(const std::string& name) {
  for (size_t at = name.find("4326"); at != std::string::npos; at = name.find("4326", at + 1)) {
    const bool digitBefore = at > 0 && std::isdigit(static_cast<unsigned char>(name[at - 1]));
    const bool digitAfter = at + 4 < name.size() && std::isdigit(static_cast<unsigned char>(name[at + 4]));
    if (!digitBefore && !digitAfter) return true;
  }
  return false;
}

class Reader {
 public:
  Reader(const std::string& name, size_t& skipped) : name_(name), skipped_(skipped) {}

  std::vector<Pending> read(const Json& root) {
    if (!root.is_object()) fail(name_ + ": a GeoJSON file holds an object, got " + typeName(root));
    degrees_ = lonLat(root);
    const std::string type = typeOf(root, name_);
    if (type == "FeatureCollection") {
      const auto features = root.find("features");
      if (features == root.end() || !features->is_array())
        fail(name_ + ": a FeatureCollection needs a \"features\" array" +
             (features == root.end() ? std::string() : std::string(", got ") + typeName(*features)));
      for (size_t i = 0; i < features->size(); ++i) readFeature((*features)[i], i);
    } else if (type == "Feature") {
      readFeature(root, 0);
    } else {
      readGeometry(root, name_ + ": geometry", name_ + ": geometry", Lot());
    }
    if (pending_.empty())
      fail(name_ + ": no Polygon or MultiPolygon to take lots from" +
           (skipped_ == 0   ? std::string()
            : skipped_ == 1 ? std::string(" (1 other geometry skipped)")
                            : " (" + std::to_string(skipped_) + " other geometries skipped)"));
    return std::move(pending_);
  }

  bool degrees() const { return degrees_; }

 private:
  // False when the top-level "crs" names a CRS other than longitude/latitude (see the header).
  bool lonLat(const Json& root) const {
    const auto crs = root.find("crs");
    if (crs == root.end() || crs->is_null()) return true;
    const std::string expected = "expected {\"type\": \"name\", \"properties\": {\"name\": \"...\"}}";
    if (!crs->is_object()) fail(name_ + ": crs: " + expected + ", got " + typeName(*crs));
    const auto properties = crs->find("properties");
    if (properties == crs->end() || !properties->is_object()) fail(name_ + ": crs: " + expected);
    const auto crsName = properties->find("name");
    if (crsName == properties->end() || !crsName->is_string()) fail(name_ + ": crs: " + expected);
    std::string name = crsName->get<std::string>();
    std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return char(std::toupper(c)); });
    return name.find("CRS84") != std::string::npos || namesEpsg4326(name);
  }

  static std::string typeOf(const Json& object, const std::string& where) {
    const auto type = object.find("type");
    if (type == object.end()) fail(where + ": no \"type\" member");
    if (!type->is_string()) fail(where + ": \"type\" is a string, got " + typeName(*type));
    return type->get<std::string>();
  }

  void readFeature(const Json& feature, size_t index) {
    std::string place = name_ + ": feature " + std::to_string(index);
    if (!feature.is_object()) fail(place + ": a feature is an object, got " + typeName(feature));
    if (const std::string type = typeOf(feature, place); type != "Feature")
      fail(place + ": \"type\" is \"Feature\", got \"" + type + "\"");
    Lot lot;
    lot.feature = index;
    if (const auto id = feature.find("id"); id != feature.end()) {
      if (id->is_string()) lot.id = id->get<std::string>();
      else if (id->is_number()) lot.id = id->dump();
      else if (!id->is_null()) fail(place + ": \"id\" is a string or a number, got " + typeName(*id));
    }
    if (!lot.id.empty()) place += " (id \"" + lot.id + "\")";
    if (const auto properties = feature.find("properties"); properties != feature.end()) {
      if (properties->is_object()) {
        for (auto it = properties->begin(); it != properties->end(); ++it) {
          if (it->is_boolean()) lot.numbers.emplace_back(it.key(), it->get<bool>() ? 1.0 : 0.0);
          else if (it->is_number()) lot.numbers.emplace_back(it.key(), it->get<double>());
          else if (it->is_string()) lot.strings.emplace_back(it.key(), it->get<std::string>());
          if (it.key() == "streetWidth") lot.streetWidth = readStreetWidths(*it, place);
        }
      } else if (!properties->is_null()) {
        fail(place + ": \"properties\" is an object or null, got " + typeName(*properties));
      }
    }
    const auto geometry = feature.find("geometry");
    if (geometry == feature.end()) fail(place + ": no \"geometry\" member (null for none)");
    if (geometry->is_null()) {
      ++skipped_;
      return;
    }
    readGeometry(*geometry, place, place + ": geometry", lot);
  }

  // `place` names the lot in messages ("lots.geojson: feature 3 (id "L4")"), `where` the
  // geometry itself (the same with ": geometry" inside a feature).
  void readGeometry(const Json& geometry, const std::string& place, const std::string& where, const Lot& lot) {
    if (!geometry.is_object()) fail(where + ": a geometry is an object, got " + typeName(geometry));
    const std::string type = typeOf(geometry, where);
    if (type == "Point" || type == "MultiPoint" || type == "LineString" || type == "MultiLineString" ||
        type == "GeometryCollection") {
      ++skipped_;
      return;
    }
    if (type != "Polygon" && type != "MultiPolygon") fail(where + ": \"" + type + "\" is not a GeoJSON geometry type");
    const auto coordinates = geometry.find("coordinates");
    if (coordinates == geometry.end()) fail(where + ": a " + type + " needs \"coordinates\"");
    if (!coordinates->is_array()) fail(where + ": \"coordinates\" is an array, got " + typeName(*coordinates));
    if (type == "Polygon") {
      readPolygon(*coordinates, place, lot);
      return;
    }
    if (coordinates->empty()) fail(where + ": a MultiPolygon without polygons");
    if (!lot.streetWidth.empty() && coordinates->size() > 1)
      fail(place + ": property \"streetWidth\" gives the edges of one polygon; this MultiPolygon has " +
           std::to_string(coordinates->size()) + " (give each polygon a feature of its own)");
    for (size_t k = 0; k < coordinates->size(); ++k) {
      Lot part = lot;
      part.part = k;
      readPolygon((*coordinates)[k], place + ", polygon " + std::to_string(k), part);
    }
  }

  void readPolygon(const Json& polygon, const std::string& place, Lot lot) {
    if (!polygon.is_array()) fail(place + ": a polygon is an array of rings, got " + typeName(polygon));
    if (polygon.empty()) fail(place + ": an empty polygon (no rings)");
    Pending p{std::move(lot), place, {}};
    size_t points = 0;
    for (size_t r = 0; r < polygon.size(); ++r) {
      const std::string ringPlace = place + ", " + lotRingName(r);
      const Json& ring = polygon[r];
      if (!ring.is_array()) fail(ringPlace + ": a ring is an array of positions, got " + typeName(ring));
      LotRing out;
      for (size_t i = 0; i < ring.size(); ++i) {
        const Eigen::Vector2d position = readPosition(ring[i], ringPlace + ", point " + std::to_string(i));
        const Eigen::Vector3d q(position.x(), position.y(), 0);
        if (!out.file.empty() && q == out.file.back()) continue;
        out.file.push_back(q);
        out.index.push_back(i);
      }
      size_t closing = ring.size();  // the position that closes the ring (none: one past the last)
      if (out.file.size() > 1 && out.file.front() == out.file.back()) {
        closing = out.index.back();
        out.file.pop_back();
        out.index.pop_back();
      }
      if (r == 0 && !p.lot.streetWidth.empty()) p.lot.streetWidth = keptStreetWidths(p.lot.streetWidth, ring, out, closing, place);
      points += out.file.size();
      if (points > kMaxLotPoints)
        fail(place + ": more than " + std::to_string(kMaxLotPoints) + " points; a lot has fewer");
      checkDistinct(out, ringPlace);
      p.rings.push_back(std::move(out));
    }
    pending_.push_back(std::move(p));
  }

  // "streetWidth": an array of numbers, none below 0 (JSON numbers are finite).
  static std::vector<double> readStreetWidths(const Json& value, const std::string& place) {
    const std::string what = place + ": property \"streetWidth\"";
    if (!value.is_array())
      fail(what + " is an array of numbers, one per edge of the outer ring, got " + typeName(value));
    std::vector<double> widths;
    for (size_t i = 0; i < value.size(); ++i) {
      if (!value[i].is_number())
        fail(what + ", value " + std::to_string(i) + ": a street width is a number, got " + typeName(value[i]));
      const double w = value[i].get<double>();
      if (!(w >= 0)) fail(what + ", value " + std::to_string(i) + ": " + fmt(w) + " is below 0 (0: no street)");
      widths.push_back(w);
    }
    return widths;
  }

  // The widths as written (one per edge from position i to i + 1 of the outer ring, the
  // last edge closing it) as the kept points' edges: an edge a dropped duplicate point
  // made has no length, and its width goes with it. `closing`: the position that closed
  // the ring (ring.size() when it was left open).
  static std::vector<double> keptStreetWidths(const std::vector<double>& written, const Json& ring,
                                              const LotRing& kept, size_t closing, const std::string& place) {
    const size_t edges = ring.size() > 1 && ring.front() == ring.back() ? ring.size() - 1 : ring.size();
    if (written.size() != edges)
      fail(place + ": property \"streetWidth\" has " + std::to_string(written.size()) + " values; the outer ring has " +
           std::to_string(edges) + " edges (one value per edge, in the ring's order)");
    std::vector<double> widths(kept.index.size());
    for (size_t k = 0; k + 1 < kept.index.size(); ++k) widths[k] = written[kept.index[k + 1] - 1];
    if (!widths.empty()) widths.back() = written[std::min(closing, ring.size()) - 1];
    return widths;
  }

  // JSON numbers are finite (the parser refuses overflow), so only types and ranges are checked.
  Eigen::Vector2d readPosition(const Json& position, const std::string& where) const {
    if (!position.is_array() || position.size() < 2)
      fail(where + ": a position is an array of 2 or more numbers, got " +
           (position.is_array() ? "an array of " + std::to_string(position.size()) : std::string(typeName(position))));
    for (const Json& v : position)
      if (!v.is_number()) fail(where + ": a position is an array of numbers, it holds " + typeName(v));
    const Eigen::Vector2d q(position[0].get<double>(), position[1].get<double>());
    if (degrees_ && (std::abs(q.x()) > 180 || std::abs(q.y()) > 90))
      fail(where + ": " + fmt(q) +
           " is not longitude/latitude in degrees; a file in metres says so with a \"crs\" such as "
           "{\"type\": \"name\", \"properties\": {\"name\": \"urn:fgsg:local-metres\"}}");
    if (!degrees_ && (std::abs(q.x()) > kMaxLotMetres || std::abs(q.y()) > kMaxLotMetres))
      fail(where + ": " + fmt(q) + " is more than " + fmt(kMaxLotMetres) + " m from the origin");
    return q;
  }

  // Here rather than in the ring checks, so that such a ring is refused in file order.
  static void checkDistinct(const LotRing& ring, const std::string& where) {
    std::vector<Eigen::Vector2d> distinct;
    for (const Eigen::Vector3d& q : ring.file) distinct.push_back(q.head<2>());
    const auto less = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
      return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
    };
    std::sort(distinct.begin(), distinct.end(), less);
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    if (distinct.size() >= 3) return;
    std::string listed;
    for (const Eigen::Vector2d& q : distinct) listed += (listed.empty() ? ": " : " and ") + fmt(q);
    fail(where + ": " + std::to_string(distinct.size()) + " distinct points" + listed +
         "; a ring needs at least 3");
  }

  const std::string& name_;
  size_t& skipped_;
  bool degrees_ = true;
  std::vector<Pending> pending_;
};

// Equirectangular projection about the centre of the bounding box of every lot (see the header).
void project(std::vector<Pending>& pending, bool degrees) {
  Eigen::Vector2d lo(INFINITY, INFINITY), hi(-INFINITY, -INFINITY);
  for (const Pending& p : pending)
    for (const LotRing& ring : p.rings)
      for (const Eigen::Vector3d& q : ring.file) lo = lo.cwiseMin(q.head<2>()), hi = hi.cwiseMax(q.head<2>());
  const Eigen::Vector2d centre = 0.5 * (lo + hi);
  const double toMetres = kEarthRadius * std::numbers::pi / 180;
  const Eigen::Vector2d scale(toMetres * std::cos(centre.y() * std::numbers::pi / 180), toMetres);
  for (Pending& p : pending)
    for (LotRing& ring : p.rings) {
      ring.xy.reserve(ring.file.size());
      for (const Eigen::Vector3d& q : ring.file) {
        const Eigen::Vector2d file = q.head<2>();
        ring.xy.push_back(degrees ? Eigen::Vector2d((file - centre).cwiseProduct(scale)) : file);
      }
    }
}

Lot finish(Pending& p) {
  LotMessages messages;  // the defaults are GeoJSON's words
  messages.place = p.place;
  Lot lot = std::move(p.lot);
  // checkAndOrientRings turns a clockwise outer ring about its first point: its edges, and
  // so their street widths, then run the other way round.
  double twiceArea = 0;
  const std::vector<Eigen::Vector2d>& outer = p.rings.front().xy;
  for (size_t i = 0; i < outer.size(); ++i) {
    const Eigen::Vector2d& a = outer[i];
    const Eigen::Vector2d& b = outer[(i + 1) % outer.size()];
    twiceArea += a.x() * b.y() - a.y() * b.x();
  }
  std::string error;
  if (!checkAndOrientRings(p.rings, messages, lot, error)) fail(error);
  if (twiceArea < 0) std::reverse(lot.streetWidth.begin(), lot.streetWidth.end());
  return lot;
}

}  // namespace

bool parseGeoJsonLots(const std::string& text, const std::string& nameForMessages, std::vector<Lot>& lots,
                      size_t& skipped, std::string& error) {
  lots.clear();
  skipped = 0;
  try {
    const Json root = parseJson(text, nameForMessages);
    Reader reader(nameForMessages, skipped);
    std::vector<Pending> pending = reader.read(root);
    project(pending, reader.degrees());
    std::vector<Lot> out;
    out.reserve(pending.size());
    for (Pending& p : pending) out.push_back(finish(p));
    lots = std::move(out);
    return true;
  } catch (const GeoJsonError& e) {
    error = e.message;
  } catch (const std::bad_alloc&) {
    error = nameForMessages + ": out of memory reading the lots";
  }
  skipped = 0;
  return false;
}

bool readGeoJsonLots(const std::string& path, std::vector<Lot>& lots, size_t& skipped, std::string& error) {
  lots.clear();
  skipped = 0;
  std::string text;
  if (!io::readInputFile(path, "a GeoJSON file", text, error)) return false;
  return parseGeoJsonLots(text, path, lots, skipped, error);
}

}  // namespace fgsg::rt
