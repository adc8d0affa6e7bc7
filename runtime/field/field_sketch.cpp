#include "runtime/field/field_sketch.h"

#include "runtime/field/trace.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace fgsg::rt::field {
namespace {

// One way along a streamline from `start`: its points every `step`, up to `length`, until
// the trace stops (the boundary, a zero of a vector field).
std::vector<Vec3> traceOneWay(const SurfaceMesh& mesh, const TangentField& field, surface::SurfacePoint start,
                              Vec3 heading, double angle, double length, double step) {
  std::vector<Vec3> points{start.position(mesh)};
  for (double travelled = 0; travelled < length;) {
    const TraceResult r = traceField(mesh, field, start, heading, angle, std::min(step, length - travelled));
    if (!(r.length > 0)) break;
    points.push_back(r.end.position(mesh));
    travelled += r.length;
    if (r.stopped) break;
    start = r.end;
    heading = r.direction;
  }
  return points;
}

// Both ways from a seed joined into one polyline (the backward half reversed).
std::vector<Vec3> traceBothWays(const SurfaceMesh& mesh, const TangentField& field, const surface::SurfacePoint& seed,
                                double angle, double length, double step) {
  Vec3 dir;
  if (!field.direction(seed, dir)) return {};
  const Vec3 n = seed.normal(mesh);
  const Vec3 heading = rotateAbout(dir, n, angle);
  std::vector<Vec3> back = traceOneWay(mesh, field, seed, -heading, angle, length, step);
  const std::vector<Vec3> ahead = traceOneWay(mesh, field, seed, heading, angle, length, step);
  std::reverse(back.begin(), back.end());
  back.insert(back.end(), ahead.begin() + 1, ahead.end());
  return back;
}

std::array<float, 3> kindColour(Degeneracy::Kind kind) {
  switch (kind) {
    case Degeneracy::Wedge: return {0.85f, 0.2f, 0.15f};
    case Degeneracy::Trisector: return {0.15f, 0.35f, 0.9f};
    case Degeneracy::Saddle: return {0.2f, 0.7f, 0.9f};
    case Degeneracy::Node: return {0.95f, 0.6f, 0.1f};
    case Degeneracy::Centre: return {0.9f, 0.85f, 0.2f};
    case Degeneracy::Focus: return {0.8f, 0.3f, 0.8f};
    default: return {0.5f, 0.5f, 0.5f};
  }
}

}  // namespace

const char* singularityName(Degeneracy::Kind kind) {
  switch (kind) {
    case Degeneracy::Wedge: return "wedge";
    case Degeneracy::Trisector: return "trisector";
    case Degeneracy::Node: return "node";
    case Degeneracy::Centre: return "centre";
    case Degeneracy::Saddle: return "saddle";
    case Degeneracy::Focus: return "focus";
    default: return "other";
  }
}

FieldSketch sketchField(const SurfaceMesh& mesh, const TangentField& field, const FieldSketchOptions& options) {
  FieldSketch sketch;
  const double diagonal = (mesh.boundsMax - mesh.boundsMin).norm();
  const double length = options.length > 0 ? options.length : diagonal / 10;
  const double step = options.step > 0 ? options.step : diagonal / 400;
  // Seeds at the centres of faces spread evenly through the face list.
  const size_t faces = mesh.faceCount();
  const size_t seeds = std::min(faces, size_t(std::max(options.seeds, 0)));
  // The seeds' lines are independent: traced concurrently (fgsg view redraws them after
  // each design edit, #49), kept in seed order.
  std::vector<std::vector<Vec3>> major(seeds), minor(seeds);
  tbb::parallel_for(size_t(0), seeds, [&](size_t k) {
    const surface::SurfacePoint seed{int(k * faces / seeds), Vec3(1.0 / 3, 1.0 / 3, 1.0 / 3)};
    major[k] = traceBothWays(mesh, field, seed, 0.0, length, step);
    if (options.minor && field.isTensor()) minor[k] = traceBothWays(mesh, field, seed, M_PI / 2, length, step);
  });
  for (size_t k = 0; k < seeds; ++k) {
    if (major[k].size() >= 2) sketch.majorLines.push_back(std::move(major[k]));
    if (minor[k].size() >= 2) sketch.minorLines.push_back(std::move(minor[k]));
  }
  // A singularity on an edge is found in both faces: listed once.
  const double same = 1e-2 * mesh.meanEdgeLength;
  for (const Degeneracy& d : field.degeneracies()) {
    const Vec3 at = d.at.position(mesh);
    const bool listed = std::any_of(sketch.singularities.begin(), sketch.singularities.end(), [&](const Singularity& s) {
      return s.kind == d.kind && (s.position - at).norm() <= same;
    });
    if (!listed) sketch.singularities.push_back({at, d.kind, d.indexTimesTwo});
  }
  return sketch;
}

Mesh sketchMesh(const Mesh& surface, const FieldSketch& sketch, double markerSize) {
  Mesh out = surface;
  const size_t surfaceVertices = out.vertexCount();
  out.colors.resize(3 * surfaceVertices);
  std::fill(out.colors.begin(), out.colors.end(), 0.75f);
  const auto addVertex = [&](const Vec3& p, const Vec3& n, const std::array<float, 3>& c) {
    for (int k = 0; k < 3; ++k) {
      out.positions.push_back(float(p[k]));
      out.normals.push_back(float(n[k]));
      out.colors.push_back(c[k]);
    }
    return uint32_t(out.vertexCount() - 1);
  };
  const auto addLines = [&](const std::vector<std::vector<Vec3>>& lines, const std::array<float, 3>& colour) {
    for (const auto& line : lines) {
      uint32_t previous = addVertex(line[0], Vec3::UnitZ(), colour);
      for (size_t i = 1; i < line.size(); ++i) {
        const uint32_t v = addVertex(line[i], Vec3::UnitZ(), colour);
        out.lines.push_back(previous);
        out.lines.push_back(v);
        previous = v;
      }
    }
  };
  addLines(sketch.majorLines, {0.1f, 0.1f, 0.1f});
  addLines(sketch.minorLines, {0.55f, 0.1f, 0.1f});
  // An octahedron per singularity: its six corners along the axes, eight faces.
  const double r = markerSize / 2;
  const Vec3 axes[6] = {Vec3::UnitX(), -Vec3::UnitX(), Vec3::UnitY(), -Vec3::UnitY(), Vec3::UnitZ(), -Vec3::UnitZ()};
  static const int kFaces[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for (const Singularity& s : sketch.singularities) {
    const auto colour = kindColour(s.kind);
    for (const auto& f : kFaces) {
      const Vec3 n = (axes[f[0]] + axes[f[1]] + axes[f[2]]).normalized();
      for (int k = 0; k < 3; ++k) out.indices.push_back(addVertex(s.position + r * axes[f[k]], n, colour));
    }
  }
  return out;
}

}  // namespace fgsg::rt::field
