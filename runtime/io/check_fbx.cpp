#include "runtime/io/check_fbx.h"

#include "runtime/memory_budget.h"

#include <algorithm>
#include <cstring>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace fgsg::rt::io {

namespace {

// What assimp holds for one node of the hierarchy, with what the surface reader builds
// from it (measured: 2^17 nodes of a 3 KB file took 584 MB).
constexpr uint64_t kFbxBytesPerNode = 4096;

// A model, or a connection of one object (the child) to another (its parent).
struct Model {
  std::string name;
  std::string where;  // "LINE" (ASCII) or "byte N" (binary), for messages
};
struct Link {
  int64_t child = 0, parent = 0;
  std::string where;
};

struct Graph {
  std::unordered_map<int64_t, Model> models;
  std::unordered_set<int64_t> objects{0};  // the root is object 0
  std::vector<Link> links;
};

// "PATH:LINE: " or "PATH: byte N: ".
std::string place(const std::string& path, const std::string& where) {
  return where.rfind("byte ", 0) == 0 ? path + ": " + where + ": " : path + ":" + where + ": ";
}

std::string modelName(int64_t id, const Model& m) {
  std::string name = m.name.substr(0, m.name.find('\0'));  // binary: "m0\0\1Model"
  if (name.rfind("Model::", 0) == 0) name = name.substr(7);
  if (name.size() > 60) name = name.substr(0, 60) + "...";
  for (char& c : name)
    if (static_cast<unsigned char>(c) < 0x20) c = '?';
  return "model " + std::to_string(id) + (name.empty() ? std::string() : " ('" + name + "')");
}

// Walks the hierarchy from the root as assimp builds it (each connection of a model to a
// parent is one copy of the model and all below it), iteratively: the nodes each model
// expands to are counted once, and added up once per connection.
bool checkHierarchy(const std::string& path, const Graph& g, uint64_t memoryLimit, std::string& error) {
  std::unordered_map<int64_t, std::vector<const Link*>> children;
  for (const Link& l : g.links)
    if (g.models.count(l.child) && g.objects.count(l.parent)) children[l.parent].push_back(&l);
  std::unordered_map<int64_t, uint64_t> size;  // of the models done: nodes, itself included
  std::unordered_set<int64_t> onPath{0};
  struct Frame {
    int64_t id;
    const std::vector<const Link*>* kids;
    size_t next = 0;
    uint64_t total = 1;
  };
  auto kidsOf = [&](int64_t id) {
    static const std::vector<const Link*> none;
    const auto k = children.find(id);
    return k == children.end() ? &none : &k->second;
  };
  std::vector<Frame> stack{{0, kidsOf(0)}};
  while (!stack.empty()) {
    Frame& f = stack.back();
    if (f.next == f.kids->size()) {
      const Frame done = f;
      stack.pop_back();
      onPath.erase(done.id);
      size[done.id] = done.total;
      if (stack.empty()) break;
      stack.back().total += done.total;  // each at most kMaxFbxNodes + 1: no overflow
    } else {
      const Link& l = *(*f.kids)[f.next++];
      if (onPath.count(l.child)) {
        error = place(path, l.where) + modelName(l.child, g.models.at(l.child)) +
                " is connected below itself (a cycle of connections): a node hierarchy is a tree";
        return false;
      }
      if (const auto known = size.find(l.child); known != size.end()) {
        f.total += known->second;
      } else {
        if (stack.size() > kMaxFbxDepth) {
          error = place(path, l.where) + modelName(l.child, g.models.at(l.child)) + " is nested deeper than " +
                  std::to_string(kMaxFbxDepth) + " levels of models";
          return false;
        }
        onPath.insert(l.child);
        stack.push_back({l.child, kidsOf(l.child)});
        continue;
      }
    }
    // The root is assimp's own node: the file's nodes are the others.
    if (stack.back().total > kMaxFbxNodes + 1) {
      const Frame& top = stack.back();
      const Link& l = *(*top.kids)[top.next - 1];
      error = place(path, l.where) + "the models' connections expand to more than " + std::to_string(kMaxFbxNodes) +
              " nodes (here " + modelName(l.child, g.models.at(l.child)) +
              " is placed once more, with all below it): a model connected to parents more than once is copied "
              "for each connection, with everything below it";
      return false;
    }
  }
  const uint64_t nodes = size[0] - 1;  // the root is assimp's own
  if (nodes * kFbxBytesPerNode > memoryLimit) {
    error = path + ": its models' connections expand to " + std::to_string(nodes) + " nodes, about " +
            formatMemorySize(nodes * kFbxBytesPerNode) + " to read, more than the memory limit of " +
            formatMemorySize(memoryLimit) + " (--max-memory)";
    return false;
  }
  return true;
}

// ---- ASCII: key: value, value { ... } with ; comments, as assimp's tokenizer reads it.


bool asciiGraph(const std::string& path, std::string_view s, Graph& g, std::string& error) {
  // Elements: a key, its values, and maybe a { scope }. Of interest: the elements of the
  // top-level scopes Objects (Model: ID, "Model::name", ...) and Connections (C: "OO",
  // child, parent), whose first four values are collected as the tokens stream by (a
  // file's vertex arrays are not kept).
  std::vector<std::string_view> scopes;  // the keys of the open scopes
  std::string_view lastKey;
  struct Value {
    bool string;
    std::string_view text;
  };
  std::string_view pendingKey;  // an element of interest whose values are being collected
  size_t pendingLine = 0;
  std::vector<Value> values;
  const auto id = [](const Value& v, int64_t& out) {
    if (v.string || v.text.empty()) return false;
    const std::string text(v.text);
    char* end = nullptr;
    out = text[0] == '-' ? int64_t(std::strtoll(text.c_str(), &end, 10)) : int64_t(std::strtoull(text.c_str(), &end, 10));
    return end && *end == '\0';
  };
  const auto finish = [&] {
    if (pendingKey.empty()) return;
    int64_t a = 0, b = 0;
    if (scopes[0] == "Objects" && !values.empty() && id(values[0], a)) {
      g.objects.insert(a);
      if (pendingKey == "Model")
        g.models[a] = {values.size() > 1 ? std::string(values[1].text) : std::string(), std::to_string(pendingLine)};
    } else if (scopes[0] == "Connections" && pendingKey == "C" && values.size() >= 3 && values[0].string &&
               (values[0].text == "OO" || (values[0].text == "OP" && (values.size() < 4 || values[3].text.empty()))) &&
               id(values[1], a) && id(values[2], b)) {
      g.links.push_back({a, b, std::to_string(pendingLine)});
    }
    pendingKey = {};
    values.clear();
  };
  enum Kind { Word, String, Key, Open, Close, Comma };
  // One token: false on an error.
  const auto token = [&](Kind kind, std::string_view text, size_t line) {
    if (!pendingKey.empty()) {
      if (kind == Comma) return true;
      if ((kind == Word || kind == String) && values.size() < 4) {
        values.push_back({kind == String, text});
        return true;
      }
      finish();
    }
    if (kind == Open) {
      if (scopes.size() >= kMaxFbxNesting) {
        error = path + ":" + std::to_string(line) + ": the file's scopes nest deeper than " +
                std::to_string(kMaxFbxNesting) + " levels";
        return false;
      }
      scopes.push_back(lastKey);
    } else if (kind == Close) {
      if (!scopes.empty()) scopes.pop_back();
    } else if (kind == Key) {
      lastKey = text;
      if (scopes.size() == 1 && (scopes[0] == "Objects" || scopes[0] == "Connections") && !text.empty()) {
        pendingKey = text;
        pendingLine = line;
      }
    }
    return true;
  };
  size_t line = 1;
  for (size_t i = 0; i < s.size();) {
    const char c = s[i];
    bool ok = true;
    if (c == '\n') {
      ++line, ++i;
    } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v' || c == ':') {
      ++i;  // (a ':' not after a word ends nothing)
    } else if (c == ';') {
      while (i < s.size() && s[i] != '\n') ++i;
    } else if (c == '"') {
      const size_t end = s.find('"', i + 1);
      const size_t stop = end == std::string_view::npos ? s.size() : end;
      ok = token(String, s.substr(i + 1, stop - i - 1), line);
      line += size_t(std::count(s.begin() + long(i), s.begin() + long(stop), '\n'));
      i = stop + 1;
    } else if (c == '{' || c == '}' || c == ',') {
      ok = token(c == '{' ? Open : c == '}' ? Close : Comma, s.substr(i, 1), line);
      ++i;
    } else {
      // A word: up to a space or a character the branches above take (a NUL byte is part
      // of a word: strchr would find the set's own terminator for it, and the scan would
      // stop there without advancing).
      size_t end = i + 1;
      while (end < s.size() && (s[end] == '\0' || !std::strchr(" \t\r\n\f\v;\"{},:", s[end]))) ++end;
      const bool key = end < s.size() && s[end] == ':';
      ok = token(key ? Key : Word, s.substr(i, end - i), line);
      i = end + (key ? 1 : 0);
    }
    if (!ok) return false;
  }
  if (!pendingKey.empty()) finish();
  return true;
}

// ---- Binary: records of (end offset, property count, property bytes, name, properties,
// nested records), 32-bit offsets before version 7500 and 64-bit from it.

struct Binary {
  std::string_view s;
  bool wide = false;
  Graph& g;
  const std::string& path;
  std::string& error;

  uint64_t number(size_t at, int bytes) const {
    uint64_t v = 0;
    for (int i = bytes - 1; i >= 0; --i) v = v << 8 | uint8_t(s[at + size_t(i)]);
    return v;
  }

  // The leading scalar properties of a record: 'L' ids and 'S' strings (others end it).
  struct Property {
    char type;
    int64_t id = 0;
    std::string_view text;
  };
  std::vector<Property> properties(size_t at, size_t end, uint64_t count) const {
    std::vector<Property> out;
    for (uint64_t i = 0; i < count && i < 4 && at < end; ++i) {
      const char type = s[at++];
      if (type == 'L' && at + 8 <= end) {
        out.push_back({type, int64_t(number(at, 8)), {}});
        at += 8;
      } else if ((type == 'S' || type == 'R') && at + 4 <= end && number(at, 4) <= end - at - 4) {
        const size_t n = size_t(number(at, 4));
        out.push_back({type, 0, s.substr(at + 4, n)});
        at += 4 + n;
      } else {
        break;
      }
    }
    return out;
  }

  // The records from `at` to `end` (a null record ends them early); false on an error.
  bool list(size_t at, size_t end, size_t depth, std::string_view parent) {
    const size_t header = wide ? 25 : 13;
    while (at + header <= end) {
      const uint64_t recordEnd = number(at, wide ? 8 : 4);
      const uint64_t count = number(at + (wide ? 8 : 4), wide ? 8 : 4);
      const uint64_t propertyBytes = number(at + (wide ? 16 : 8), wide ? 8 : 4);
      const size_t nameLength = uint8_t(s[at + header - 1]);
      if (recordEnd == 0) return true;  // the null record that closes a list
      if (recordEnd <= at || recordEnd > end || at + header + nameLength > recordEnd ||
          propertyBytes > recordEnd - at - header - nameLength)
        return true;  // not a structure this scan can walk: assimp says what is wrong
      const std::string_view name = s.substr(at + header, nameLength);
      const size_t props = at + header + nameLength;
      const std::string where = "byte " + std::to_string(at);
      if (depth == 1 && parent == "Objects") {
        const auto p = properties(props, props + size_t(propertyBytes), count);
        if (!p.empty() && p[0].type == 'L') {
          g.objects.insert(p[0].id);
          if (name == "Model") g.models[p[0].id] = {p.size() > 1 ? std::string(p[1].text) : std::string(), where};
        }
      } else if (depth == 1 && parent == "Connections" && name == "C") {
        const auto p = properties(props, props + size_t(propertyBytes), count);
        if (p.size() >= 3 && p[0].type == 'S' && p[1].type == 'L' && p[2].type == 'L' &&
            (p[0].text == "OO" || (p[0].text == "OP" && (p.size() < 4 || p[3].text.empty()))))
          g.links.push_back({p[1].id, p[2].id, where});
      }
      const size_t nested = props + size_t(propertyBytes);
      if (nested < recordEnd) {
        if (depth + 1 >= kMaxFbxNesting) {
          error = path + ": " + where + ": the file's records nest deeper than " + std::to_string(kMaxFbxNesting) + " levels";
          return false;
        }
        if (!list(nested, size_t(recordEnd), depth + 1, name)) return false;
      }
      at = size_t(recordEnd);
    }
    return true;
  }
};

}  // namespace

bool checkFbxNodes(const std::string& path, std::string_view bytes, uint64_t memoryLimit, std::string& error) {
  Graph g;
  static constexpr char kBinary[] = "Kaydara FBX Binary  ";
  if (bytes.substr(0, sizeof kBinary - 1) == kBinary) {
    if (bytes.size() < 27) return true;  // assimp says it is truncated
    Binary b{bytes, false, g, path, error};
    const uint64_t version = b.number(23, 4);
    b.wide = version >= 7500;
    if (!b.list(27, bytes.size(), 0, "")) return false;
  } else if (!asciiGraph(path, bytes, g, error)) {
    return false;
  }
  return checkHierarchy(path, g, memoryLimit, error);
}

}  // namespace fgsg::rt::io
