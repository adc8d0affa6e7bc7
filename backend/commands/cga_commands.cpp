#include "backend/commands/cga_commands.h"

#include "backend/commands/shape_operations.h"
#include "backend/engine/derivation.h"
#include "runtime/cga/cga.h"
#include "runtime/cga/comp_selector_name.h"
#include "runtime/cga/edge_index_label.h"
#include "runtime/cga/ground_face.h"
#include "runtime/cga/shape_operations.h"
#include "runtime/cga/trim_planes.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <sstream>

namespace fgsg::backend {

// A straight skeleton that --max-seconds abandoned ends the derivation with R004, as the
// time limit does everywhere.
namespace {
template <class Op>
bool skeletonWithin(Derivation& d, Op op) {
  try {
    return op();
  } catch (const rt::TimeLimitReached&) {
    throw d.timeLimit();
  }
}
}  // namespace

std::vector<ir::OpKind> CgaCommands::kinds() const {
  using K = ir::OpKind;
  return {K::Subdiv, K::Repeat, K::Comp, K::Extrude, K::Footprint, K::Offset, K::Roof, K::ShapeOperation};
}

void CgaCommands::apply(const ir::Op& op, const double* a, uint32_t n, State& st, Exec& ex, Frame& f) {
  // CityEngine makes a shape a comp or offset runs on an occluder (context queries).
  if (op.kind == ir::OpKind::Comp || op.kind == ir::OpKind::Offset) d_.noteOccluder(st);
  // A `.cga` lot (a ground face) goes to offset and the roofs as fgsg's polygon (extrude
  // takes it as it is).
  const bool ground = (op.kind == ir::OpKind::Offset || op.kind == ir::OpKind::Roof) &&
                      rt::cga::isGroundFace(st.geom, d_.arena());
  rt::Scope scope = st.scope;
  rt::GeomRef geom = st.geom;
  if (ground) rt::cga::groundToPolygon(scope, geom, d_.arena());
  switch (op.kind) {
    case ir::OpKind::Extrude: {
      rt::cga::Part part;
      std::string error;
      if (!rt::cga::extrude(scope, geom, a[0], d_.arena(), part, error))
        throw DeriveError{op.loc, "R002", error};
      // `.cga`'s extrude(world.up, h) (a second argument, not 0): the face's normal must be
      // world up, the one case where it is extrude(h). CityEngine sweeps any other face
      // straight up; that is not here yet, so it is an error rather than a wrong solid.
      if (n >= 2 && a[1] != 0.0 && part.scope.axes.col(1).normalized().y() < 1.0 - 1e-6) {
        const Eigen::Vector3d up = part.scope.axes.col(1).normalized();
        std::ostringstream m;
        m << "extrude(world.up, h) on a face whose normal (" << up.x() << ", " << up.y() << ", " << up.z()
          << ") is not world up: only faces facing up are supported (use extrude(h) to go along the normal)";
        throw DeriveError{op.loc, "R002", m.str()};
      }
      st.scope = part.scope;
      st.geom = part.geom;
      break;
    }
    case ir::OpKind::Footprint: {
      rt::cga::Part part;
      std::string error;
      // The outline, then each hole from its ring start on.
      std::vector<std::vector<Eigen::Vector2d>> rings(1);
      for (uint32_t k = 0; k + 1 < n; k += 2) {
        if (std::find(op.ringStarts.begin(), op.ringStarts.end(), k) != op.ringStarts.end()) rings.emplace_back();
        rings.back().emplace_back(a[k], a[k + 1]);
      }
      const std::vector<std::vector<Eigen::Vector2d>> holes(rings.begin() + 1, rings.end());
      if (!rt::cga::footprint(st.scope, rings[0], holes, d_.arena(), part, error))
        throw DeriveError{op.loc, "R002", error};
      if (d_.module().cityEngineLots) rt::cga::polygonOnGround(part.scope, part.geom, d_.arena());
      st.scope = part.scope;
      st.geom = part.geom;
      break;
    }
    case ir::OpKind::Offset: {
      std::vector<uint32_t> insideBodies, borderBodies;
      for (uint32_t k = 0; k < op.partLabels.size(); ++k)
        (d_.module().strings[op.partLabels[k]] == "inside" ? insideBodies : borderBodies).push_back(k);
      std::vector<rt::cga::Part> inside, border;
      std::string error;
      if (!skeletonWithin(d_, [&] {
            return rt::cga::offset(scope, geom, a[0], !borderBodies.empty(), d_.arena(), inside, border, error,
                                   &d_.deadline());
          }))
        throw DeriveError{op.loc, "R002", error};
      if (ground) {  // the pieces of a ground face are ground faces, x along the lot's
        const rt::Vec3 x = st.scope.X();
        for (auto* pieces : {&inside, &border})
          for (rt::cga::Part& piece : *pieces) rt::cga::polygonOnGround(piece.scope, piece.geom, d_.arena(), &x);
      }
      for (const auto& [pieces, bodies] : {std::pair{&inside, &insideBodies}, std::pair{&border, &borderBodies}})
        for (const rt::cga::Part& piece : *pieces)
          for (uint32_t k : *bodies) {
            d_.runBody(op, k, piece.scope, piece.geom, st, ex, f);
            if (ex.culled) return;
          }
      break;
    }
    case ir::OpKind::Roof: {
      rt::cga::Part part;
      std::string error;
      // Roof(kind, angle, overhang, gable overhang, edge index): the optional ones in order;
      // Roof(kind, "byHeight", height, ...) (op.index 1) has the height in the angle's place.
      rt::cga::RoofOptions options;
      if (n > 1) options.overhang = a[1];
      options.gableOverhang = n > 2 ? a[2] : options.overhang;
      if (n > 3) {
        if (!(std::isfinite(a[3]) && std::abs(a[3]) < 1e9))
          throw DeriveError{op.loc, "R002", "Roof: the edge index is not a finite number"};
        options.edgeIndex = static_cast<int>(std::floor(a[3]));
        if (options.edgeIndex < 0)
          throw DeriveError{op.loc, "R002", "Roof: the edge index " + std::to_string(options.edgeIndex) +
                                                " is negative"};
      }
      if (!skeletonWithin(d_, [&] {
            const std::string& kind = d_.module().strings[op.str];
            return op.index == ir::kRoofByHeight
                       ? rt::cga::roofByHeight(scope, geom, kind, a[0], d_.arena(), part, error, &d_.deadline(), options)
                       : rt::cga::roof(scope, geom, kind, a[0], d_.arena(), part, error, &d_.deadline(), options);
          }))
        throw DeriveError{op.loc, "R002", error};
      d_.runBody(op, 0, part.scope, part.geom, st, ex, f);
      break;
    }
    case ir::OpKind::ShapeOperation: applyShapeOperation(d_, op, a, n, st, ex, f); break;
    default: split(op, a, st, ex, f); break;
  }
}

void CgaCommands::split(const ir::Op& op, const double* a, State& st, Exec& ex, Frame& f) {
  std::vector<rt::cga::Part> parts;
  std::string error;
  bool ok = false;
  size_t derivedParts = SIZE_MAX;  // a repeat split's leftover piece (past these) is not derived
  std::vector<bool> generated;     // a .cga split: which parts CityEngine generates
  if (op.kind == ir::OpKind::Subdiv) {
    std::vector<rt::cga::SizeValue> sizes;
    for (size_t k = 0; k < op.sizes.size(); ++k)
      sizes.push_back({static_cast<rt::cga::SizeValue::Kind>(op.sizes[k].kind), a[k]});
    const int axis = static_cast<int>(op.index);
    ok = true;
    if (op.cityEngineSizing) {
      // A .cga split: CityEngine's sizing; the parts it does not generate are skipped.
      // SplitArea's sizes are areas, turned into the lengths that cut them off.
      std::vector<rt::cga::SizeValue> written = std::move(sizes);
      size_t pattern = 0;
      const bool byArea = op.str < d_.module().strings.size() && d_.module().strings[op.str] == "SplitArea";
      ok = (byArea ? rt::cga::splitAreaSizes(st.scope, st.geom, d_.arena(), axis, op.repeat, written, sizes, generated,
                                             error)
                   : rt::cga::cityEngineSizes(written, st.scope.S[axis], axis, op.repeat, sizes, generated, pattern,
                                              error)) &&
           rt::cga::subdivide(st.scope, st.geom, axis, sizes, d_.arena(), parts, error);
      if (!ok) throw DeriveError{op.loc, "R002", error};
      for (size_t i = 0; i < parts.size(); ++i) parts[i].empty = parts[i].empty || !generated[i];
    } else if (op.repeat) {
      std::vector<rt::cga::SizeValue> pattern = std::move(sizes);
      size_t repeats = 0;
      ok = rt::cga::repeatPattern(pattern, st.scope.S[axis], axis, sizes, repeats, error);
      derivedParts = repeats * pattern.size();
    }
    if (!op.cityEngineSizing) ok = ok && rt::cga::subdivide(st.scope, st.geom, axis, sizes, d_.arena(), parts, error);
  } else if (op.kind == ir::OpKind::Repeat) {
    std::vector<double> sizes(a, a + op.sizes.size());
    ok = rt::cga::repeat(st.scope, st.geom, op.index, sizes, d_.arena(), parts, error);
  }
  // Labelled parts of Comp: each component goes to the first part whose label names it (a
  // class of componentSelectorMask's, or an index selector `2:` by its place among them all).
  std::vector<uint64_t> labelMasks;
  std::vector<long long> labelIndex;  // an index selector's index; LLONG_MIN: none
  uint64_t wantedClasses = 0;
  for (uint32_t label : op.partLabels) {
    const std::string& name = d_.module().strings[label];
    long long index = LLONG_MIN;
    if (!rt::cga::edgeIndexOfLabel(name, index)) index = LLONG_MIN;
    labelIndex.push_back(index);
    labelMasks.push_back(rt::cga::componentSelectorMask(d_.module().strings[op.str], name));
    if (labelMasks.back() != ~0u) wantedClasses |= labelMasks.back();  // `all` needs no class
  }
  // comp.sel: each part's place among the module's comp selectors (ir::Module).
  std::vector<uint32_t> labelSel(op.partLabels.size(), 0);
  const std::vector<uint32_t>& selectors = d_.module().compSelectorLabels;
  for (size_t k = 0; k < op.partLabels.size(); ++k)
    for (size_t s = 0; s < selectors.size() && s < 255; ++s)
      if (selectors[s] == op.partLabels[k]) labelSel[k] = uint32_t(s + 1);
  // An unlabelled comp (`.cga`'s one `all :`) chose its components by `all`.
  if (op.kind == ir::OpKind::Comp && op.partLabels.empty())
    for (size_t s = 0; s < selectors.size() && s < 255 && labelSel.empty(); ++s)
      if (d_.module().strings[selectors[s]] == "all") labelSel.push_back(uint32_t(s + 1));
  if (op.kind == ir::OpKind::Comp)
    ok = rt::cga::components(st.scope, st.geom, d_.module().strings[op.str], d_.arena(), parts, error,
                             d_.objectFrame().axes, wantedClasses, d_.streetEdges());
  if (!ok) throw DeriveError{op.loc, "R002", error};
  // comp(f)'s trim planes (attr_trim), each face's from the faces it shares edges with.
  std::vector<std::vector<rt::cga::TrimPlane>> trimPlanes;
  if (op.kind == ir::OpKind::Comp && d_.makesTrimPlanes())
    trimPlanes = rt::cga::compTrimPlanes(st.scope, st.geom, d_.arena(), parts, d_.pivotFrame(st.scope).Y());
  // The body each derived part runs (SIZE_MAX: none), and how many parts each body runs.
  std::vector<size_t> bodyOf(parts.size(), SIZE_MAX);
  std::vector<int32_t> perBody(op.bodies.size() + labelMasks.size() + 1, 0);
  int32_t derived = 0;
  for (size_t i = 0; i < parts.size() && i < derivedParts; ++i) {
    if (parts[i].empty) continue;
    size_t body = op.kind == ir::OpKind::Subdiv ? i % op.bodies.size() : 0;
    if (!labelMasks.empty()) {
      body = 0;
      // ~0u (an edge comp's `all`) takes edges of no roof class too; an index wraps around
      // the components' count as setback's does.
      auto takes = [&](size_t k) {
        return labelMasks[k] == ~0u || (labelMasks[k] & parts[i].faceClass) ||
               (labelIndex[k] != LLONG_MIN && rt::cga::edgeIndexSelects(labelIndex[k], i, parts.size()));
      };
      while (body < labelMasks.size() && !takes(body)) ++body;
      if (body == labelMasks.size()) continue;  // no part takes this face
    }
    bodyOf[i] = body;
    ++perBody[body];
    ++derived;
  }
  // A merged part (`all =`, fgsg `all=:`) of comp(e) / comp(v): its components are one shape,
  // run where its first one comes (rt::cga::mergedComponents).
  if (op.kind == ir::OpKind::Comp)
    for (size_t k = 0; k < labelMasks.size(); ++k) {
      if (!rt::cga::compLabelMerged(d_.module().strings[op.partLabels[k]]) || perBody[k] == 0) continue;
      std::vector<rt::cga::Part> taken;
      size_t first = SIZE_MAX;
      for (size_t i = 0; i < parts.size(); ++i)
        if (bodyOf[i] == k) {
          taken.push_back(parts[i]);
          if (first == SIZE_MAX) first = i;
          else bodyOf[i] = SIZE_MAX;
        }
      // comp(f)'s faces as one shape of all of them; its trim planes (the first face's)
      // would cut the faces merged with it: none. One face alone keeps its planes, as `:`.
      const bool faces = taken.front().geom.kind == rt::GeomKind::Polygon ||
                         taken.front().geom.kind == rt::GeomKind::Polyhedron;
      parts[first] = faces ? rt::cga::mergedFaces(taken, d_.arena()) : rt::cga::mergedComponents(taken);
      if (faces && taken.size() > 1 && first < trimPlanes.size()) trimPlanes[first].clear();
      perBody[k] = 1;
    }
  // CGA's split.index / split.total count the parts a split derives; comp.index /
  // comp.total the faces of the part's selector (CityEngine's per-selector count).
  std::vector<int32_t> seen(perBody.size(), 0);
  int32_t index = 0;
  for (size_t i = 0; i < parts.size(); ++i) {
    if (bodyOf[i] == SIZE_MAX) continue;
    rt::Scope::Place place = st.scope.place;
    if (op.kind == ir::OpKind::Comp)
      place.compIndex = seen[bodyOf[i]]++, place.compTotal = uint32_t(perBody[bodyOf[i]]),
      place.compSel = bodyOf[i] < labelSel.size() ? labelSel[bodyOf[i]] : 0;
    else
      place.splitIndex = index++, place.splitTotal = derived;
    uint16_t frame = st.scope.pivot;
    if (i < trimPlanes.size() && !trimPlanes[i].empty())
      frame = d_.shapeFrames().withTrimPlanes(frame, trimPlanes[i], op.loc);
    d_.runBody(op, bodyOf[i], parts[i].scope, parts[i].geom, st, ex, f, &place, &frame);
    if (ex.culled) return;
  }
}

}  // namespace fgsg::backend
