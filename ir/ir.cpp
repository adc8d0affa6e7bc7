#include "ir/ir.h"

namespace fgsg::ir {

const char* typeName(Type t) {
  switch (t) {
    case Type::Num: return "num";
    case Type::Bool: return "bool";
    case Type::Str: return "str";
    case Type::Vec3: return "vec3";
  }
  return "?";
}

Expr Expr::number(double v) {
  Expr e;
  e.type = Type::Num;
  e.num = v;
  return e;
}

Expr Expr::boolean(bool v) {
  Expr e;
  e.type = Type::Bool;
  e.num = v ? 1.0 : 0.0;
  return e;
}

Expr Expr::string(uint32_t id) {
  Expr e;
  e.type = Type::Str;
  e.num = static_cast<double>(id);
  return e;
}

namespace {

// Tables are small (tens of entries), so a linear search keeps them plain vectors.
uint32_t intern(std::vector<std::string>& table, const std::string& s) {
  for (size_t i = 0; i < table.size(); ++i)
    if (table[i] == s) return static_cast<uint32_t>(i);
  table.push_back(s);
  return static_cast<uint32_t>(table.size() - 1);
}

}  // namespace

uint32_t Module::internString(const std::string& s) { return intern(strings, s); }

uint32_t Module::internAsset(const std::string& s) { return intern(assets, s); }

int Module::findSymbol(const std::string& name) const {
  for (size_t i = 0; i < symbols.size(); ++i)
    if (symbols[i].name == name) return static_cast<int>(i);
  return -1;
}

int Module::findAttr(const std::string& name) const {
  for (size_t i = 0; i < attrs.size(); ++i)
    if (attrs[i].name == name) return static_cast<int>(i);
  return -1;
}

}  // namespace fgsg::ir
