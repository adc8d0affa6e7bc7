#include "cli/view_message.h"

#include <nlohmann/json.hpp>

#include <cctype>
#include <cmath>
#include <cstdint>

namespace fgsg::cli {

using Json = nlohmann::json;

namespace {

std::string quoted(const std::string& s) {
  return "'" + (s.size() > 60 ? s.substr(0, 60) + "...' (" + std::to_string(s.size()) + " bytes)" : s + "'");
}

// A value as --set writes it; false for anything but a short string, a finite number
// or a boolean.
bool valueText(const Json& v, std::string& text) {
  if (v.is_string()) {
    text = v.get<std::string>();
    return text.size() <= kMaxPageValueBytes && text.find('\0') == std::string::npos;
  }
  if (v.is_boolean()) {
    text = v.get<bool>() ? "true" : "false";
    return true;
  }
  if (v.is_number()) {
    if (v.is_number_float() && !std::isfinite(v.get<double>())) return false;
    text = v.dump();
    return true;
  }
  return false;
}

// A finite number within kMaxPageCoordinate.
bool coordinate(const Json& v, double& out) {
  if (!v.is_number()) return false;
  out = v.get<double>();
  return std::isfinite(out) && std::abs(out) <= kMaxPageCoordinate;
}

// A number from 0 to 1.
bool unit(const Json& v, double& out) { return v.is_number() && (out = v.get<double>()) >= 0 && out <= 1; }

// Only the fields in `allowed` besides "type".
bool onlyFields(const Json& j, std::initializer_list<const char*> allowed, const std::string& kind, std::string& reason) {
  for (const auto& [key, value] : j.items()) {
    if (key == "type") continue;
    bool known = false;
    for (const char* a : allowed) known = known || key == a;
    if (!known) {
      reason = kind + ": unknown field " + quoted(key);
      return false;
    }
  }
  return true;
}

bool parseSeeds(const Json& j, std::vector<PageSeed>& out, std::string& reason) {
  if (!onlyFields(j, {"seeds"}, "seeds", reason)) return false;
  const auto list = j.find("seeds");
  if (list == j.end() || !list->is_array() || list->size() > kMaxPageSeeds) {
    reason = "seeds: \"seeds\" must be a list of at most " + std::to_string(kMaxPageSeeds) + " seeds";
    return false;
  }
  for (const Json& s : *list) {
    PageSeed seed;
    bool ok = s.is_array() && (s.size() == 3 || s.size() == 6);
    for (size_t k = 0; ok && k < s.size(); ++k) ok = coordinate(s[k], k < 3 ? seed.point[k] : seed.direction[k - 3]);
    seed.hasDirection = ok && s.size() == 6;
    if (ok && seed.hasDirection) ok = std::hypot(seed.direction[0], seed.direction[1], seed.direction[2]) > 0;
    if (!ok) {
      reason = "seeds: seed " + std::to_string(out.size()) + " must be [x,y,z] or [x,y,z,dx,dy,dz] (finite, a non-zero heading)";
      return false;
    }
    out.push_back(seed);
  }
  return true;
}

bool parsePaint(const Json& j, PagePaint& out, std::string& reason) {
  if (!onlyFields(j, {"texture", "stroke", "dabs", "radius", "strength", "value", "erase"}, "paint", reason)) return false;
  const auto texture = j.find("texture");
  bool named = texture != j.end() && texture->is_string();
  if (named) {
    out.texture = texture->get<std::string>();
    named = !out.texture.empty() && out.texture.size() <= kMaxPageNameBytes;
    for (const char c : out.texture) named = named && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
  }
  if (!named) {
    reason = "paint: \"texture\" must name one of the grammar's textures (letters, digits, _)";
    return false;
  }
  const auto stroke = j.find("stroke");
  if (stroke == j.end() || !stroke->is_number_unsigned()) {
    reason = "paint: \"stroke\" must be a whole number from 0";
    return false;
  }
  out.stroke = stroke->get<uint64_t>();
  const auto dabs = j.find("dabs");
  if (dabs == j.end() || !dabs->is_array() || dabs->empty() || dabs->size() > kMaxPageDabs) {
    reason = "paint: \"dabs\" must be a list of 1 to " + std::to_string(kMaxPageDabs) + " points [x,y,z]";
    return false;
  }
  for (const Json& d : *dabs) {
    std::array<double, 3> p{};
    bool ok = d.is_array() && d.size() == 3;
    for (size_t k = 0; ok && k < 3; ++k) ok = coordinate(d[k], p[k]);
    if (!ok) {
      reason = "paint: every dab must be [x,y,z] of finite numbers";
      return false;
    }
    out.dabs.push_back(p);
  }
  const auto radius = j.find("radius");
  if (radius == j.end() || !coordinate(*radius, out.radius) || !(out.radius > 0)) {
    reason = "paint: \"radius\" must be a positive finite number";
    return false;
  }
  for (const auto& [key, target] : {std::pair<const char*, double*>{"strength", &out.strength}, {"value", &out.value}}) {
    const auto it = j.find(key);
    if (it != j.end() && !unit(*it, *target)) {
      reason = std::string("paint: \"") + key + "\" must be a number from 0 to 1";
      return false;
    }
  }
  if (const auto erase = j.find("erase"); erase != j.end()) {
    if (!erase->is_boolean()) {
      reason = "paint: \"erase\" must be true or false";
      return false;
    }
    out.erase = erase->get<bool>();
  }
  return true;
}

// A point [x,y,z] of finite numbers within kMaxPageCoordinate.
bool pagePoint(const Json& v, double (&out)[3]) {
  bool ok = v.is_array() && v.size() == 3;
  for (size_t k = 0; ok && k < 3; ++k) ok = coordinate(v[k], out[k]);
  return ok;
}

constexpr const char* kPageElementKinds[] = {"regular", "wedge", "trisector", "node", "centre", "saddle"};

// {"type":"fieldElement", "op":..., ...}: each operation takes its own words and no other.
bool parseFieldElement(const Json& j, PageFieldElement& out, std::string& reason) {
  const auto op = j.find("op");
  const std::string name = op != j.end() && op->is_string() ? op->get<std::string>() : "";
  if (name == "add") {
    out.op = PageFieldElement::Op::Add;
    if (!onlyFields(j, {"op", "kind", "position", "direction", "strength"}, "fieldElement add", reason)) return false;
  } else if (name == "move") {
    out.op = PageFieldElement::Op::Move;
    if (!onlyFields(j, {"op", "index", "position", "drag"}, "fieldElement move", reason)) return false;
  } else if (name == "delete") {
    out.op = PageFieldElement::Op::Delete;
    if (!onlyFields(j, {"op", "index"}, "fieldElement delete", reason)) return false;
  } else if (name == "strength") {
    out.op = PageFieldElement::Op::Strength;
    if (!onlyFields(j, {"op", "index", "strength"}, "fieldElement strength", reason)) return false;
  } else {
    reason = "fieldElement: \"op\" must be \"add\", \"move\", \"delete\" or \"strength\"";
    return false;
  }
  if (out.op != PageFieldElement::Op::Add) {
    const auto index = j.find("index");
    if (index == j.end() || !index->is_number_unsigned() || index->get<uint64_t>() >= kMaxPageElementIndex) {
      reason = "fieldElement " + name + ": \"index\" must be a whole number from 0 to " +
               std::to_string(kMaxPageElementIndex - 1);
      return false;
    }
    out.index = static_cast<uint32_t>(index->get<uint64_t>());
  } else {
    const auto kind = j.find("kind");
    bool known = false;
    if (kind != j.end() && kind->is_string())
      for (const char* k : kPageElementKinds) known = known || kind->get<std::string>() == k;
    if (!known) {
      reason = "fieldElement add: \"kind\" must be regular, wedge, trisector, node, centre or saddle";
      return false;
    }
    out.kind = kind->get<std::string>();
  }
  if (out.op == PageFieldElement::Op::Add || out.op == PageFieldElement::Op::Move) {
    const auto position = j.find("position");
    if (position == j.end() || !pagePoint(*position, out.position)) {
      reason = "fieldElement " + name + ": \"position\" must be [x,y,z] of finite numbers";
      return false;
    }
  }
  if (const auto direction = j.find("direction"); direction != j.end()) {
    if (out.kind != "regular") {
      reason = "fieldElement add: only a regular element takes a \"direction\"";
      return false;
    }
    if (!pagePoint(*direction, out.direction) || !(std::hypot(out.direction[0], out.direction[1], out.direction[2]) > 0)) {
      reason = "fieldElement add: \"direction\" must be [dx,dy,dz] of finite numbers, not all 0";
      return false;
    }
    out.hasDirection = true;
  }
  const auto strength = j.find("strength");
  if (strength != j.end() || out.op == PageFieldElement::Op::Strength) {
    if (strength == j.end() || !strength->is_number() || !std::isfinite(out.strength = strength->get<double>()) ||
        std::abs(out.strength) > kMaxPageElementStrength) {
      reason = "fieldElement " + name + ": \"strength\" must be a number from -1000 to 1000";
      return false;
    }
    out.hasStrength = true;
  }
  if (const auto drag = j.find("drag"); drag != j.end()) {
    if (!drag->is_number_unsigned() || drag->get<uint64_t>() == 0 || drag->get<uint64_t>() > kMaxPageDrag) {
      reason = "fieldElement move: \"drag\" must be a whole number from 1 to " + std::to_string(kMaxPageDrag);
      return false;
    }
    out.drag = drag->get<uint64_t>();
  }
  return true;
}

// {"type":"undo"|"redo", "history":"paint"|"field"}: the paint strokes' (the default) or
// the field design edits'.
bool parseUndoRedo(const Json& j, const std::string& kind, PageRequest& out, std::string& reason) {
  out.kind = kind == "undo" ? PageRequest::Kind::Undo : PageRequest::Kind::Redo;
  if (!onlyFields(j, {"history"}, kind, reason)) return false;
  const auto history = j.find("history");
  if (history == j.end()) return true;
  if (*history == "field") out.history = PageRequest::History::Field;
  else if (*history != "paint") {
    reason = kind + ": \"history\" must be \"paint\" or \"field\"";
    return false;
  }
  return true;
}

}  // namespace

bool jsonNestingWithin(const std::string& text, int limit) {
  int depth = 0;
  bool inString = false, escaped = false;
  for (const char c : text) {
    if (inString) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > limit) return false;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return true;
}

bool parsePageRequest(const std::string& text, PageRequest& out, std::string& reason) {
  out = PageRequest{};
  if (text.size() > kMaxPageMessageBytes) {
    reason = "message of " + std::to_string(text.size()) + " bytes (at most " + std::to_string(kMaxPageMessageBytes) + ")";
    return false;
  }
  // JSON text holds no raw NUL (a string spells it \u0000), and the parser would stop at
  // one, taking what precedes it for the whole message.
  if (const size_t nul = text.find('\0'); nul != std::string::npos) {
    reason = "a NUL byte at byte " + std::to_string(nul) + " (not JSON text)";
    return false;
  }
  if (!jsonNestingWithin(text, kMaxPageMessageDepth)) {
    reason = "message nested deeper than " + std::to_string(kMaxPageMessageDepth) + " levels";
    return false;
  }
  const Json j = Json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object()) {
    reason = "not a JSON object";
    return false;
  }
  const auto type = j.find("type");
  if (type == j.end() || !type->is_string()) {
    reason = "no \"type\"";
    return false;
  }
  const std::string kind = type->get<std::string>();
  if (kind == "pick") {
    out.kind = PageRequest::Kind::Pick;
    bool found = false;
    for (const auto& [key, value] : j.items()) {
      if (key == "type") continue;
      if (key != "instance") {
        reason = "pick: unknown field " + quoted(key);
        return false;
      }
      if (!value.is_number_unsigned() || value.get<uint64_t>() > UINT32_MAX) {
        reason = "pick: \"instance\" must be a whole number from 0 to 4294967295";
        return false;
      }
      out.instance = static_cast<uint32_t>(value.get<uint64_t>());
      found = true;
    }
    if (!found) reason = "pick: no \"instance\"";
    return found;
  }
  if (kind == "seeds") {
    out.kind = PageRequest::Kind::Seeds;
    return parseSeeds(j, out.seeds, reason);
  }
  if (kind == "paint") {
    out.kind = PageRequest::Kind::Paint;
    return parsePaint(j, out.paint, reason);
  }
  if (kind == "field") {  // the field overlay (view_field.h)
    out.kind = PageRequest::Kind::Field;
    return onlyFields(j, {}, kind, reason);
  }
  if (kind == "resend") {  // the page could not show pieces it was sent: all of them again
    out.kind = PageRequest::Kind::Resend;
    return onlyFields(j, {}, kind, reason);
  }
  if (kind == "fieldElement") {  // a design element edited (view_field_edit.h)
    out.kind = PageRequest::Kind::FieldElement;
    return parseFieldElement(j, out.element, reason);
  }
  if (kind == "undo" || kind == "redo") return parseUndoRedo(j, kind, out, reason);
  if (kind != "set") {
    reason = "unknown message type " + quoted(kind);
    return false;
  }
  out.kind = PageRequest::Kind::Set;
  for (const auto& [key, value] : j.items()) {
    if (key == "type") continue;
    if (key == "seed") {
      if (!value.is_number_unsigned()) {
        reason = "set: \"seed\" must be a whole number from 0";
        return false;
      }
      out.hasSeed = true;
      out.seed = value.get<uint64_t>();
    } else if (key == "step") {
      if (!value.is_number_unsigned() || value.get<uint64_t>() > kMaxPageStep) {
        reason = "set: \"step\" must be a whole number from 0 to " + std::to_string(kMaxPageStep);
        return false;
      }
      out.hasStep = true;
      out.step = static_cast<uint32_t>(value.get<uint64_t>());
    } else if (key == "attrs") {
      if (!value.is_object() || value.size() > kMaxPageAttrs) {
        reason = "set: \"attrs\" must be an object of at most " + std::to_string(kMaxPageAttrs) + " names";
        return false;
      }
      out.hasAttrs = true;
      for (const auto& [name, v] : value.items()) {
        std::string text;
        if (name.empty() || name.size() > kMaxPageNameBytes) {
          reason = "set: attribute name " + quoted(name) + " is empty or too long";
          return false;
        }
        if (!valueText(v, text)) {
          reason = "set: attribute " + quoted(name) + " must be a string (at most " + std::to_string(kMaxPageValueBytes) +
                   " bytes), a finite number or a boolean";
          return false;
        }
        out.attrs.emplace_back(name, std::move(text));
      }
    } else {
      reason = "set: unknown field " + quoted(key);
      return false;
    }
  }
  return true;
}

}  // namespace fgsg::cli
