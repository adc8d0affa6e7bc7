// WFC-style tile sets (JSON). Tiles have a symmetry class (X L T I \ F, as in Gumin's
// SimpleTiledModel) that says how many distinct orientations the tile has; each
// orientation becomes a label ("name", "name.1", ...). A neighbour rule names two tile
// orientations ("line 1") side by side in x ("left"/"right") or stacked in z
// ("bottom"/"top"); all its images under the 8 symmetries of the square are added.
#include "runtime/synthesis/example.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <set>

namespace fgsg::rt::synthesis {

namespace {

using json = nlohmann::json;

struct SymmetryClass {
  int cardinality;
  int (*a)(int);  // turn 90° counter-clockwise
  int (*b)(int);  // mirror x -> -x
};

bool symmetryClass(const std::string& s, SymmetryClass& out) {
  if (s == "X") out = {1, [](int i) { return i; }, [](int i) { return i; }};
  else if (s == "L") out = {4, [](int i) { return (i + 1) % 4; }, [](int i) { return i % 2 == 0 ? i + 1 : i - 1; }};
  else if (s == "T") out = {4, [](int i) { return (i + 1) % 4; }, [](int i) { return i % 2 == 0 ? i : 4 - i; }};
  else if (s == "I") out = {2, [](int i) { return 1 - i; }, [](int i) { return i; }};
  else if (s == "\\") out = {2, [](int i) { return 1 - i; }, [](int i) { return 1 - i; }};
  else if (s == "F") out = {8, [](int i) { return i < 4 ? (i + 1) % 4 : 4 + (i - 1) % 4; },
                            [](int i) { return i < 4 ? i + 4 : i - 4; }};
  else return false;
  return true;
}

// Line and column of a byte offset, for JSON diagnostics.
void lineCol(std::string_view text, size_t byte, int& line, int& col, std::string& src) {
  line = 1;
  size_t start = 0;
  for (size_t i = 0; i < byte && i < text.size(); ++i)
    if (text[i] == '\n') { ++line; start = i + 1; }
  col = int(std::min(byte, text.size()) - start) + 1;
  size_t end = text.find('\n', start);
  src = std::string(text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
}

// Finds where a string value occurs in the text (JSON values carry no positions).
int lineOfString(std::string_view text, const std::string& needle) {
  size_t at = text.find("\"" + needle + "\"");
  if (at == std::string_view::npos) return 0;
  int line = 1;
  for (size_t i = 0; i < at; ++i) line += text[i] == '\n';
  return line;
}

// The line of `"key"` in the object that `"owner"` names or opens (a tile's name, a border
// face), for a wrong-typed field: from the '{' before the owner (a tile's fields may come
// before its name) or, with `after`, the first '{' after it, to that object's '}'. The
// owner's line when the key is not found there. Tile fields hold no nested objects.
int lineOfKey(std::string_view text, const std::string& owner, const std::string& key, bool after) {
  const size_t at = text.find("\"" + owner + "\"");
  if (at == std::string_view::npos) return 0;
  const size_t open = after ? text.find('{', at) : text.rfind('{', at);
  size_t where = at;
  if (open != std::string_view::npos) {
    const size_t found = text.find("\"" + key + "\"", open);
    const size_t close = text.find('}', open);
    if (found != std::string_view::npos && (close == std::string_view::npos || found < close)) where = found;
  }
  int line = 1;
  for (size_t i = 0; i < where; ++i) line += text[i] == '\n';
  return line;
}

// "a number (3)": what a wrong-typed field holds, short enough for one message line.
std::string describe(const json& v) {
  std::string text = v.dump();
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  return std::string(v.type_name()) + " (" + text + ")";
}

// Reads the optional fields of one JSON object (a tile, a border entry). A field that is
// present with another type is reported with what was expected, instead of letting
// nlohmann's typed accessors throw.
class FieldReader {
 public:
  using Fail = std::function<void(const std::string& key, const std::string& message)>;
  FieldReader(const json& object, std::string owner, Fail fail)
      : object_(object), owner_(std::move(owner)), fail_(std::move(fail)) {}

  // Each returns false (after reporting) when the field is there with the wrong type;
  // an absent field leaves `out` at its default.
  bool string(const char* key, std::string& out, const char* expected = "a string") {
    const json* v = find(key);
    if (!v) return true;
    if (!v->is_string()) return wrong(key, expected, *v);
    out = v->get<std::string>();
    return true;
  }
  bool boolean(const char* key, bool& out) {
    const json* v = find(key);
    if (!v) return true;
    if (!v->is_boolean()) return wrong(key, "true or false", *v);
    out = v->get<bool>();
    return true;
  }

 private:
  const json* find(const char* key) const {
    auto it = object_.find(key);
    return it == object_.end() ? nullptr : &*it;
  }
  bool wrong(const char* key, const char* expected, const json& v) {
    fail_(key, owner_ + ": \"" + key + "\" must be " + expected + ", got " + describe(v));
    return false;
  }

  const json& object_;
  std::string owner_;
  Fail fail_;
};

// Reads the tile set from the parsed document; reports and returns false on bad content.
bool readTileSet(const json& doc, std::string_view text, const std::string& fileName, Example& out,
                 Diagnostics& diags) {
  const size_t diagStart = diags.size();
  auto fail = [&](const std::string& near, std::string msg) {
    diags.push_back({fileName, lineOfString(text, near), 0, "E712", std::move(msg), ""});
  };
  auto failAtKey = [&](const std::string& owner, bool after, const std::string& key, const std::string& msg) {
    diags.push_back({fileName, lineOfKey(text, owner, key, after), 0, "E712", msg, ""});
  };
  if (!doc.is_object() || !doc.contains("tiles") || !doc["tiles"].is_array()) {
    diags.push_back({fileName, 1, 1, "E712", "a tile set is an object with a \"tiles\" array", ""});
    return false;
  }

  struct TileInfo {
    std::string name;
    SymmetryClass sym;
    int32_t first;  // label of orientation 0
  };
  std::vector<TileInfo> tiles;
  std::vector<int32_t> tileOf;  // label -> tile index
  for (const auto& t : doc["tiles"]) {
    if (!t.is_object() || !t.contains("name") || !t["name"].is_string()) {
      fail("tiles", "every tile needs a \"name\" string");
      continue;
    }
    const std::string name = t["name"];
    for (const auto& ti : tiles)
      if (ti.name == name) fail(name, "tile `" + name + "` declared twice");
    FieldReader fields(t, "tile `" + name + "`", [&](const std::string& key, const std::string& msg) {
      failAtKey(name, false, key, msg);
    });
    std::string symName = "X";
    Piece base;
    base.asset = "cube";
    bool background = false, empty = false;
    bool typesOk = fields.string("symmetry", symName, "a symmetry class X, L, T, I, \\ or F (a string)");
    typesOk &= fields.string("asset", base.asset, "an asset name (a string; \"none\" for no asset)");
    typesOk &= fields.boolean("background", background);
    typesOk &= fields.boolean("empty", empty);
    typesOk &= fields.boolean("connect", base.connect);
    if (!typesOk) continue;
    SymmetryClass sym;
    if (!symmetryClass(symName, sym)) {
      fail(symName, "tile `" + name + "`: unknown symmetry class `" + symName + "` (X L T I \\ F)");
      continue;
    }
    if (base.asset == "none") base.asset.clear();
    base.weight = 1.0;
    if (t.contains("weight")) {
      if (!t["weight"].is_number() || t["weight"].get<double>() < 0)
        failAtKey(name, false, "weight", "tile `" + name + "`: \"weight\" must be a number >= 0, got " + describe(t["weight"]));
      else
        base.weight = t["weight"].get<double>();
    }
    if (t.contains("color")) {
      std::string c = t["color"].is_string() ? t["color"].get<std::string>() : "";
      unsigned v = 0;
      if (c.size() == 7 && c[0] == '#' && std::sscanf(c.c_str() + 1, "%06x", &v) == 1) {
        base.hasColor = true;
        base.color = {float((v >> 16) & 255) / 255.f, float((v >> 8) & 255) / 255.f, float(v & 255) / 255.f};
      } else {
        failAtKey(name, false, "color", "tile `" + name + "`: \"color\" must be a string \"#rrggbb\", got " + describe(t["color"]));
      }
    }
    base.background = background || empty;
    const int32_t first = int32_t(out.labels.size());
    if (empty) out.emptyLabel = first;
    tiles.push_back({name, sym, first});
    for (int v = 0; v < sym.cardinality; ++v) {
      Piece p = base;
      p.name = v == 0 ? name : name + "." + std::to_string(v);
      // Orientation v of X/L/T/I/\ is the base turned v times; F's 4..7 are mirrored.
      if (sym.cardinality == 8 && v >= 4) { p.mirrored = true; p.rotation = (4 - (v - 4)) % 4; }
      else p.rotation = v % 4;
      p.weight = base.weight / sym.cardinality;
      out.labels.push_back(p);
      tileOf.push_back(int32_t(tiles.size() - 1));
    }
  }
  if (diags.size() != diagStart) return false;
  const int k = out.labelCount();
  if (k == 0) { diags.push_back({fileName, 1, 1, "E712", "the tile set has no tiles", ""}); return false; }

  // Group action: g = (r, m) maps label t to a^r(b^m(t)) within its tile.
  auto act = [&](int32_t label, int r, int m) {
    const TileInfo& ti = tiles[size_t(tileOf[size_t(label)])];
    int v = label - ti.first;
    if (m) v = ti.sym.b(v);
    for (int i = 0; i < r; ++i) v = ti.sym.a(v);
    return ti.first + v;
  };
  out.rot90.resize(size_t(k));
  out.mirrorX.resize(size_t(k));
  out.mirrorY.resize(size_t(k));
  for (int32_t l = 0; l < k; ++l) {
    out.rot90[size_t(l)] = act(l, 1, 0);
    out.mirrorX[size_t(l)] = act(l, 0, 1);
    out.mirrorY[size_t(l)] = act(l, 2, 1);  // mirror y = turn 180° after mirroring x
  }

  auto resolve = [&](const json& v, int32_t& label) {
    if (!v.is_string()) return false;
    std::string s = v;
    std::string tname = s;
    int idx = 0;
    auto sp = s.find(' ');
    if (sp != std::string::npos) {
      tname = s.substr(0, sp);
      try { idx = std::stoi(s.substr(sp + 1)); } catch (...) { idx = -1; }
    }
    for (const auto& ti : tiles)
      if (ti.name == tname) {
        if (idx < 0 || idx >= 8) return false;
        // Like WFC, an orientation index past the tile's own count wraps through the group.
        label = act(ti.first, idx % 4, idx / 4);
        return true;
      }
    return false;
  };

  std::array<std::set<std::pair<int32_t, int32_t>>, 3> rules;
  bool anyZ = false;
  if (doc.contains("neighbors")) {
    if (!doc["neighbors"].is_array()) fail("neighbors", "\"neighbors\" must be an array");
    else
      for (const auto& n : doc["neighbors"]) {
        if (!n.is_object()) { fail("neighbors", "a neighbour rule is an object"); continue; }
        bool horizontal = n.contains("left") || n.contains("right");
        const char* k1 = horizontal ? "left" : "bottom";
        const char* k2 = horizontal ? "right" : "top";
        int32_t p = -1, q = -1;
        if (!n.contains(k1) || !n.contains(k2) || !resolve(n[k1], p) || !resolve(n[k2], q)) {
          fail(n.dump().size() > 2 ? (n.contains(k1) && n[k1].is_string() ? n[k1].get<std::string>() : "neighbors") : "neighbors",
               "bad neighbour rule " + n.dump() + ": expected {\"left\": \"TILE [N]\", \"right\": \"TILE [N]\"} or bottom/top with known tiles");
          continue;
        }
        anyZ |= !horizontal;
        for (int m = 0; m < 2; ++m)
          for (int r = 0; r < 4; ++r) {
            int32_t gp = act(p, r, m), gq = act(q, r, m);
            if (!horizontal) { rules[2].insert({gp, gq}); continue; }
            // Image of +x under g: mirror then turn r quarter turns.
            int dx = m ? -1 : 1, dy = 0;
            for (int i = 0; i < r; ++i) { int t = dx; dx = -dy; dy = t; }
            if (dx == 1) rules[0].insert({gp, gq});
            else if (dx == -1) rules[0].insert({gq, gp});
            else if (dy == 1) rules[1].insert({gp, gq});
            else rules[1].insert({gq, gp});
          }
      }
  }
  if (doc.contains("border") && !doc["border"].is_object()) {
    fail("border", "\"border\" must be an object {\"FACE\": \"LABEL\", ...}, got " + describe(doc["border"]));
  } else if (doc.contains("border")) {
    for (auto it = doc["border"].begin(); it != doc["border"].end(); ++it) {
      int face = faceFromName(it.key());
      bool fixed = false;
      json lab = it.value();
      if (it.value().is_object()) {
        FieldReader entry(it.value(), "border entry `" + it.key() + "`",
                          [&](const std::string& key, const std::string& msg) { failAtKey(it.key(), true, key, msg); });
        if (!entry.boolean("fixed", fixed)) continue;
        lab = it.value().contains("label") ? it.value()["label"] : json();
      }
      int32_t l = -1;
      if (face < 0 || !lab.is_string() || (l = out.findLabel(lab.get<std::string>())) < 0) {
        fail(it.key(), "bad border entry `" + it.key() + "`: expected FACE: \"LABEL\" with a face xmin..zmax and a known label");
        continue;
      }
      (fixed ? out.border.fixed : out.border.outside)[size_t(face)] = l;
    }
  }
  if (diags.size() != diagStart) return false;
  for (int a = 0; a < 3; ++a) out.allowed[a].assign(rules[a].begin(), rules[a].end());
  out.dims = anyZ ? 3 : 2;
  if (out.emptyLabel < 0)
    for (int32_t l = 0; l < k; ++l)
      if (out.labels[size_t(l)].background) { out.emptyLabel = l; break; }
  return true;
}

}  // namespace

bool parseTileSetJson(std::string_view text, const std::string& fileName, Example& out,
                      Diagnostics& diags) {
  out = Example{};
  out.path = fileName;
  json doc;
  try {
    doc = json::parse(text.begin(), text.end());
  } catch (const json::parse_error& e) {
    int line, col;
    std::string src;
    lineCol(text, e.byte > 0 ? e.byte - 1 : 0, line, col, src);
    std::string msg = e.what();
    auto p = msg.find("parse error");
    diags.push_back({fileName, line, col, "E711", "malformed JSON: " + (p == std::string::npos ? msg : msg.substr(p)), src});
    return false;
  } catch (const json::exception& e) {  // a number too large for a double (out_of_range)
    diags.push_back({fileName, 0, 0, "E711", std::string("malformed JSON: ") + e.what(), ""});
    return false;
  }
  try {
    return readTileSet(doc, text, fileName, out, diags);
  } catch (const json::exception& e) {
    // Every field is type-checked before it is read; this only keeps a missed case an
    // error about the file rather than an abort.
    diags.push_back({fileName, 0, 0, "E712", std::string("unexpected JSON content: ") + e.what(), ""});
    return false;
  }
}

}  // namespace fgsg::rt::synthesis
