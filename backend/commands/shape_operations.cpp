#include "backend/commands/shape_operations.h"

#include "backend/commands/insert_along_uv_command.h"
#include "backend/commands/scatter_command.h"
#include "backend/engine/derivation.h"
#include "runtime/cga/edge_index_label.h"
#include "runtime/cga/shape_operations.h"
#include "runtime/cga/trim_planes.h"

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace fgsg::backend {
namespace {

// A turn by `degrees` about the x, y or z axis (translate/rotate's frames).
rt::Mat3 scopeTurnAbout(int axis, double degrees) {
  return rt::Mat3(Eigen::AngleAxisd(degrees * M_PI / 180.0, rt::Vec3::Unit(axis)).toRotationMatrix());
}
rt::Mat3 scopeTurnX(double degrees) { return scopeTurnAbout(0, degrees); }
rt::Mat3 scopeTurnY(double degrees) { return scopeTurnAbout(1, degrees); }
rt::Mat3 scopeTurnZ(double degrees) { return scopeTurnAbout(2, degrees); }

std::string bare(std::string label) {
  if (!label.empty() && label.back() == '=') label.pop_back();
  return label;
}

// SetbackPerEdge's distance is an expression evaluated once per edge: the lowering puts it
// in the op's first body as an EdgeDistance op (ir/lower.cpp), which the setback runs on
// each edge and which leaves its value here. Per thread: each thread derives on its own.
thread_local double* edgeDistanceSink = nullptr;

// The distance of each edge of SetbackPerEdge: body 0 run on the edge as CityEngine's
// comp(fe) component (x along the edge from corner i to i + 1, z the polygon's normal,
// sx its length), with comp.index = i and comp.total = the number of edges.
std::vector<double> distancesPerEdge(Derivation& d, const ir::Op& op, const rt::cga::FlatPolygon& polygon, State& st,
                                     Exec& ex, Frame& f) {
  const size_t n = polygon.ring.size();
  std::vector<double> out(n, 0.0);
  for (size_t i = 0; i < n; ++i) {
    const auto a = polygon.ring[i], b = polygon.ring[(i + 1) % n];
    const rt::Scope& plane = polygon.scope;
    rt::Scope edge = plane;
    const rt::Vec3 along = (plane.X() * (b.x() - a.x()) + plane.Y() * (b.y() - a.y())).normalized();
    edge.axes.col(0) = along;
    edge.axes.col(2) = plane.Z();
    edge.axes.col(1) = plane.Z().cross(along);
    edge.P = plane.P + plane.X() * a.x() + plane.Y() * a.y();
    edge.S = rt::Vec3((b - a).norm(), 0.0, 0.0);
    rt::Scope::Place place = st.scope.place;
    place.compIndex = static_cast<int32_t>(i);
    place.compTotal = static_cast<int32_t>(n);
    double value = 0.0;
    edgeDistanceSink = &value;
    d.runBody(op, 0, edge, rt::GeomRef{rt::GeomKind::Edge, 0, 0}, st, ex, f, &place);
    edgeDistanceSink = nullptr;
    if (!std::isfinite(value))
      throw DeriveError{op.loc, "R002", "SetbackPerEdge: the distance of edge " + std::to_string(i) + " is not a number"};
    out[i] = value;
  }
  return out;
}

// Setback and shapeL/U/O: each edge's distance and the part it goes to, then the bands
// and the remainder through their parts, in the order the edges run.
void setbackParts(Derivation& d, const ir::Op& op, const std::string& name, const double* a, State& st, Exec& ex,
                  Frame& f) {
  std::string error;
  rt::cga::FlatPolygon polygon;
  if (!rt::cga::flatPolygon(st.scope, st.geom, d.arena(), name.c_str(), polygon, error))
    throw DeriveError{op.loc, "R002", error};
  std::vector<std::string> labels;
  for (uint32_t l : op.partLabels) labels.push_back(d.module().strings[l]);
  const std::vector<unsigned> classes = rt::cga::edgeSelectors(polygon, d.streetEdges());
  const size_t edges = classes.size();
  std::vector<double> distance(edges, 0.0);
  std::vector<int> group(edges, -1);
  std::vector<bool> merged(labels.size(), false);
  if (name == "Setback" || name == "SetbackToArea" || name == "SetbackPerEdge") {
    // SetbackPerEdge's body 0 is its distance (its label "#distance" selects no edge).
    const std::vector<double> perEdge =
        name == "SetbackPerEdge" ? distancesPerEdge(d, op, polygon, st, ex, f) : std::vector<double>(edges, a[0]);
    for (size_t k = 0; k < labels.size(); ++k) merged[k] = !labels[k].empty() && labels[k].back() == '=';
    for (size_t i = 0; i < edges; ++i)
      for (size_t k = 0; k < labels.size(); ++k) {
        long long index = 0;
        const bool selects = rt::cga::edgeIndexOfLabel(labels[k], index)
                                 ? rt::cga::edgeIndexSelects(index, i, edges)
                                 : (rt::cga::edgeSelectorMask(labels[k]) & classes[i]) != 0;
        if (bare(labels[k]) != "remainder" && selects) {
          distance[i] = perEdge[i];
          group[i] = static_cast<int>(k);
          break;
        }
      }
  } else {
    // shapeL(front, left), shapeU(front, right, left), shapeO(front, right, back, left): the
    // wings along those edges, one merged `shape`.
    using namespace rt::cga;
    std::vector<std::pair<unsigned, double>> wings;
    if (name == "ShapeL") wings = {{kEdgeFront, a[0]}, {kEdgeLeft, a[1]}};
    if (name == "ShapeU") wings = {{kEdgeFront, a[0]}, {kEdgeRight, a[1]}, {kEdgeLeft, a[2]}};
    if (name == "ShapeO") wings = {{kEdgeFront, a[0]}, {kEdgeRight, a[1]}, {kEdgeBack, a[2]}, {kEdgeLeft, a[3]}};
    int shape = -1;
    for (size_t k = 0; k < labels.size(); ++k)
      if (bare(labels[k]) == "shape") shape = shape < 0 ? static_cast<int>(k) : shape, merged[k] = true;
    for (size_t i = 0; i < edges; ++i)
      for (const auto& [mask, width] : wings)
        if (classes[i] & mask) distance[i] = width, group[i] = width > 0 ? shape : -1;
  }
  if (name == "SetbackToArea") {
    // One distance for the selected edges, chosen so that the remainder has the area asked for.
    std::vector<bool> selected(edges);
    for (size_t i = 0; i < edges; ++i) selected[i] = group[i] >= 0;
    double d = 0;
    if (!rt::cga::setbackDistanceForArea(polygon, selected, a[0], d, error)) throw DeriveError{op.loc, "R002", error};
    for (size_t i = 0; i < edges; ++i) distance[i] = selected[i] ? d : 0.0;
  }
  std::vector<rt::cga::Part> pieces, remainder;
  std::vector<int> pieceGroup;
  if (!rt::cga::setback(polygon, distance, group, merged, d.arena(), pieces, pieceGroup, remainder, error))
    throw DeriveError{op.loc, "R002", error};
  for (size_t j = 0; j < pieces.size(); ++j) {
    d.runBody(op, static_cast<size_t>(pieceGroup[j]), pieces[j].scope, pieces[j].geom, st, ex, f);
    if (ex.culled) return;
  }
  for (size_t k = 0; k < labels.size(); ++k)
    if (bare(labels[k]) == "remainder")
      for (const rt::cga::Part& part : remainder) {
        d.runBody(op, k, part.scope, part.geom, st, ex, f);
        if (ex.culled) return;
      }
}

// trim() (op_trim): the shape's geometry cut by its trim planes, those the trim attribute
// turns on (vertical ones unless set off, horizontal ones only when set on).
void trimByShapePlanes(Derivation& d, const rt::Scope& scope, const rt::GeomRef& geom, rt::cga::Part& out) {
  rt::cga::trimGeometry(scope, geom, d.arena(), d.shapeFrames().enabledTrimPlanes(scope.pivot, scope.trim), out);
}

}  // namespace

void applyShapeOperation(Derivation& d, const ir::Op& op, const double* a, uint32_t n, State& st, Exec& ex,
                         Frame& f) {
  const std::string& name = d.module().strings[op.str];
  if (name == "EdgeDistance") {  // SetbackPerEdge's distance for the edge it runs on
    if (!edgeDistanceSink) throw DeriveError{op.loc, "R002", "EdgeDistance outside SetbackPerEdge"};
    *edgeDistanceSink = a[0];
    return;
  }
  if (name == "Scatter") {
    applyScatter(d, op, a, n, st, ex, f);
    return;
  }
  if (name == "InsertAlongUV") {
    applyInsertAlongUv(d, op, a, n, st);
    return;
  }
  if (name.rfind("Setback", 0) == 0 || name == "ShapeL" || name == "ShapeU" || name == "ShapeO") {
    setbackParts(d, op, name, a, st, ex, f);
    return;
  }
  rt::cga::Part part;
  std::string error;
  bool ok = true;
  const bool flip[3] = {n > 0 && a[0] != 0, n > 1 && a[1] != 0, n > 2 && a[2] != 0};
  if (name == "AlignScopeToAxes") {
    ok = rt::cga::alignScopeToAxes(st.scope, st.geom, d.arena(), n ? static_cast<int>(a[0]) : 7, part, error);
  } else if (name == "AlignScopeToGeometry") {
    for (int k = 1; k < 3; ++k)
      if (a[k] != std::floor(a[k]) || std::abs(a[k]) > 1e9)
        throw DeriveError{op.loc, "R002", "AlignScopeToGeometry: a face or edge index must be a whole number"};
    ok = rt::cga::alignScopeToGeometry(st.scope, st.geom, d.arena(), static_cast<int>(a[0]), static_cast<int>(a[1]),
                                       static_cast<int>(a[2]), part, error);
  } else if (name == "RotateScope") {
    ok = rt::cga::rotateScope(st.scope, st.geom, d.arena(), rt::Vec3(a[0], a[1], a[2]), part, error);
  } else if (name == "MirrorScope") {
    ok = rt::cga::mirrorScope(st.scope, st.geom, d.arena(), flip, part, error);
  } else if (name == "Mirror") {
    ok = rt::cga::mirrorGeometry(st.scope, st.geom, d.arena(), flip, part, error);
  } else if (name == "ReverseNormals") {
    ok = rt::cga::reverseNormals(st.scope, st.geom, d.arena(), part, error);
  } else if (name == "DeleteHoles") {
    ok = rt::cga::deleteHoles(st.scope, st.geom, d.arena(), part, error);
  } else if (name == "ResetGeometry") {
    part = rt::cga::Part{st.scope, rt::GeomRef{}, false, 0};
  } else if (name == "CleanupGeometry") {
    ok = rt::cga::cleanupGeometry(st.scope, st.geom, d.arena(), n > 0 ? static_cast<int>(a[0]) : 15, n > 1 ? a[1] : 0.0,
                                  part, error);
  } else if (name == "Convexify") {
    if (n > 0 && !(a[0] > 0)) throw DeriveError{op.loc, "R002", "Convexify: maxLength must be a positive number"};
    ok = rt::cga::convexify(st.scope, st.geom, d.arena(), n > 0 ? a[0] : INFINITY, part, error);
  } else if (name == "Translate" || name == "Rotate") {
    // translate / rotate(rel|abs, system, x, y, z) (CityEngine's op_translate and
    // op_rotate, docs/cga.md): the scope (its geometry with it) moved or turned about its
    // origin in the axes of the scope (0), the pivot (1: setPivot's frame, else the
    // object's), the object (2: the start shape's frame) or the world (3).
    const bool absolute = a[0] != 0;
    const int system = static_cast<int>(a[1]);
    part = rt::cga::Part{st.scope, st.geom, false, 0};
    if (system == 0) {
      // In the scope's own system the scope stands at the origin with no turn, so setting
      // a place or angles there (abs) is moving or turning by them (rel).
      if (name == "Translate") {
        part.scope.P = st.scope.P + st.scope.axes * rt::Vec3(a[2], a[3], a[4]);
      } else {
        part.scope.axes = st.scope.axes * scopeTurnX(a[2]) * scopeTurnY(a[3]) * scopeTurnZ(a[4]);
      }
    } else {
      // About the system's fixed axes, x first: Rz·Ry·Rx in its axes. The world's are
      // the identity, left out (the same bits as before the other systems came).
      const bool world = system == 3;
      if (world && name == "Translate") {
        const rt::Vec3 v(a[2], a[3], a[4]);
        part.scope.P = absolute ? v : rt::Vec3(st.scope.P + v);
      } else if (name == "Translate") {
        const rt::Scope& frame = system == 1 ? d.pivotFrame(st.scope) : d.objectFrame();
        const rt::Vec3 v = frame.axes * rt::Vec3(a[2], a[3], a[4]);
        part.scope.P = absolute ? rt::Vec3(frame.P + v) : rt::Vec3(st.scope.P + v);
      } else {
        const rt::Mat3 turn = scopeTurnZ(a[4]) * scopeTurnY(a[3]) * scopeTurnX(a[2]);
        if (world) {
          part.scope.axes = absolute ? turn : rt::Mat3(turn * st.scope.axes);
        } else {
          const rt::Scope& frame = system == 1 ? d.pivotFrame(st.scope) : d.objectFrame();
          const rt::Mat3 r = frame.axes * turn;
          part.scope.axes = absolute ? r : rt::Mat3(r * (frame.axes.transpose() * st.scope.axes));
        }
      }
    }
  } else if (name == "SetPivot") {
    // setPivot(axisMap, cornerIndex) (op_setPivot): the pivot at a corner of the scope,
    // kept for this shape and the shapes it creates; the scope becomes its frame.
    const double corner = a[1];
    if (!(corner == std::floor(corner) && corner >= 0 && corner <= 7)) {
      std::ostringstream message;
      message << "setPivot in rule '" << (ex.symbol < d.module().symbols.size() ? d.module().symbols[ex.symbol].name : "axiom")
              << "': the corner index " << corner << " is not a whole number from 0 to 7";
      throw DeriveError{op.loc, "R002", message.str()};
    }
    rt::Scope pivot;
    ok = rt::cga::setPivot(st.scope, st.geom, d.arena(), static_cast<int>(a[0]), static_cast<int>(corner), part, pivot,
                           error);
    if (ok) part.scope.pivot = d.shapeFrames().withPivot(st.scope.pivot, pivot, op.loc);
  } else if (name == "Taper") {
    ok = rt::cga::taper(st.scope, st.geom, a[0], d.arena(), part, error);
  } else if (name == "Envelope" || name == "EnvelopePerEdge") {
    // Envelope(direction, maxHeight, front base height, front angle, ...): pairs by street
    // side; EnvelopePerEdge(direction, maxHeight, base 0, angle 0, base 1, angle 1, ...): one
    // pair per edge in edge order, edges past the pairs (0, 90), pairs past the edges unused.
    rt::cga::FlatPolygon polygon;
    ok = rt::cga::flatPolygon(st.scope, st.geom, d.arena(), "envelope", polygon, error);
    if (ok) {
      std::vector<rt::cga::EnvelopeEdge> edges(polygon.ring.size());
      if (name == "Envelope")
        edges = rt::cga::envelopeEdgesBySide(rt::cga::edgeSelectors(polygon, d.streetEdges()), a + 2, n - 2);
      for (size_t i = 0; name == "EnvelopePerEdge" && i < edges.size() && 3 + 2 * i < n; ++i)
        edges[i] = {a[2 + 2 * i], a[3 + 2 * i]};
      ok = rt::cga::envelope(st.scope, st.geom, polygon, a[0] != 0, a[1], edges, d.arena(), part, error);
    }
  } else if (name == "InnerRectangle") {
    rt::cga::FlatPolygon polygon;
    ok = rt::cga::flatPolygon(st.scope, st.geom, d.arena(), "InnerRectangle", polygon, error) &&
         rt::cga::innerRectangle(polygon, n > 0 && a[0] == 1, d.arena(), part, error);
    if (ok && !op.bodies.empty()) {
      d.runBody(op, 0, part.scope, part.geom, st, ex, f);
      return;
    }
  } else if (name.rfind("Primitive", 0) == 0) {
    // A primitive is trimmed as it is made (op_trim: "automatically performed").
    ok = rt::cga::primitive(st.scope, name, std::vector<double>(a, a + n), d.arena(), part, error);
    if (ok) trimByShapePlanes(d, part.scope, part.geom, part);
  } else if (name == "ApplyTrimPlanes") {
    trimByShapePlanes(d, st.scope, st.geom, part);
  } else if (name == "SetTrim") {
    // SetTrim(0 horizontal | 1 vertical, on): the bits of rt::Scope::trim, 0 the defaults.
    if (a[0] != 0 && a[0] != 1)
      throw DeriveError{op.loc, "R002", "SetTrim: the trim planes are \"horizontal\" (0) or \"vertical\" (1)"};
    const uint8_t bit = a[0] == 0 ? 2 : 1;
    const bool setBit = a[0] == 0 ? a[1] != 0 : a[1] == 0;
    part = rt::cga::Part{st.scope, st.geom, false, 0};
    part.scope.trim = static_cast<uint8_t>(setBit ? (st.scope.trim | bit) : (st.scope.trim & ~bit));
  } else {
    throw DeriveError{op.loc, "R002", "unknown shape operation '" + name + "'"};
  }
  if (!ok) throw DeriveError{op.loc, "R002", error};
  st.scope = part.scope;
  st.geom = part.geom;
}

}  // namespace fgsg::backend
