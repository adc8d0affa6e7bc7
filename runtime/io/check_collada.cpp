#include "runtime/io/check_collada.h"

#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace fgsg::rt::io {

namespace {

struct Node {
  std::string id;
  size_t offset = 0;                  // of its start tag, for the line
  std::vector<size_t> children;       // nested <node> elements
  std::vector<std::string> instances; // <instance_node url="#id">, without the '#'
};

// The value of attribute `name` in the tag text `tag` ("" when absent).
std::string attribute(std::string_view tag, std::string_view name) {
  for (size_t at = tag.find(name); at != std::string_view::npos; at = tag.find(name, at + 1)) {
    if (at == 0 || !(tag[at - 1] == ' ' || tag[at - 1] == '\t' || tag[at - 1] == '\n' || tag[at - 1] == '\r')) continue;
    size_t p = at + name.size();
    while (p < tag.size() && (tag[p] == ' ' || tag[p] == '\t')) ++p;
    if (p >= tag.size() || tag[p] != '=') continue;
    ++p;
    while (p < tag.size() && (tag[p] == ' ' || tag[p] == '\t')) ++p;
    if (p >= tag.size() || (tag[p] != '"' && tag[p] != '\'')) continue;
    const size_t end = tag.find(tag[p], p + 1);
    if (end == std::string_view::npos) return {};
    return std::string(tag.substr(p + 1, end - p - 1));
  }
  return {};
}

// An unsigned attribute as assimp reads it (pugixml: decimal, or hexadecimal after 0x;
// anything else 0), clamped to 32 bits.
uint64_t unsignedAttribute(std::string_view tag, std::string_view name, uint64_t otherwise) {
  const std::string text = attribute(tag, name);
  if (text.empty()) return otherwise;
  size_t i = text.find_first_not_of(" \t\r\n");
  if (i == std::string::npos) return 0;
  int base = 10;
  if (text.compare(i, 2, "0x") == 0 || text.compare(i, 2, "0X") == 0) base = 16, i += 2;
  uint64_t v = 0;
  for (; i < text.size(); ++i) {
    const char c = text[i];
    const int d = c >= '0' && c <= '9' ? c - '0' : base == 16 && c >= 'a' && c <= 'f' ? c - 'a' + 10
                : base == 16 && c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1;
    if (d < 0) break;
    v = std::min<uint64_t>(v * uint64_t(base) + uint64_t(d), UINT32_MAX);
  }
  return v;
}

// An <accessor>: what it reads of its source array.
struct Accessor {
  std::string source;  // the array's id, without the '#'
  uint64_t count = 0, stride = 1, offset = 0, params = 0;
  size_t at = 0;
};

// Whitespace-separated words in `content`.
uint64_t wordCount(std::string_view content) {
  uint64_t n = 0;
  bool inWord = false;
  for (const char c : content) {
    const bool space = c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
    n += !space && !inWord;
    inWord = !space;
  }
  return n;
}

bool isPrimitive(std::string_view name) {
  return name == "triangles" || name == "polylist" || name == "polygons" || name == "lines" || name == "linestrips" ||
         name == "tristrips" || name == "trifans";
}

// The element name of tag text `tag` (after '<' or '</').
std::string_view elementName(std::string_view tag) {
  const size_t end = tag.find_first_of(" \t\r\n/>");
  return tag.substr(0, end);
}

}  // namespace

bool checkColladaNodes(const std::string& path, std::string_view text, std::string& error) {
  std::vector<Node> nodes;
  std::vector<size_t> open;  // the <node> elements enclosing the scan
  std::unordered_map<std::string, std::pair<uint64_t, std::string>> arrays;  // id -> count, element
  std::vector<Accessor> accessors;
  bool inAccessor = false;
  // The primitive element being read (<triangles count="4"> ...): its count, the words of
  // its index lists so far, its name and where it starts.
  struct Primitive {
    uint64_t count = 0, words = 0;
    std::string name;
    size_t at = 0;
  };
  std::vector<Primitive> primitives;
  const auto lineAt = [&](size_t offset) { return std::to_string(1 + std::count(text.begin(), text.begin() + long(offset), '\n')); };
  for (size_t at = text.find('<'); at != std::string_view::npos; at = text.find('<', at + 1)) {
    if (text.compare(at, 4, "<!--") == 0) {
      at = text.find("-->", at);
      if (at == std::string_view::npos) break;
      continue;
    }
    if (text.compare(at, 9, "<![CDATA[") == 0) {
      at = text.find("]]>", at);
      if (at == std::string_view::npos) break;
      continue;
    }
    const size_t close = text.find('>', at);
    if (close == std::string_view::npos) break;
    const std::string_view tag = text.substr(at + 1, close - at - 1);
    const bool end = !tag.empty() && tag[0] == '/';
    const bool empty = !tag.empty() && tag.back() == '/';
    const std::string_view name = elementName(end ? tag.substr(1) : tag);
    if (name == "node") {
      if (end) {
        if (!open.empty()) open.pop_back();
      } else {
        const size_t index = nodes.size();
        nodes.push_back({attribute(tag, "id"), at, {}, {}});
        if (!open.empty()) nodes[open.back()].children.push_back(index);
        if (!empty) open.push_back(index);
      }
    } else if (name.size() > 6 && name.substr(name.size() - 6) == "_array" && !end) {
      // assimp reserves the declared count before it reads the values.
      const std::string id = attribute(tag, "id");
      const uint64_t count = unsignedAttribute(tag, "count", 0);
      const size_t next = text.find('<', close);
      const uint64_t words = empty ? 0 : wordCount(text.substr(close + 1, next == std::string_view::npos ? 0 : next - close - 1));
      if (count > words) {
        error = path + ":" + lineAt(at) + ": <" + std::string(name) + "> '" + id + "' declares " + std::to_string(count) +
                " values but holds " + std::to_string(words);
        return false;
      }
      if (!id.empty()) arrays[id] = {count, std::string(name)};
    } else if (isPrimitive(name)) {
      if (end && !primitives.empty()) {
        // assimp reserves room for the declared count of primitives before reading them: a
        // primitive takes at least one index.
        const Primitive& p = primitives.back();
        if (p.count > p.words) {
          error = path + ":" + lineAt(p.at) + ": <" + p.name + "> declares " + std::to_string(p.count) +
                  " primitives but its index lists hold " + std::to_string(p.words) + " numbers";
          return false;
        }
        primitives.pop_back();
      } else if (!end && !empty) {
        primitives.push_back({unsignedAttribute(tag, "count", 0), 0, std::string(name), at});
      }
    } else if ((name == "p" || name == "vcount" || name == "v" || name == "h") && !end && !empty) {
      // assimp reads index lists number by number until the text ends, and a character
      // that is neither a digit, a sign nor a space stops it from advancing: it appends
      // zeros until memory runs out.
      const size_t next = text.find('<', close);
      const std::string_view content = text.substr(close + 1, next == std::string_view::npos ? 0 : next - close - 1);
      for (size_t i = 0; i < content.size(); ++i) {
        const char c = content[i];
        if ((c >= '0' && c <= '9') || c == '+' || c == '-' || c == ' ' || c == '\t' || c == '\r' || c == '\n' ||
            c == '\f' || c == '\v')
          continue;
        const unsigned char u = static_cast<unsigned char>(c);
        error = path + ":" + lineAt(close + 1 + i) + ": <" + std::string(name) + "> holds " +
                (u >= 0x20 && u < 0x7F ? "'" + std::string(1, c) + "'" : "the byte 0x" + std::string(1, "0123456789abcdef"[u >> 4]) +
                                                                           std::string(1, "0123456789abcdef"[u & 15])) +
                ", which is not part of a whole number (indices are whole numbers separated by spaces)";
        return false;
      }
      if (!primitives.empty() && name != "vcount") primitives.back().words += wordCount(content);
    } else if (name == "accessor") {
      inAccessor = !end && !empty;
      if (!end) {
        const std::string source = attribute(tag, "source");
        accessors.push_back({source.empty() || source[0] != '#' ? std::string() : source.substr(1),
                             unsignedAttribute(tag, "count", 0), unsignedAttribute(tag, "stride", 1),
                             unsignedAttribute(tag, "offset", 0), 0, at});
      }
    } else if (name == "param" && !end && inAccessor && !accessors.empty()) {
      ++accessors.back().params;
    } else if (name == "instance_node" && !end && !open.empty()) {
      std::string url = attribute(tag, "url");
      if (!url.empty() && url[0] == '#') nodes[open.back()].instances.push_back(url.substr(1));
    }
    at = close;
  }
  // assimp reads an accessor's elements from its array without comparing them with the
  // array's size (an empty array is a null pointer): every element must lie within it.
  for (const Accessor& a : accessors) {
    const auto array = arrays.find(a.source);
    if (a.count == 0 || array == arrays.end()) continue;  // none read, or assimp's own error
    const uint64_t need = a.offset + (a.count - 1) * a.stride + std::max<uint64_t>(a.params, 1);
    if (need > array->second.first) {
      error = path + ":" + std::to_string(1 + std::count(text.begin(), text.begin() + long(a.at), '\n')) +
              ": an <accessor> of " + std::to_string(a.count) + " elements (stride " + std::to_string(a.stride) +
              ", offset " + std::to_string(a.offset) + ", " + std::to_string(a.params) + " params) reads " +
              std::to_string(need) + " values of <" + array->second.second + "> '" + a.source + "', which holds " +
              std::to_string(array->second.first);
      return false;
    }
  }

  std::unordered_map<std::string, size_t> byId;
  for (size_t i = 0; i < nodes.size(); ++i)
    if (!nodes[i].id.empty()) byId.emplace(nodes[i].id, i);
  const auto lineOf = [&](size_t n) {
    return std::to_string(1 + std::count(text.begin(), text.begin() + long(nodes[n].offset), '\n'));
  };
  const auto name = [&](size_t n) { return nodes[n].id.empty() ? std::string("(no id)") : "'" + nodes[n].id + "'"; };

  // How many nodes each expands to (itself, its nested nodes, its instances), depth first
  // without recursion; a node met again while it is being expanded is a cycle.
  enum : uint8_t { Unseen, Expanding, Done };
  std::vector<uint8_t> state(nodes.size(), Unseen);
  std::vector<uint64_t> size(nodes.size(), 0);
  const auto targets = [&](size_t n) {
    std::vector<size_t> out = nodes[n].children;
    for (const std::string& id : nodes[n].instances)
      if (const auto it = byId.find(id); it != byId.end()) out.push_back(it->second);
    return out;
  };
  for (size_t root = 0; root < nodes.size(); ++root) {
    if (state[root] != Unseen) continue;
    std::vector<std::pair<size_t, std::vector<size_t>>> stack;
    stack.push_back({root, targets(root)});
    state[root] = Expanding;
    while (!stack.empty()) {
      auto& [n, pending] = stack.back();
      if (pending.empty()) {
        uint64_t total = 1;
        for (size_t t : targets(n)) total = std::min<uint64_t>(total + size[t], UINT64_MAX / 2);
        size[n] = total;
        state[n] = Done;
        if (total > kMaxColladaNodes) {
          error = path + ":" + lineOf(n) + ": node " + name(n) + " expands to " + std::to_string(total) +
                  " nodes through <instance_node> (each instance is a copy), more than " +
                  std::to_string(kMaxColladaNodes);
          return false;
        }
        stack.pop_back();
        continue;
      }
      const size_t next = pending.back();
      pending.pop_back();
      if (state[next] == Expanding) {
        error = path + ":" + lineOf(next) + ": node " + name(next) +
                " contains itself through <instance_node> (the node graph has a cycle)";
        return false;
      }
      if (state[next] == Unseen) {
        state[next] = Expanding;
        stack.push_back({next, targets(next)});
      }
    }
  }
  return true;
}

}  // namespace fgsg::rt::io
