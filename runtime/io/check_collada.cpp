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

// The element name of tag text `tag` (after '<' or '</').
std::string_view elementName(std::string_view tag) {
  const size_t end = tag.find_first_of(" \t\r\n/>");
  return tag.substr(0, end);
}

}  // namespace

bool checkColladaNodes(const std::string& path, std::string_view text, std::string& error) {
  std::vector<Node> nodes;
  std::vector<size_t> open;  // the <node> elements enclosing the scan
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
    } else if (name == "instance_node" && !end && !open.empty()) {
      std::string url = attribute(tag, "url");
      if (!url.empty() && url[0] == '#') nodes[open.back()].instances.push_back(url.substr(1));
    }
    at = close;
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
