#include "runtime/field/design.h"

#include <cmath>
#include <complex>

namespace fgsg::rt::field {

namespace {

using Complex = std::complex<double>;
// Barycentric coordinates may be this far outside [0, 1] (rounding) and still count.
constexpr double kBaryTolerance = 1e-9;
// An element's terms below this fraction of its strength are left out.
constexpr double kNegligible = 1e-12;

// The pattern's value at angle theta (unit complex e^(i theta)), see design.h.
Complex pattern(ElementKind kind, bool tensor, const Complex& e) {
  const Complex i(0, 1);
  switch (kind) {
    case ElementKind::Regular: return 1;
    case ElementKind::Wedge: return e;
    case ElementKind::Trisector: return std::conj(e);
    case ElementKind::Node: return tensor ? e * e : e;
    case ElementKind::Centre: return tensor ? -e * e : i * e;
    case ElementKind::Saddle: return tensor ? std::conj(e * e) : std::conj(e);
  }
  return 0;
}

}  // namespace

const char* elementKindName(ElementKind kind) {
  switch (kind) {
    case ElementKind::Regular: return "regular";
    case ElementKind::Wedge: return "wedge";
    case ElementKind::Trisector: return "trisector";
    case ElementKind::Node: return "node";
    case ElementKind::Centre: return "centre";
    case ElementKind::Saddle: return "saddle";
  }
  return "?";
}

FieldDesigner::FieldDesigner(std::shared_ptr<const TangentFrames> frames, PolarMethod method)
    : frames_(frames), method_(method) {
  if (method == PolarMethod::Heat) heat_ = std::make_shared<const HeatGeodesics>(std::move(frames));
}

FieldDesigner::FieldDesigner(std::shared_ptr<const HeatGeodesics> geodesics)
    : method_(PolarMethod::Heat), heat_(std::move(geodesics)) {
  // The geodesics keep the frames alive; share them rather than build new ones.
  frames_ = std::shared_ptr<const TangentFrames>(heat_, &heat_->frames());
}

PolarMap FieldDesigner::polarMap(const SurfacePoint& at, const Vec3& reference,
                                 double maxDistance) const {
  if (heat_) return heat_->polarMap(at, reference);
  return exponentialMap(*frames_, at, reference, maxDistance);
}

bool FieldDesigner::design(FieldType type, const std::vector<DesignElement>& elements,
                           TangentField& out, std::string& error) const {
  TangentField field(frames_, type);
  for (const DesignElement& e : elements)
    if (!add(e, field, error)) return false;
  out = field;
  return true;
}

bool FieldDesigner::add(const DesignElement& e, TangentField& field, std::string& error) const {
  if (!ok()) {
    error = heat_->error();
    return false;
  }
  const SurfaceMesh& mesh = frames_->mesh();
  const bool tensor = field.isTensor();
  const std::string what = std::string(elementKindName(e.kind)) + " element";
  if (&field.mesh() != &mesh) {
    error = what + ": the field is on another surface";
    return false;
  }
  if (e.at.face < 0 || size_t(e.at.face) >= mesh.faceCount()) {
    error = what + ": face " + std::to_string(e.at.face) + " is not on the surface";
    return false;
  }
  if (!e.at.bary.allFinite() || e.at.bary.minCoeff() < -kBaryTolerance ||
      std::abs(e.at.bary.sum() - 1) > kBaryTolerance) {
    error = what + ": barycentric coordinates must be >= 0 and sum to 1";
    return false;
  }
  if (!std::isfinite(e.decay) || e.decay < 0 || !std::isfinite(e.strength) ||
      !e.direction.allFinite()) {
    error = what + ": decay must be >= 0, strength and direction finite";
    return false;
  }
  if (!tensor && (e.kind == ElementKind::Wedge || e.kind == ElementKind::Trisector)) {
    error = what + ": wedges and trisectors are tensor-field elements";
    return false;
  }
  const double reach = e.decay > 0 ? std::log(1 / kNegligible) / e.decay : INFINITY;
  const PolarMap map = polarMap(e.at, e.direction, reach);
  int onVertex = -1;
  for (int k = 0; k < 3; ++k)
    if (e.at.bary[k] >= 1 - kBaryTolerance) onVertex = mesh.faces[e.at.face][k];
  for (size_t v = 0; v < field.vertexCount(); ++v) {
    if ((int(v) == onVertex && e.kind != ElementKind::Regular) || !(map.distance[v] <= reach))
      continue;
    const double weight = e.strength * std::exp(-e.decay * map.distance[v]);
    const Complex& y = map.reference[v];
    const Complex value = weight * (tensor ? y * y : y) * pattern(e.kind, tensor, map.angle[v]);
    if (tensor) {
      Mat2 t;
      t << value.real(), value.imag(), value.imag(), -value.real();
      field.setVertexTensor(int(v), field.vertexTensor(int(v)) + t);
    } else {
      field.setVertexVector(int(v), field.vertexVector(int(v)) + Vec2(value.real(), value.imag()));
    }
  }
  return true;
}

}  // namespace fgsg::rt::field
