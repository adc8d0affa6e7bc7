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

std::vector<std::array<float, 3>> defaultTurtleColors() {
  return {{0.36f, 0.25f, 0.13f}, {0.55f, 0.4f, 0.22f}, {0.16f, 0.36f, 0.12f}, {0.3f, 0.6f, 0.2f},
          {0.56f, 0.8f, 0.35f},  {0.95f, 0.8f, 0.2f},  {0.8f, 0.15f, 0.15f},  {0.95f, 0.95f, 0.9f}};
}

int turtleOpNamed(const std::string& name) {
  if (name == "F") return int(TurtleOp::Forward);
  if (name == "f") return int(TurtleOp::Move);
  if (name == "@Tp") return int(TurtleOp::Tropism);
  if (name == "@Ts") return int(TurtleOp::Elasticity);
  if (name == "@O") return int(TurtleOp::Sphere);
  if (name == "@o") return int(TurtleOp::Circle);
  if (name == "@M") return int(TurtleOp::MoveTo);
  if (name == "@R") return int(TurtleOp::SetHeading);
  if (name == "@Gs") return int(TurtleOp::CylinderStart);
  if (name == "@Gc") return int(TurtleOp::CylinderPoint);
  if (name == "@Ge") return int(TurtleOp::CylinderEnd);
  if (name.size() != 1) return -1;
  switch (name[0]) {
    case '+': return int(TurtleOp::Left);
    case '-': return int(TurtleOp::Right);
    case '&': return int(TurtleOp::PitchDown);
    case '^': return int(TurtleOp::PitchUp);
    case '\\': return int(TurtleOp::RollLeft);
    case '/': return int(TurtleOp::RollRight);
    case '|': return int(TurtleOp::TurnAround);
    case '!': return int(TurtleOp::Width);
    case '$': return int(TurtleOp::RollHorizontal);
    case '%': return int(TurtleOp::Cut);
    case '{': return int(TurtleOp::PolygonBegin);
    case '.': return int(TurtleOp::PolygonVertex);
    case '}': return int(TurtleOp::PolygonEnd);
    case '\'': return int(TurtleOp::ColorIndex);
    case ',': return int(TurtleOp::ColorPrevious);
    case '~': return int(TurtleOp::SurfaceBox);
    default: return -1;
  }
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

const std::vector<Param>& surfacePointParams() {
  static const std::vector<Param> kParams = {{"x", Type::Num, 0}, {"y", Type::Num, 1}, {"z", Type::Num, 2}};
  return kParams;
}

uint32_t Module::internString(const std::string& s) { return intern(strings, s); }

uint32_t Module::internAsset(const std::string& s) { return intern(assets, s); }

int Module::findSymbol(const std::string& name) const {
  for (size_t i = 0; i < symbols.size(); ++i)
    if (symbols[i].name == name) return static_cast<int>(i);
  return -1;
}

int Module::findSymbolFrom(uint32_t from, const std::string& name) const {
  std::string scope = from < symbols.size() ? symbols[from].name : std::string();
  for (size_t dot = scope.rfind('.'); dot != std::string::npos; dot = scope.rfind('.')) {
    scope.resize(dot);
    if (const int s = findSymbol(scope + "." + name); s >= 0) return s;
  }
  return findSymbol(name);
}

int Module::findAttr(const std::string& name) const {
  for (size_t i = 0; i < attrs.size(); ++i)
    if (attrs[i].name == name) return static_cast<int>(i);
  return -1;
}

bool isCgaGeometryOp(OpKind kind) {
  switch (kind) {
    case OpKind::Subdiv:
    case OpKind::Repeat:
    case OpKind::Comp:
    case OpKind::Extrude:
    case OpKind::Roof:
    case OpKind::Footprint:
    case OpKind::ShapeOperation:
    case OpKind::Offset: return true;
    default: return false;
  }
}

bool anyOp(const Module& m, const std::function<bool(const Op&)>& pred) {
  const std::function<bool(const Block&)> inBlock = [&](const Block& b) {
    for (const Op& op : b) {
      if (pred(op)) return true;
      for (const Block& body : op.bodies)
        if (inBlock(body)) return true;
    }
    return false;
  };
  for (const Rule& r : m.rules)
    for (const Alternative& alt : r.alternatives)
      if (inBlock(alt.ops)) return true;
  return inBlock(m.axiom);
}

bool leavesOutputGeometry(const Module& m) {
  return m.mode != DeriveMode::Parallel && anyOp(m, [](const Op& op) { return isCgaGeometryOp(op.kind); });
}

}  // namespace fgsg::ir
