// Building lots from GeoJSON: rings oriented and kept exactly, MultiPolygons split, properties
// sorted by type, degrees projected to metres, and every invalid input refused with a
// message that names the feature, the ring and the coordinates.
#include "runtime/io/geojson_lots.h"

#include "runtime/planar.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace fgsg::rt;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Positive counter-clockwise.
double signedArea(const std::vector<Eigen::Vector2d>& ring) { return twiceRingArea(ring) / 2; }

std::vector<Lot> lotsOf(const std::string& text, size_t& skipped) {
  std::vector<Lot> lots;
  std::string error;
  const bool ok = parseGeoJsonLots(text, "lots.geojson", lots, skipped, error);
  INFO(error);
  CHECK(ok);
  return lots;
}

std::vector<Lot> lotsOf(const std::string& text) {
  size_t skipped = 0;
  std::vector<Lot> lots = lotsOf(text, skipped);
  CHECK(skipped == 0);
  return lots;
}

std::string refusal(const std::string& text) {
  std::vector<Lot> lots(1);
  size_t skipped = 9;
  std::string error;
  CHECK_FALSE(parseGeoJsonLots(text, "lots.geojson", lots, skipped, error));
  CHECK(lots.empty());
  CHECK(skipped == 0);
  return error;
}

// One feature with id "a" holding a Polygon with `coordinates`, in local metres.
std::string polygonInMetres(const std::string& coordinates) {
  return R"({"type": "FeatureCollection",
             "crs": {"type": "name", "properties": {"name": "urn:fgsg:local-metres"}},
             "features": [{"type": "Feature", "id": "a", "properties": {},
                           "geometry": {"type": "Polygon", "coordinates": )" +
         coordinates + "}}]}";
}

}  // namespace

TEST_CASE("a Polygon with a hole comes out with the outer ring counter-clockwise and the hole clockwise",
          "[geojson]") {
  // Outer ring clockwise and closed, hole counter-clockwise and open: both turned.
  const std::vector<Lot> lots = lotsOf(polygonInMetres(R"([
      [[0, 0], [0, 10], [10, 10], [10, 0], [0, 0]],
      [[2, 2], [4, 2], [4, 4], [2, 4]]])"));
  REQUIRE(lots.size() == 1);
  const Lot& lot = lots[0];
  CHECK(lot.id == "a");
  CHECK(lot.feature == 0);
  CHECK(lot.part == 0);
  REQUIRE(lot.outer.size() == 4);
  CHECK(signedArea(lot.outer) == 100.0);
  REQUIRE(lot.holes.size() == 1);
  REQUIRE(lot.holes[0].size() == 4);
  CHECK(signedArea(lot.holes[0]) == -4.0);
  // The points are the file's, only their order reversed.
  CHECK(lot.outer[0] == Eigen::Vector2d(0, 0));
  CHECK(lot.outer[1] == Eigen::Vector2d(10, 0));
  CHECK(lot.outer[3] == Eigen::Vector2d(0, 10));
  CHECK(lot.holes[0][1] == Eigen::Vector2d(2, 4));
}

TEST_CASE("rings already counter-clockwise keep their order and repeated points are dropped", "[geojson]") {
  const std::vector<Lot> lots = lotsOf(polygonInMetres(R"([
      [[0, 0], [6, 0], [6, 0], [6, 3], [0, 3], [0, 3], [0, 0], [0, 0]]])"));
  REQUIRE(lots.size() == 1);
  const std::vector<Eigen::Vector2d> expected{{0, 0}, {6, 0}, {6, 3}, {0, 3}};
  CHECK(lots[0].outer == expected);
  CHECK(signedArea(lots[0].outer) == 18.0);
  CHECK(lots[0].holes.empty());
}

TEST_CASE("a MultiPolygon gives one lot per polygon", "[geojson]") {
  size_t skipped = 0;
  const std::vector<Lot> lots = lotsOf(R"({
    "type": "FeatureCollection",
    "crs": {"type": "name", "properties": {"name": "EPSG:25832"}},
    "features": [
      {"type": "Feature", "properties": null, "geometry": {"type": "Point", "coordinates": [1, 2]}},
      {"type": "Feature", "id": 17, "properties": {"height": 9},
       "geometry": {"type": "MultiPolygon", "coordinates": [
         [[[0, 0], [4, 0], [4, 5], [0, 5]]],
         [[[10, 0], [13, 0], [13, 2], [10, 2], [10, 0]], [[11, 0.5], [11, 1.5], [12, 1.5], [12, 0.5]]]]}},
      {"type": "Feature", "geometry": null}
    ]})",
                                       skipped);
  CHECK(skipped == 2);
  REQUIRE(lots.size() == 2);
  for (const Lot& lot : lots) {
    CHECK(lot.id == "17");
    CHECK(lot.feature == 1);
    REQUIRE(lot.numbers.size() == 1);
    CHECK(lot.numbers[0].second == 9.0);
  }
  CHECK(lots[0].part == 0);
  CHECK(signedArea(lots[0].outer) == 20.0);
  CHECK(lots[0].holes.empty());
  CHECK(lots[1].part == 1);
  CHECK(signedArea(lots[1].outer) == 6.0);
  REQUIRE(lots[1].holes.size() == 1);
  CHECK(signedArea(lots[1].holes[0]) == -1.0);
}

TEST_CASE("a single Feature and a bare geometry are read like a collection of one", "[geojson]") {
  const std::string metres = R"("crs": {"type": "name", "properties": {"name": "urn:fgsg:local-metres"}})";
  const std::vector<Lot> feature = lotsOf("{" + metres + R"(, "type": "Feature", "id": "f",
      "properties": {"usage": "office"},
      "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [2, 0], [2, 2], [0, 2]]]}})");
  REQUIRE(feature.size() == 1);
  CHECK(feature[0].id == "f");
  CHECK(feature[0].feature == 0);
  CHECK(signedArea(feature[0].outer) == 4.0);
  REQUIRE(feature[0].strings.size() == 1);
  CHECK(feature[0].strings[0] == std::make_pair(std::string("usage"), std::string("office")));

  const std::vector<Lot> polygon =
      lotsOf("{" + metres + R"(, "type": "Polygon", "coordinates": [[[0, 0], [3, 0], [3, 3], [0, 3]]]})");
  REQUIRE(polygon.size() == 1);
  CHECK(polygon[0].id.empty());
  CHECK(polygon[0].numbers.empty());
  CHECK(signedArea(polygon[0].outer) == 9.0);

  const std::vector<Lot> multi = lotsOf("{" + metres + R"(, "type": "MultiPolygon", "coordinates": [
      [[[0, 0], [1, 0], [1, 1], [0, 1]]], [[[5, 0], [7, 0], [7, 1], [5, 1]]], [[[9, 0], [12, 0], [12, 1], [9, 1]]]]})");
  REQUIRE(multi.size() == 3);
  CHECK(multi[2].part == 2);
  CHECK(signedArea(multi[2].outer) == 3.0);
}

TEST_CASE("properties go to numbers and strings in file order, other values are left out", "[geojson]") {
  const std::vector<Lot> lots = lotsOf(R"({
    "type": "FeatureCollection",
    "crs": {"type": "name", "properties": {"name": "urn:fgsg:local-metres"}},
    "features": [{"type": "Feature", "id": 2.5,
      "properties": {"roof": "hipped", "height": 12.5, "floors": 4, "listed": true, "shop": false,
                     "owner": null, "tags": [1, 2], "extra": {"a": 1}, "usage": "residential"},
      "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [2, 0], [2, 2], [0, 2]]]}}]})");
  REQUIRE(lots.size() == 1);
  CHECK(lots[0].id == "2.5");
  const std::vector<std::pair<std::string, double>> numbers{
      {"height", 12.5}, {"floors", 4.0}, {"listed", 1.0}, {"shop", 0.0}};
  CHECK(lots[0].numbers == numbers);
  const std::vector<std::pair<std::string, std::string>> strings{{"roof", "hipped"}, {"usage", "residential"}};
  CHECK(lots[0].strings == strings);
}

TEST_CASE("longitude and latitude are projected to metres about the centre of the lots", "[geojson]") {
  // A 0.001-degree square at latitude 45 (no crs: RFC 7946 degrees), and the same square
  // with a lon/lat crs named in the two usual ways.
  const std::string square = R"("features": [{"type": "Feature", "properties": {},
      "geometry": {"type": "Polygon",
                   "coordinates": [[[7, 45], [7.001, 45], [7.001, 45.001], [7, 45.001], [7, 45]]]}}]})";
  const std::string crs84 = R"("crs": {"type": "name", "properties": {"name": "urn:ogc:def:crs:OGC:1.3:CRS84"}},)";
  const std::string epsg4326 = R"("crs": {"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::4326"}},)";
  for (const std::string& crs : {std::string(), crs84, epsg4326}) {
    INFO(crs);
    const std::vector<Lot> lots = lotsOf(R"({"type": "FeatureCollection", )" + crs + square);
    REQUIRE(lots.size() == 1);
    const std::vector<Eigen::Vector2d>& ring = lots[0].outer;
    REQUIRE(ring.size() == 4);
    // The area of the square on the sphere of radius R.
    const double R = 6371008.8, toRadians = kPi / 180;
    const double sphere = R * R * (0.001 * toRadians) * (std::sin(45.001 * toRadians) - std::sin(45 * toRadians));
    CHECK(std::abs(signedArea(ring) - sphere) < 0.001 * sphere);
    // Centred on (0, 0): the corners at +-half the sides, x east and y north.
    CHECK(ring[0].x() == Approx(-ring[1].x()));
    CHECK(ring[0].y() == Approx(-ring[3].y()));
    CHECK(ring[1].x() - ring[0].x() == Approx(R * std::cos(45.0005 * toRadians) * 0.001 * toRadians).epsilon(1e-9));
    CHECK(ring[3].y() - ring[0].y() == Approx(R * 0.001 * toRadians).epsilon(1e-9));
  }
}

TEST_CASE("a crs in metres keeps the coordinates as they are", "[geojson]") {
  const std::vector<Lot> lots = lotsOf(R"({"type": "FeatureCollection",
    "crs": {"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::25832"}},
    "features": [{"type": "Feature", "properties": {},
      "geometry": {"type": "Polygon", "coordinates": [[[500000.25, 5400000.5], [500030.25, 5400000.5],
                                                       [500030.25, 5400020.5], [500000.25, 5400020.5]]]}}]})");
  REQUIRE(lots.size() == 1);
  const std::vector<Eigen::Vector2d> expected{
      {500000.25, 5400000.5}, {500030.25, 5400000.5}, {500030.25, 5400020.5}, {500000.25, 5400020.5}};
  CHECK(lots[0].outer == expected);
}

TEST_CASE("invalid JSON is refused with its line and column", "[geojson]") {
  const std::string error = refusal("{\"type\": \"FeatureCollection\",\n  \"features\": [,]}");
  CHECK(error.rfind("lots.geojson:2:16: not valid JSON: syntax error", 0) == 0);
  CHECK(refusal("{\"type\": \"Polygon\",\n \"coordinates\": [[[0, 0], [1e999, 0], [1, 1]]]}") ==
        "lots.geojson:2:28: not valid JSON: number overflow parsing '1e999'");
}

TEST_CASE("a file that cannot be read is refused with its name", "[geojson]") {
  std::vector<Lot> lots;
  size_t skipped = 0;
  std::string error;
  CHECK_FALSE(readGeoJsonLots("/nonexistent/fgsg/lots.geojson", lots, skipped, error));
  CHECK(error.rfind("/nonexistent/fgsg/lots.geojson: ", 0) == 0);
}

TEST_CASE("coordinates of the wrong type are refused naming the feature, ring and point", "[geojson]") {
  CHECK(refusal(polygonInMetres(R"([[[0, 0], [1, 0], ["1", 1]]])")) ==
        "lots.geojson: feature 0 (id \"a\"), ring 0 (outer), point 2: a position is an array of numbers, it holds a "
        "string");
  CHECK(refusal(polygonInMetres(R"([[[0, 0], [1, 0], [1, 1]], [[0.2, 0.1], [0.5]]])")) ==
        "lots.geojson: feature 0 (id \"a\"), ring 1 (hole 1), point 1: a position is an array of 2 or more numbers, "
        "got an array of 1");
  CHECK(refusal(polygonInMetres(R"([[[0, 0], [1, 0], [1, 1]], 7])")) ==
        "lots.geojson: feature 0 (id \"a\"), ring 1 (hole 1): a ring is an array of positions, got a number");
  CHECK(refusal(polygonInMetres(R"("none")")) ==
        "lots.geojson: feature 0 (id \"a\"): geometry: \"coordinates\" is an array, got a string");
  CHECK(refusal(R"({"type": "FeatureCollection",
                    "features": [{"type": "Feature", "properties": 3, "geometry": null}]})") ==
        "lots.geojson: feature 0: \"properties\" is an object or null, got a number");
}

TEST_CASE("degrees out of range are refused with a hint at the crs", "[geojson]") {
  const std::string error = refusal(R"({"type": "Feature", "id": "x", "properties": {},
      "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [500, 0], [500, 20]]]}})");
  CHECK(error.rfind("lots.geojson: feature 0 (id \"x\"), ring 0 (outer), point 1: (500, 0) is not longitude/latitude "
                    "in degrees; a file in metres says so with a \"crs\"",
                    0) == 0);
}

TEST_CASE("an empty polygon is refused", "[geojson]") {
  CHECK(refusal(polygonInMetres("[]")) == "lots.geojson: feature 0 (id \"a\"): an empty polygon (no rings)");
  CHECK(refusal(polygonInMetres("[[]]")) ==
        "lots.geojson: feature 0 (id \"a\"), ring 0 (outer): 0 distinct points; a ring needs at least 3");
}

TEST_CASE("a ring with fewer than 3 distinct points is refused", "[geojson]") {
  CHECK(refusal(polygonInMetres(R"([[[0, 0], [1, 2], [0, 0], [1, 2], [0, 0]]])")) ==
        "lots.geojson: feature 0 (id \"a\"), ring 0 (outer): 2 distinct points: (0, 0) and (1, 2); a ring needs at "
        "least 3");
}

TEST_CASE("a ring of zero area is refused", "[geojson]") {
  CHECK(refusal(polygonInMetres(R"([[[0, 0], [4, 0], [4, 4], [0, 4]], [[1, 1], [3, 3], [2, 2]]])")) ==
        "lots.geojson: feature 0 (id \"a\"), ring 1 (hole 1): zero area (all its points on one line, from point 0 "
        "(1, 1))");
}

TEST_CASE("a self-intersecting ring is refused naming the two edges", "[geojson]") {
  // A bow tie: the second and fourth edges cross at (1, 1).
  CHECK(refusal(polygonInMetres(R"([[[0, 0], [2, 0], [0, 2], [2, 2], [0, 0]]])")) ==
        "lots.geojson: feature 0 (id \"a\"), ring 0 (outer): the edge from point 3 (2, 2) to point 0 (0, 0) crosses "
        "the edge from point 1 (2, 0) to point 2 (0, 2)");
  // Pinched: the ring passes through (2, 2) twice.
  CHECK(refusal(polygonInMetres(R"([[[0, 0], [4, 0], [2, 2], [4, 4], [0, 4], [2, 2]]])")) ==
        "lots.geojson: feature 0 (id \"a\"), ring 0 (outer): the edge from point 4 (0, 4) to point 5 (2, 2) touches "
        "the edge from point 1 (4, 0) to point 2 (2, 2)");
}

TEST_CASE("a hole that crosses or touches the outer ring is refused", "[geojson]") {
  CHECK(refusal(polygonInMetres(R"([[[0, 0], [10, 0], [10, 10], [0, 10]], [[8, 2], [12, 2], [12, 4], [8, 4]]])")) ==
        "lots.geojson: feature 0 (id \"a\"), ring 1 (hole 1): the edge from point 0 (8, 2) to point 1 (12, 2) crosses "
        "ring 0 (outer) at the edge from point 1 (10, 0) to point 2 (10, 10)");
  CHECK(refusal(polygonInMetres(R"([[[0, 0], [10, 0], [10, 10], [0, 10]], [[10, 5], [8, 4], [8, 6]]])")) ==
        "lots.geojson: feature 0 (id \"a\"), ring 1 (hole 1): the edge from point 0 (10, 5) to point 1 (8, 4) touches "
        "ring 0 (outer) at the edge from point 1 (10, 0) to point 2 (10, 10)");
}

TEST_CASE("a hole outside the outer ring is refused", "[geojson]") {
  CHECK(refusal(polygonInMetres(R"([[[0, 0], [10, 0], [10, 10], [0, 10]], [[20, 20], [21, 20], [21, 21]]])")) ==
        "lots.geojson: feature 0 (id \"a\"), ring 1 (hole 1): lies outside the outer ring (its point 0 (20, 20))");
  // The outer ring inside its hole.
  CHECK(refusal(polygonInMetres(R"([[[4, 4], [6, 4], [6, 6], [4, 6]], [[0, 0], [10, 0], [10, 10], [0, 10]]])")) ==
        "lots.geojson: feature 0 (id \"a\"), ring 1 (hole 1): lies outside the outer ring (its point 0 (0, 0))");
}

TEST_CASE("holes that overlap each other are refused", "[geojson]") {
  CHECK(refusal(polygonInMetres(R"([[[0, 0], [10, 0], [10, 10], [0, 10]],
                                     [[1, 1], [5, 1], [5, 5], [1, 5]], [[4, 4], [8, 4], [8, 8], [4, 8]]])")) ==
        "lots.geojson: feature 0 (id \"a\"), ring 2 (hole 2): the edge from point 3 (4, 8) to point 0 (4, 4) crosses "
        "ring 1 (hole 1) at the edge from point 2 (5, 5) to point 3 (1, 5)");
  CHECK(refusal(polygonInMetres(R"([[[0, 0], [10, 0], [10, 10], [0, 10]],
                                     [[1, 1], [9, 1], [9, 9], [1, 9]], [[4, 4], [6, 4], [6, 6], [4, 6]]])")) ==
        "lots.geojson: feature 0 (id \"a\"), ring 2 (hole 2): lies inside ring 1 (hole 1) (its point 0 (4, 4)); holes "
        "may not overlap");
}

TEST_CASE("an invalid polygon of a MultiPolygon is named by its index", "[geojson]") {
  CHECK(refusal(R"({"type": "FeatureCollection",
    "crs": {"type": "name", "properties": {"name": "urn:fgsg:local-metres"}},
    "features": [{"type": "Feature", "id": "ok", "properties": {},
                  "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, 1]]]}},
                 {"type": "Feature", "id": "m", "properties": {},
                  "geometry": {"type": "MultiPolygon", "coordinates": [
                    [[[0, 0], [1, 0], [1, 1]]], [[[0, 0], [2, 0], [0, 2], [2, 2]]]]}}]})") ==
        "lots.geojson: feature 1 (id \"m\"), polygon 1, ring 0 (outer): the edge from point 3 (2, 2) to point 0 (0, 0) "
        "crosses the edge from point 1 (2, 0) to point 2 (0, 2)");
}

TEST_CASE("a file without a Polygon or MultiPolygon is refused", "[geojson]") {
  CHECK(refusal(R"({"type": "FeatureCollection", "features": [
      {"type": "Feature", "properties": {}, "geometry": {"type": "Point", "coordinates": [1, 2]}},
      {"type": "Feature", "properties": {}, "geometry": {"type": "LineString", "coordinates": [[1, 2], [3, 4]]}}]})") ==
        "lots.geojson: no Polygon or MultiPolygon to take lots from (2 other geometries skipped)");
  CHECK(refusal(R"({"type": "Feature", "properties": {},
                    "geometry": {"type": "GeometryCollection", "geometries": []}})") ==
        "lots.geojson: no Polygon or MultiPolygon to take lots from (1 other geometry skipped)");
  CHECK(refusal(R"({"type": "FeatureCollection", "features": []})") ==
        "lots.geojson: no Polygon or MultiPolygon to take lots from");
  CHECK(refusal(R"({"type": "Polygn", "coordinates": []})") ==
        "lots.geojson: geometry: \"Polygn\" is not a GeoJSON geometry type");
}

TEST_CASE("a lot with too many points is refused before its quadratic checks", "[geojson]") {
  std::string ring;
  for (size_t i = 0; i <= kMaxLotPoints; ++i) {
    const double angle = 2 * kPi * double(i) / double(kMaxLotPoints + 1);
    ring += (i ? ", [" : "[") + std::to_string(1000 * std::cos(angle)) + ", " +
            std::to_string(1000 * std::sin(angle)) + "]";
  }
  CHECK(refusal(polygonInMetres("[[" + ring + "]]")) ==
        "lots.geojson: feature 0 (id \"a\"): more than " + std::to_string(kMaxLotPoints) + " points; a lot has fewer");
}

namespace {

// One feature with id "a" and `properties`, holding a `geometry`, in local metres.
std::string featureInMetres(const std::string& properties, const std::string& geometry) {
  return R"({"type": "FeatureCollection",
             "crs": {"type": "name", "properties": {"name": "urn:fgsg:local-metres"}},
             "features": [{"type": "Feature", "id": "a", "properties": )" +
         properties + R"(, "geometry": )" + geometry + "}]}";
}

}  // namespace

TEST_CASE("streetWidth gives each edge of the outer ring its width, in the ring's order", "[geojson][street]") {
  // Counter-clockwise as written: edge i runs from point i to i + 1.
  std::vector<Lot> lots = lotsOf(featureInMetres(
      R"({"streetWidth": [8, 4, 0, 0]})", R"({"type": "Polygon", "coordinates": [[[0,0],[10,0],[10,6],[0,6],[0,0]]]})"));
  REQUIRE(lots.size() == 1);
  CHECK(lots[0].streetWidth == std::vector<double>{8, 4, 0, 0});
  CHECK(lots[0].numbers.empty());  // an array: not one of the numbers
  // Clockwise as written: the ring is turned about its first point, (0,0) (0,6) (10,6)
  // (10,0) becoming (0,0) (10,0) (10,6) (0,6); the written edge 1, (0,6)-(10,6), is the
  // third edge of the turned ring.
  lots = lotsOf(featureInMetres(R"({"streetWidth": [0, 12, 0, 3]})",
                                R"({"type": "Polygon", "coordinates": [[[0,0],[0,6],[10,6],[10,0],[0,0]]]})"));
  REQUIRE(lots.size() == 1);
  CHECK(lots[0].outer[1] == Eigen::Vector2d(10, 0));
  CHECK(lots[0].streetWidth == std::vector<double>{3, 0, 12, 0});
  // A repeated point makes an edge of no length: its width goes with it.
  lots = lotsOf(featureInMetres(R"({"streetWidth": [1, 2, 99, 3, 4]})",
                                R"({"type": "Polygon", "coordinates": [[[0,0],[10,0],[10,6],[10,6],[0,6],[0,0]]]})"));
  REQUIRE(lots.size() == 1);
  CHECK(lots[0].outer.size() == 4);
  CHECK(lots[0].streetWidth == std::vector<double>{1, 2, 3, 4});
  // No property: no widths.
  lots = lotsOf(polygonInMetres("[[[0,0],[10,0],[10,6],[0,0]]]"));
  CHECK(lots[0].streetWidth.empty());
}

TEST_CASE("a malformed streetWidth is refused naming the feature and the value", "[geojson][street]") {
  const std::string rect = R"({"type": "Polygon", "coordinates": [[[0,0],[10,0],[10,6],[0,6],[0,0]]]})";
  CHECK(refusal(featureInMetres(R"({"streetWidth": [8, 4, 0]})", rect)) ==
        "lots.geojson: feature 0 (id \"a\"): property \"streetWidth\" has 3 values; the outer ring has 4 edges (one "
        "value per edge, in the ring's order)");
  CHECK(refusal(featureInMetres(R"({"streetWidth": [8, -4, 0, 0]})", rect)) ==
        "lots.geojson: feature 0 (id \"a\"): property \"streetWidth\", value 1: -4 is below 0 (0: no street)");
  CHECK(refusal(featureInMetres(R"({"streetWidth": [8, "4", 0, 0]})", rect)) ==
        "lots.geojson: feature 0 (id \"a\"): property \"streetWidth\", value 1: a street width is a number, got a "
        "string");
  CHECK(refusal(featureInMetres(R"({"streetWidth": 8})", rect)) ==
        "lots.geojson: feature 0 (id \"a\"): property \"streetWidth\" is an array of numbers, one per edge of the "
        "outer ring, got a number");
  CHECK(refusal(featureInMetres(
            R"({"streetWidth": [1, 1, 1]})",
            R"({"type": "MultiPolygon", "coordinates": [[[[0,0],[1,0],[0,1],[0,0]]], [[[5,0],[6,0],[5,1],[5,0]]]]})")) ==
        "lots.geojson: feature 0 (id \"a\"): property \"streetWidth\" gives the edges of one polygon; this "
        "MultiPolygon has 2 (give each polygon a feature of its own)");
}
