// Building lots from GeoJSON: reading, unit handling, ring validation and orientation.
#include "runtime/io/geojson_lots.h"

#include "runtime/io/read_input.h"
#include "runtime/planar.h"

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <tuple>

namespace fgsg::rt {

namespace {

// Ordered, so that a lot's properties keep the order of the file.
using Json = nlohmann::ordered_json;

constexpr double kPi = 3.14159265358979323846;
constexpr double kEarthRadius = 6371008.8;  // mean radius of the WGS84 ellipsoid, metres
// Coordinates in metres beyond this are no place on Earth, and would overflow the area sums.
constexpr double kMaxMetres = 1e9;
// Points closer than this (relative to the lot's coordinates) count as touching: 1 micron
// on a kilometre, far above rounding and far below any real gap between two walls.
constexpr double kRelativeTolerance = 1e-9;

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

// One ring as read: the points kept, where they stood in the file's array, and the same
// points in metres (equal to `file` when the file is in metres).
struct Ring {
  std::vector<Eigen::Vector2d> file;
  std::vector<size_t> index;
  std::vector<Eigen::Vector2d> xy;
};

// A polygon read but not yet checked: its lot (properties filled in) and the text that
// places it in messages, "lots.geojson: feature 3 (id "L4"), polygon 1".
struct Pending {
  Lot lot;
  std::string place;
  std::vector<Ring> rings;
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

std::string ringName(size_t r) {
  return "ring " + std::to_string(r) + (r == 0 ? " (outer)" : " (hole " + std::to_string(r) + ")");
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
      const std::string ringPlace = place + ", " + ringName(r);
      const Json& ring = polygon[r];
      if (!ring.is_array()) fail(ringPlace + ": a ring is an array of positions, got " + typeName(ring));
      Ring out;
      for (size_t i = 0; i < ring.size(); ++i) {
        const Eigen::Vector2d q = readPosition(ring[i], ringPlace + ", point " + std::to_string(i));
        if (!out.file.empty() && q == out.file.back()) continue;
        out.file.push_back(q);
        out.index.push_back(i);
      }
      if (out.file.size() > 1 && out.file.front() == out.file.back()) {
        out.file.pop_back();
        out.index.pop_back();
      }
      points += out.file.size();
      if (points > kMaxLotPoints)
        fail(place + ": more than " + std::to_string(kMaxLotPoints) + " points; a lot has fewer");
      checkDistinct(out, ringPlace);
      p.rings.push_back(std::move(out));
    }
    pending_.push_back(std::move(p));
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
    if (!degrees_ && (std::abs(q.x()) > kMaxMetres || std::abs(q.y()) > kMaxMetres))
      fail(where + ": " + fmt(q) + " is more than " + fmt(kMaxMetres) + " m from the origin");
    return q;
  }

  static void checkDistinct(const Ring& ring, const std::string& where) {
    std::vector<Eigen::Vector2d> distinct = ring.file;
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
    for (const Ring& ring : p.rings)
      for (const Eigen::Vector2d& q : ring.file) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
  const Eigen::Vector2d centre = 0.5 * (lo + hi);
  const double toMetres = kEarthRadius * kPi / 180;
  const Eigen::Vector2d scale(toMetres * std::cos(centre.y() * kPi / 180), toMetres);
  for (Pending& p : pending)
    for (Ring& ring : p.rings) {
      ring.xy.reserve(ring.file.size());
      for (const Eigen::Vector2d& q : ring.file)
        ring.xy.push_back(degrees ? Eigen::Vector2d((q - centre).cwiseProduct(scale)) : q);
    }
}

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

double pointSegmentDistance(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

// Whether the open segments ab and cd cross at a single point inside both.
bool crossProperly(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                   const Eigen::Vector2d& d) {
  const double abc = cross(b - a, c - a), abd = cross(b - a, d - a);
  const double cda = cross(d - c, a - c), cdb = cross(d - c, b - c);
  return ((abc > 0 && abd < 0) || (abc < 0 && abd > 0)) && ((cda > 0 && cdb < 0) || (cda < 0 && cdb > 0));
}

double segmentDistance(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                       const Eigen::Vector2d& d) {
  if (crossProperly(a, b, c, d)) return 0;
  return std::min({pointSegmentDistance(a, c, d), pointSegmentDistance(b, c, d), pointSegmentDistance(c, a, b),
                   pointSegmentDistance(d, a, b)});
}

// Crossing-number test; `p` is known not to lie on the ring.
bool inside(const Eigen::Vector2d& p, const std::vector<Eigen::Vector2d>& ring) {
  bool in = false;
  for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const Eigen::Vector2d& a = ring[i];
    const Eigen::Vector2d& b = ring[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()))
      in = !in;
  }
  return in;
}

std::string point(const Ring& ring, size_t i) {
  return "point " + std::to_string(ring.index[i]) + " " + fmt(ring.file[i]);
}

std::string edge(const Ring& ring, size_t i) {
  return "the edge from " + point(ring, i) + " to " + point(ring, (i + 1) % ring.file.size());
}

struct Edge {
  size_t ring, i;
  double minX, maxX, minY, maxY;
};

// No two edges of the lot's rings touch or cross, except neighbours in a ring at their
// shared point. Edges sorted by their left end are compared only with those whose x
// ranges overlap theirs, which keeps ordinary lots near n log n.
void checkEdges(const Pending& p, double tolerance) {
  std::vector<Edge> edges;
  for (size_t r = 0; r < p.rings.size(); ++r) {
    const std::vector<Eigen::Vector2d>& xy = p.rings[r].xy;
    for (size_t i = 0; i < xy.size(); ++i) {
      const Eigen::Vector2d& a = xy[i];
      const Eigen::Vector2d& b = xy[(i + 1) % xy.size()];
      edges.push_back({r, i, std::min(a.x(), b.x()), std::max(a.x(), b.x()), std::min(a.y(), b.y()),
                       std::max(a.y(), b.y())});
    }
  }
  // Ties broken by ring and index, so that which of several faults is reported is fixed.
  std::sort(edges.begin(), edges.end(), [](const Edge& a, const Edge& b) {
    return std::tie(a.minX, a.ring, a.i) < std::tie(b.minX, b.ring, b.i);
  });
  for (size_t u = 0; u < edges.size(); ++u)
    for (size_t v = u + 1; v < edges.size() && edges[v].minX <= edges[u].maxX + tolerance; ++v) {
      // The edge of the later ring (or the later edge of one ring) first in messages.
      const bool swap = std::tie(edges[u].ring, edges[u].i) < std::tie(edges[v].ring, edges[v].i);
      const Edge& e = swap ? edges[v] : edges[u];
      const Edge& f = swap ? edges[u] : edges[v];
      if (e.minY > f.maxY + tolerance || f.minY > e.maxY + tolerance) continue;
      const Ring& re = p.rings[e.ring];
      const Ring& rf = p.rings[f.ring];
      const size_t n = re.xy.size();
      const Eigen::Vector2d& a = re.xy[e.i];
      const Eigen::Vector2d& b = re.xy[(e.i + 1) % n];
      const Eigen::Vector2d& c = rf.xy[f.i];
      const Eigen::Vector2d& d = rf.xy[(f.i + 1) % rf.xy.size()];
      // Neighbours meet at their shared point. Two that fold back onto each other leave a
      // point on an edge that is no neighbour (or, in a triangle, zero area), found there.
      if (e.ring == f.ring && (e.i == (f.i + 1) % n || f.i == (e.i + 1) % n)) continue;
      if (segmentDistance(a, b, c, d) > tolerance) continue;
      const std::string where = p.place + ", " + ringName(e.ring) + ": ";
      const std::string verb = crossProperly(a, b, c, d) ? " crosses " : " touches ";
      if (e.ring == f.ring) fail(where + edge(re, e.i) + verb + edge(rf, f.i));
      fail(where + edge(re, e.i) + verb + ringName(f.ring) + " at " + edge(rf, f.i));
    }
}

// The rings are sound on their own and no two touch: each hole lies wholly inside the
// outer ring or wholly outside, and likewise for two holes, as one point of it tells.
void checkHoles(const Pending& p) {
  const std::vector<Ring>& rings = p.rings;
  std::vector<Eigen::AlignedBox2d> boxes;
  for (const Ring& ring : rings) {
    Eigen::AlignedBox2d box;
    for (const Eigen::Vector2d& q : ring.xy) box.extend(q);
    boxes.push_back(box);
  }
  for (size_t h = 1; h < rings.size(); ++h)
    if (!inside(rings[h].xy[0], rings[0].xy))
      fail(p.place + ", " + ringName(h) + ": lies outside the outer ring (its " + point(rings[h], 0) + ")");
  for (size_t h = 1; h < rings.size(); ++h)
    for (size_t k = 1; k < rings.size(); ++k)
      if (h != k && boxes[k].contains(boxes[h]) && inside(rings[h].xy[0], rings[k].xy))
        fail(p.place + ", " + ringName(h) + ": lies inside " + ringName(k) + " (its " +
             point(rings[h], 0) + "); holes may not overlap");
}

Lot finish(Pending& p) {
  Eigen::Vector2d lo(INFINITY, INFINITY), hi(-INFINITY, -INFINITY);
  double largest = 0;
  for (const Ring& ring : p.rings)
    for (const Eigen::Vector2d& q : ring.xy) {
      lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
      largest = std::max(largest, q.cwiseAbs().maxCoeff());
    }
  const double tolerance = kRelativeTolerance * std::max(largest, (hi - lo).maxCoeff());
  checkEdges(p, tolerance);
  // Left for a ring without touching edges to be degenerate: a triangle on one line (a
  // figure eight has zero area too, but its edges cross, as found above).
  for (size_t r = 0; r < p.rings.size(); ++r) {
    const Ring& ring = p.rings[r];
    Eigen::AlignedBox2d box;
    for (const Eigen::Vector2d& q : ring.xy) box.extend(q);
    if (std::abs(twiceRingArea(ring.xy)) <= 2 * tolerance * box.sizes().maxCoeff())
      fail(p.place + ", " + ringName(r) + ": zero area (all its points on one line, from " + point(ring, 0) +
           ")");
  }
  checkHoles(p);
  Lot lot = std::move(p.lot);
  for (size_t r = 0; r < p.rings.size(); ++r) {
    std::vector<Eigen::Vector2d>& xy = p.rings[r].xy;
    // Outer rings counter-clockwise, holes clockwise, whatever the file had; the first
    // point stays first.
    if ((twiceRingArea(xy) > 0) != (r == 0)) std::reverse(xy.begin() + 1, xy.end());
    if (r == 0) lot.outer = std::move(xy);
    else lot.holes.push_back(std::move(xy));
  }
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
