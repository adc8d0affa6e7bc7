// Field design with elements (FGSG §4.2 "initialization stage", after Zhang et al. 2007
// for tensors and Zhang et al. 2006 for vectors): each element sits at a surface point
// and spreads over the surface through geodesic polar coordinates (rho, theta) around it
// (HeatGeodesics, accurate; or exponentialMap, fast); the field at vertex i is (FGSG eq. 3)
//   T(p_i) = sum_j exp(-d_j rho_ij) T_j(rho_ij, theta_ij).
// Each basis T_j is a unit pattern in the element's tangent plane, written below as the
// complex number z (a vector) or w = (t11 - t22) / 2 + i t12 (a traceless tensor, whose
// major eigenvector has half w's angle); theta is measured from the element's `direction`:
//   kind       vector field z        tensor field w        index (vector / tensor)
//   Regular    1                     1                     0 / 0
//   Wedge      -                     e^(i theta)           - / +1/2
//   Trisector  -                     e^(-i theta)          - / -1/2
//   Node       e^(i theta)  source   e^(2i theta) radial   +1 / +1
//   Centre     i e^(i theta) ccw     -e^(2i theta) around  +1 / +1
//   Saddle     e^(-i theta)          e^(-2i theta)         -1 / -1
// (Zhang et al.'s patterns are these times rho or rho^2: [[x, y], [y, -x]] for a wedge;
// the unit form keeps every element's strength where it is placed, the decay shapes it.)
// The value at the element is carried to vertex i along the geodesic, i.e. expressed
// relative to the reference direction transported there: z_i = s e^(-d rho) Y_i z(theta),
// w_i = s e^(-d rho) Y_i^2 w(theta), with Y_i the unit transported reference and s the
// strength (negative: a sink, a clockwise centre; for tensors the eigenvectors swap). A
// vertex an element sits on gets no value from a singular element (undefined there).
// Terms below 1e-12 of the strength (rho > ln(1e12) / d) are left out.
#pragma once

#include "runtime/field/exp_map.h"
#include "runtime/field/geodesics.h"
#include "runtime/field/tangent_field.h"

#include <memory>
#include <string>
#include <vector>

namespace fgsg::rt::field {

enum class ElementKind { Regular, Wedge, Trisector, Node, Centre, Saddle };

struct DesignElement {
  ElementKind kind = ElementKind::Regular;
  SurfacePoint at;
  double decay = 1;     // d_j, per unit of geodesic distance (0: no decay)
  double strength = 1;  // the pattern's magnitude at the element
  // World direction, projected onto the tangent plane at `at`: a regular element's
  // direction (a tensor's major eigenvector), a singular element's axis (theta = 0).
  Vec3 direction = Vec3::UnitX();
};

// How the designer finds polar coordinates around an element.
enum class PolarMethod {
  Heat,            // HeatGeodesics: accurate everywhere; factorises three matrices first
  ExponentialMap,  // exponentialMap: no set-up, O(n log n) per element, drifts far away
};

class FieldDesigner {
 public:
  // Heat: factorises the mesh's operators once (HeatGeodesics); reuse one designer for
  // every field on the same surface.
  explicit FieldDesigner(std::shared_ptr<const TangentFrames> frames,
                         PolarMethod method = PolarMethod::Heat);
  explicit FieldDesigner(std::shared_ptr<const HeatGeodesics> geodesics);

  bool ok() const { return !heat_ || heat_->ok(); }
  PolarMethod method() const { return method_; }
  const HeatGeodesics* heatGeodesics() const { return heat_.get(); }  // null: ExponentialMap
  // Polar coordinates around `at` by the designer's method; the exponential map stops at
  // maxDistance.
  PolarMap polarMap(const SurfacePoint& at, const Vec3& reference,
                    double maxDistance = INFINITY) const;

  // A new field: the sum of the elements' basis fields. False with `error` set for an
  // element that does not fit (outside the mesh, a wedge in a vector field, bad numbers).
  bool design(FieldType type, const std::vector<DesignElement>& elements, TangentField& out,
              std::string& error) const;
  // Adds one element's basis field to an existing field.
  bool add(const DesignElement& element, TangentField& field, std::string& error) const;

 private:
  std::shared_ptr<const TangentFrames> frames_;
  PolarMethod method_;
  std::shared_ptr<const HeatGeodesics> heat_;
};

const char* elementKindName(ElementKind kind);

}  // namespace fgsg::rt::field
