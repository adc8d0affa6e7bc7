#include "runtime/evolve/tiles.h"

#include "runtime/io/quoted_text.h"
#include "runtime/io/read_input.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace fgsg::rt::evolve {

namespace {

using nlohmann::json;

constexpr double kTolerance = 1e-9;

std::string fmt(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::string fmt(Point2 p) { return "(" + fmt(p.x) + ", " + fmt(p.y) + ")"; }

char defaultLetter(int i) { return i < 26 ? char('A' + i) : char('a' + (i - 26)); }

bool isAsciiLetter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }

[[noreturn]] void fail(std::string_view source, const std::string& where, const std::string& what) {
  throw TileFileError(std::string(source) + ": " + (where.empty() ? "" : where + ": ") + what);
}

const char* typeName(const json& j) {
  switch (j.type()) {
    case json::value_t::null: return "null";
    case json::value_t::object: return "an object";
    case json::value_t::array: return "an array";
    case json::value_t::string: return "a string";
    case json::value_t::boolean: return "a boolean";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float: return "a number";
    default: return "something else";
  }
}

Point2 readPoint(const json& j, std::string_view source, const std::string& where) {
  if (!j.is_array() || j.size() != 2 || !j[0].is_number() || !j[1].is_number())
    fail(source, where, std::string("a point is an array of two numbers [x, y], got ") +
                            (j.is_array() ? "an array of " + std::to_string(j.size()) : typeName(j)));
  const Point2 p{j[0].get<double>(), j[1].get<double>()};
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) fail(source, where, "coordinates must be finite");
  return p;
}

// {"name": ..., "polyline": [...]} or {"name": ..., "cubic": [...]}.
template <class Item>
Item readCurveItem(const json& j, std::string_view source, const std::string& where, const std::string& defaultName) {
  if (!j.is_object()) fail(source, where, std::string("expected an object, got ") + typeName(j));
  Item item;
  item.name = defaultName;
  int curves = 0;
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string& key = it.key();
    if (key == "name") {
      if (!it->is_string()) fail(source, where + ".name", std::string("expected a string, got ") + typeName(*it));
      item.name = it->get<std::string>();
    } else if (key == "polyline" || key == "cubic") {
      ++curves;
      item.curve.kind = key == "cubic" ? Curve::Kind::kCubic : Curve::Kind::kPolyline;
      const std::string w = where + "." + key;
      if (!it->is_array()) fail(source, w, std::string("expected an array of points, got ") + typeName(*it));
      for (size_t i = 0; i < it->size(); ++i)
        item.curve.points.push_back(readPoint((*it)[i], source, w + "[" + std::to_string(i) + "]"));
    } else {
      fail(source, where, "unknown key \"" + key + "\" (expected \"name\" and one of \"polyline\", \"cubic\")");
    }
  }
  if (curves != 1) fail(source, where, curves == 0 ? "needs a curve: \"polyline\" or \"cubic\"" : "has both \"polyline\" and \"cubic\"");
  return item;
}

void checkCurve(const Curve& c, std::string_view source, const std::string& where) {
  if (c.kind == Curve::Kind::kCubic && c.points.size() != 4)
    fail(source, where, "a cubic needs 4 points, got " + std::to_string(c.points.size()));
  if (c.kind == Curve::Kind::kPolyline && c.points.size() < 2)
    fail(source, where, "a polyline needs at least 2 points, got " + std::to_string(c.points.size()));
  for (size_t i = 0; i < c.points.size(); ++i)
    if (!std::isfinite(c.points[i].x) || !std::isfinite(c.points[i].y))
      fail(source, where + "[" + std::to_string(i) + "]", "coordinates must be finite");
}

bool near(Point2 a, Point2 b) { return std::abs(a.x - b.x) <= kTolerance && std::abs(a.y - b.y) <= kTolerance; }

std::string curveKey(const Curve& c) { return c.kind == Curve::Kind::kCubic ? "cubic" : "polyline"; }

}  // namespace

Point2 turnInTile(Point2 p, int quarterTurns) {
  switch (((quarterTurns % 4) + 4) % 4) {
    case 1: return {1 - p.y, p.x};
    case 2: return {1 - p.x, 1 - p.y};
    case 3: return {p.y, 1 - p.x};
    default: return p;
  }
}

Point2 Curve::at(double t) const {
  t = std::clamp(t, 0.0, 1.0);
  if (kind == Kind::kCubic) {
    const double s = 1 - t;
    const double b0 = s * s * s, b1 = 3 * s * s * t, b2 = 3 * s * t * t, b3 = t * t * t;
    return {b0 * points[0].x + b1 * points[1].x + b2 * points[2].x + b3 * points[3].x,
            b0 * points[0].y + b1 * points[1].y + b2 * points[2].y + b3 * points[3].y};
  }
  const size_t segments = points.size() - 1;
  const double u = t * double(segments);
  const size_t i = std::min(segments - 1, size_t(u));
  const double f = u - double(i);
  return {points[i].x + f * (points[i + 1].x - points[i].x), points[i].y + f * (points[i + 1].y - points[i].y)};
}

std::vector<Point2> Curve::sample(int count) const {
  count = std::max(count, 2);
  std::vector<Point2> out;
  out.reserve(size_t(count));
  for (int i = 0; i < count; ++i) out.push_back(i + 1 == count ? end() : i == 0 ? start() : at(double(i) / (count - 1)));
  return out;
}

std::string TileSet::letters() const {
  std::string s;
  for (const Tile& t : tiles) s += t.letter;
  return s;
}

std::vector<Allele> TileSet::alleles() const {
  std::vector<Allele> out;
  for (int s = 0; s < symbolCount(); ++s)
    for (int o : orientations) out.push_back(Allele{uint8_t(s), uint8_t(o)});
  return out;
}

std::array<Point2, 2> TileSet::endpoints(Allele a) const {
  const Curve& c = loci[size_t(tiles[a.symbol].locus)].curve;
  return {turnInTile(c.start(), a.turns), turnInTile(c.end(), a.turns)};
}

std::vector<Point2> TileSet::locusPoints(Allele a, int count) const {
  std::vector<Point2> pts = loci[size_t(tiles[a.symbol].locus)].curve.sample(count);
  for (Point2& p : pts) p = turnInTile(p, a.turns);
  return pts;
}

// Runs `check` on part[index] of a tile set; its TileFileError comes out naming them.
template <class Check>
void checkPart(const char* part, size_t index, Check&& check) {
  try {
    check();
  } catch (const TileFileError& e) {
    throw TileFileError(e.what(), part, int(index));
  }
}

void validateTileSet(const TileSet& ts, std::string_view source) {
  if (ts.loci.empty()) fail(source, "loci", "at least one locus is needed");
  if (ts.sections.empty()) fail(source, "sections", "at least one cross-section is needed");
  for (size_t i = 0; i < ts.loci.size(); ++i) {
    const Curve& c = ts.loci[i].curve;
    const std::string where = "loci[" + std::to_string(i) + "]." + curveKey(c);
    checkPart("loci", i, [&] {
      checkCurve(c, source, where);
      for (size_t k = 0; k < c.points.size(); ++k) {
        const Point2 p = c.points[k];
        if (p.x < -kTolerance || p.x > 1 + kTolerance || p.y < -kTolerance || p.y > 1 + kTolerance)
          fail(source, where + "[" + std::to_string(k) + "]",
               "point " + fmt(p) + " is outside the tile's unit square [0,1] x [0,1]");
      }
    });
  }
  for (size_t i = 0; i < ts.sections.size(); ++i) {
    const Curve& c = ts.sections[i].curve;
    const std::string where = "sections[" + std::to_string(i) + "]." + curveKey(c);
    checkPart("sections", i, [&] {
      checkCurve(c, source, where);
      if (!near(c.start(), {-1, 0}) || !near(c.end(), {1, 0}))
        fail(source, where,
             "a cross-section runs from (-1, 0) to (1, 0) (Elber's blending, paper §2.4); this one runs from " +
                 fmt(c.start()) + " to " + fmt(c.end()));
    });
  }
  if (ts.tiles.empty()) fail(source, "symbols", "no symbols");
  if (int(ts.tiles.size()) > kMaxSymbols)
    fail(source, "symbols", std::to_string(ts.tiles.size()) + " symbols (loci x cross-sections); at most " +
                                std::to_string(kMaxSymbols) + " (the letters A-Z, a-z)");
  for (size_t i = 0; i < ts.tiles.size(); ++i) {
    const Tile& t = ts.tiles[i];
    const std::string where = "symbols[" + std::to_string(i) + "]";
    if (!isAsciiLetter(t.letter)) fail(source, where, std::string("a symbol is a letter A-Z or a-z, not '") + t.letter + "'");
    for (size_t j = 0; j < i; ++j)
      if (ts.tiles[j].letter == t.letter) fail(source, where, std::string("letter '") + t.letter + "' is used twice");
    if (t.locus < 0 || size_t(t.locus) >= ts.loci.size()) fail(source, where, "no locus " + std::to_string(t.locus));
    if (t.section < 0 || size_t(t.section) >= ts.sections.size())
      fail(source, where, "no cross-section " + std::to_string(t.section));
  }
  if (ts.orientations.empty()) fail(source, "orientations", "at least one orientation is needed");
  for (size_t i = 0; i < ts.orientations.size(); ++i) {
    if (ts.orientations[i] < 0 || ts.orientations[i] > 3)
      fail(source, "orientations[" + std::to_string(i) + "]", "quarter turns 0..3 (0, 90, 180, 270 degrees)");
    if (i > 0 && ts.orientations[i] <= ts.orientations[i - 1])
      fail(source, "orientations", "must be ascending without repeats");
  }
}

TileSet parseTileSet(std::string_view text, std::string_view source) {
  json root;
  try {
    root = json::parse(text.begin(), text.end(), nullptr, /*allow_exceptions=*/true, /*ignore_comments=*/true);
  } catch (const json::parse_error& e) {
    // e.byte: 1-based offset of the character where parsing failed.
    size_t line = 1, column = 1;
    const size_t end = std::min(text.size(), e.byte > 0 ? size_t(e.byte - 1) : size_t(0));
    for (size_t i = 0; i < end; ++i) {
      if (text[i] == '\n') ++line, column = 1;
      else ++column;
    }
    std::string what = e.what();
    // nlohmann's text: "[json.exception.parse_error.101] parse error at line 1, column 5: syntax error ..."
    if (const size_t colon = what.find(": "); colon != std::string::npos) what = what.substr(colon + 2);
    throw TileFileError(std::string(source) + ":" + std::to_string(line) + ":" + std::to_string(column) +
                        ": not valid JSON: " + what);
  } catch (const json::exception& e) {
    // A number too large for a double ("number overflow parsing '1e999'", out_of_range)
    // carries no position: the first place the number's text occurs is where it is.
    std::string what = e.what(), where(source);
    const size_t open = what.find('\''), close = what.rfind('\'');
    std::string number;
    if (open != std::string::npos && close > open) number = what.substr(open + 1, close - open - 1);
    if (const size_t at = number.empty() ? std::string_view::npos : text.find(number); at != std::string_view::npos) {
      size_t line = 1, column = 1;
      for (size_t i = 0; i < at; ++i) {
        if (text[i] == '\n') ++line, column = 1;
        else ++column;
      }
      where += ":" + std::to_string(line) + ":" + std::to_string(column);
    }
    throw TileFileError(where + ": not valid JSON: " +
                        (number.empty() ? what : "the number " + io::quoteText(number) + " is too large"));
  }
  if (!root.is_object()) fail(source, "", std::string("a tile file is a JSON object, got ") + typeName(root));

  TileSet ts;
  ts.tiles.clear();
  std::string symbols;
  bool haveSymbols = false;
  for (auto it = root.begin(); it != root.end(); ++it) {
    const std::string& key = it.key();
    if (key == "loci" || key == "sections") {
      if (!it->is_array()) fail(source, key, std::string("expected an array, got ") + typeName(*it));
      for (size_t i = 0; i < it->size(); ++i) {
        const std::string where = key + "[" + std::to_string(i) + "]";
        if (key == "loci") ts.loci.push_back(readCurveItem<Locus>((*it)[i], source, where, "locus " + std::to_string(i)));
        else ts.sections.push_back(readCurveItem<Section>((*it)[i], source, where, "section " + std::to_string(i)));
      }
    } else if (key == "orientations") {
      if (!it->is_array()) fail(source, key, std::string("expected an array of angles, got ") + typeName(*it));
      ts.orientations.clear();
      for (size_t i = 0; i < it->size(); ++i) {
        const json& v = (*it)[i];
        const std::string where = "orientations[" + std::to_string(i) + "]";
        if (!v.is_number_integer() && !v.is_number_unsigned())
          fail(source, where, std::string("an orientation is 0, 90, 180 or 270, got ") + typeName(v));
        const long long deg = v.get<long long>();
        if (deg != 0 && deg != 90 && deg != 180 && deg != 270)
          fail(source, where, "an orientation is 0, 90, 180 or 270, got " + std::to_string(deg));
        ts.orientations.push_back(int(deg / 90));
      }
      std::vector<int> sorted = ts.orientations;
      std::sort(sorted.begin(), sorted.end());
      if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
        fail(source, "orientations", "an orientation is listed twice");
      ts.orientations = sorted;
    } else if (key == "symbols") {
      if (!it->is_string()) fail(source, key, std::string("expected a string of letters, got ") + typeName(*it));
      symbols = it->get<std::string>();
      haveSymbols = true;
    } else {
      fail(source, "", "unknown key \"" + key + "\" (expected \"loci\", \"sections\", \"orientations\", \"symbols\")");
    }
  }
  if (!root.contains("loci")) fail(source, "", "missing \"loci\"");
  if (!root.contains("sections")) fail(source, "", "missing \"sections\"");
  return makeTileSet(std::move(ts.loci), std::move(ts.sections),
                     root.contains("orientations") ? std::optional(ts.orientations) : std::nullopt,
                     haveSymbols ? std::optional(symbols) : std::nullopt, source);
}

TileSet makeTileSet(std::vector<Locus> loci, std::vector<Section> sections, std::optional<std::vector<int>> turns,
                    std::optional<std::string> symbols, std::string_view source) {
  TileSet ts;
  ts.loci = std::move(loci);
  ts.sections = std::move(sections);
  if (turns) ts.orientations = *turns;
  ts.tiles.clear();
  const bool haveSymbols = symbols.has_value();
  const size_t count = ts.loci.size() * ts.sections.size();
  if (haveSymbols && symbols->size() != count)
    fail(source, "symbols", "needs one letter per locus x cross-section: " + std::to_string(ts.loci.size()) + " x " +
                                std::to_string(ts.sections.size()) + " = " + std::to_string(count) + ", got " +
                                std::to_string(symbols->size()));
  if (count > size_t(kMaxSymbols))
    fail(source, "", std::to_string(count) + " symbols (loci x cross-sections); at most " + std::to_string(kMaxSymbols) +
                         " (the letters A-Z, a-z)");
  for (size_t l = 0; l < ts.loci.size(); ++l)
    for (size_t s = 0; s < ts.sections.size(); ++s) {
      const size_t i = l * ts.sections.size() + s;
      ts.tiles.push_back(Tile{haveSymbols ? (*symbols)[i] : defaultLetter(int(i)), int(l), int(s)});
    }
  validateTileSet(ts, source);
  return ts;
}

TileSet readTileFile(const std::string& path) {
  std::string text, error;
  if (!io::readInputFile(path, "a tile file", text, error)) throw TileFileError(error);
  return parseTileSet(text, path);
}

TileSet exampleTileSet() {
  TileSet ts;
  ts.loci.push_back({"A", {Curve::Kind::kCubic, {{0.5, 0}, {0.5, 0.276}, {0.724, 0.5}, {1, 0.5}}}});
  ts.loci.push_back({"B", {Curve::Kind::kPolyline, {{0, 0.5}, {1, 0.5}}}});
  ts.sections.push_back({"C", {Curve::Kind::kPolyline, {{-1, 0}, {-0.7, 0.7}, {0, 1}, {0.7, 0.7}, {1, 0}}}});
  ts.tiles = {Tile{'A', 0, 0}, Tile{'B', 1, 0}};
  ts.orientations = {0, 1, 2, 3};
  validateTileSet(ts, "example tile set");
  return ts;
}

}  // namespace fgsg::rt::evolve
