#include "cli/view_message.h"

#include <nlohmann/json.hpp>

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
