#include "backend/commands/surface_world.h"

#include "backend/commands/surface_geometry.h"

#include "backend/interp/eval.h"

#include "runtime/field/curvature.h"
#include "runtime/field/design.h"
#include "runtime/field/eigen_basis_direction.h"
#include "runtime/field/field_file.h"
#include "runtime/field/image_field.h"
#include "runtime/field/scalar_field.h"
#include "runtime/field/smooth.h"
#include "runtime/field/tangent_field.h"
#include "runtime/field/tangent_frames.h"
#include "runtime/field/trace.h"
#include "runtime/io/find_file.h"
#include "runtime/surface/locate.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <cstdio>
#include <mutex>
#include <queue>
#include <unordered_map>
#include <optional>

namespace fgsg::backend {
namespace {

using rt::Vec3;
using rt::surface::SurfaceMesh;
using rt::surface::SurfacePoint;

constexpr double kPi = 3.14159265358979323846;
// A tangent direction shorter than this (relative) has no direction: the scope's X axis
// stood along the normal, or T moved only along it.
constexpr double kTinyDirection = 1e-12;

// `v` laid into the tangent plane of `n`, unit length; `fallback` when v is along n.
Vec3 tangent(const Vec3& v, const Vec3& n, const Vec3& fallback) {
  Vec3 t = v - n * n.dot(v);
  if (t.norm() > kTinyDirection * std::max(1.0, v.norm())) return t.normalized();
  t = fallback - n * n.dot(fallback);
  if (t.norm() > kTinyDirection) return t.normalized();
  return n.unitOrthogonal();
}

}  // namespace

struct SurfaceWorld::Impl {
  explicit Impl(std::shared_ptr<const SurfaceGeometry> built)
      : geometry(std::move(built)), mesh(geometry->mesh()), locator(&geometry->locator()) {}

  rt::Deadline* deadline = nullptr;  // --max-seconds: field design and smoothing ask it
  struct Field {
    std::string name;
    std::unique_ptr<rt::field::TangentField> values;
    bool curvature = false;  // `curvature`: answers mincurv ... gausscurv
    std::unique_ptr<rt::field::Picture> picture;  // `image(...)`: answers intensity
    std::unique_ptr<rt::field::ScalarField> scalar;  // `scalar(...)`: values is its gradient field
  };

  // The mesh, its locator and frames: shared with other worlds on the same surface (fgsg
  // view keeps them across recompiles, surface_geometry.h).
  std::shared_ptr<const SurfaceGeometry> geometry;
  const SurfaceMesh& mesh;
  const rt::surface::SurfaceLocator* locator;
  std::shared_ptr<const rt::field::TangentFrames> frames;
  std::vector<Field> fields;        // in declaration order; the first guides T
  std::vector<int> fieldOfEnv;      // Module::environment index -> fields index (-1: none)
  // For geodesic distances, built on first use (once, whichever thread asks first).
  mutable std::once_flag vertexFacesBuilt;
  mutable std::vector<std::vector<int>> vertexFaces;
  Vec3 start = Vec3::Zero();

  // The scope's surface point; a scope made without one (a synthesized piece) is snapped.
  SurfacePoint pointOf(const rt::Scope& s) const {
    if (s.face >= 0) return {s.face, s.bary};
    return locator->closestPoint(s.P);
  }

  // Puts the scope on `p` with X along `x` (laid into the tangent plane), keeping lift.
  void place(rt::Scope& s, const SurfacePoint& p, const Vec3& x) const {
    const Vec3 n = p.normal(mesh);
    const Vec3 X = tangent(x, n, s.axes.col(0));
    s.face = p.face;
    s.bary = p.bary;
    s.axes.col(0) = X;
    s.axes.col(1) = n.cross(X);
    s.axes.col(2) = n;
    s.P = p.position(mesh) + s.lift * n;
  }
};

SurfaceWorld::SurfaceWorld(const ir::Module& m, const rt::DeriveOptions& options,
                           const std::vector<std::string>& searchDirs, rt::Deadline* deadline)
    : SurfaceWorld(m, options, searchDirs, SurfaceGeometry::build(m.surface, options, searchDirs, deadline),
                   deadline) {}

SurfaceWorld::SurfaceWorld(const ir::Module& m, const rt::DeriveOptions& options,
                           const std::vector<std::string>& searchDirs, std::shared_ptr<const SurfaceGeometry> geometry,
                           rt::Deadline* deadline)
    : impl_(std::make_unique<Impl>(std::move(geometry))) {
  impl_->deadline = deadline;
  buildFields(m, options, searchDirs);
  impl_->start = options.hasStart ? Vec3(options.start[0], options.start[1], options.start[2])
                                  : Vec3(0.5 * (impl_->mesh.boundsMin + impl_->mesh.boundsMax));
  // The deadline is the building derivation's: fgsg view hands the world to later ones
  // (engine/surface_reuse.h), so it is not kept past construction.
  impl_->deadline = nullptr;
}

SurfaceWorld::~SurfaceWorld() = default;

namespace {

const std::vector<double>* word(const ir::FieldDesignSpec& item, const std::string& key) {
  for (const auto& [k, values] : item.words)
    if (k == key) return &values;
  return nullptr;
}

// Whether a scalar field's file is a picture (its brightness) rather than a field file.
bool isPicturePath(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".pgm" || ext == ".ppm" || ext == ".bmp" ||
         ext == ".tga";
}

// `scalar(EXPR)`: the expression at each vertex, its position in x, y, z; attrs as --set
// gives them, Rand drawn from the run's seed (vertex by vertex, in order).
rt::field::ScalarField scalarFromExpression(const ir::Module& m, const ir::FieldSpec& spec,
                                            const rt::DeriveOptions& options,
                                            const rt::surface::SurfaceMesh& mesh) {
  ir::Module local = m;  // attributeSlots interns the strings --set gives
  const Evaluator eval(local, attributeSlots(local, options.attrOverrides, attributeRandomKey(options.seed, 0)));
  rt::RandomStream rng{rt::keyWithSalt(rt::rootKey(options.seed), 0x5ca1a4f1e1dull), 0};
  rt::field::ScalarField out;
  out.values.reserve(mesh.vertices.size());
  for (const rt::Vec3& v : mesh.vertices) {
    const double params[3] = {v.x(), v.y(), v.z()};
    Frame frame;
    frame.params = params;
    frame.rng = &rng;
    const double value = eval.num(spec.expression.at(0), frame);
    if (!std::isfinite(value))
      throw DeriveError{spec.loc, "R015",
                        "field " + spec.name + ": the expression is " + std::to_string(value) +
                            " at vertex " + std::to_string(out.values.size()) + " (" +
                            std::to_string(v.x()) + ", " + std::to_string(v.y()) + ", " +
                            std::to_string(v.z()) + "); it must be a finite number everywhere"};
    out.values.push_back(value);
  }
  return out;
}

}  // namespace

void SurfaceWorld::buildFields(const ir::Module& m, const rt::DeriveOptions& options,
                               const std::vector<std::string>& searchDirs) {
  Impl& w = *impl_;
  namespace field = rt::field;
  w.frames = w.geometry->frames();
  std::unique_ptr<field::FieldDesigner> designer;  // on the geometry's factorisation, made on first use
  for (const ir::FieldSpec& spec : m.fields) try {
    const field::FieldType type =
        spec.kind == "vector" ? field::FieldType::Vector : field::FieldType::Tensor;
    Impl::Field f;
    f.name = spec.name;
    std::string error;
    if (spec.kind == "scalar") {
      // A number per vertex from a field file, a picture's brightness under each vertex,
      // or an expression of the vertex's position.
      f.scalar = std::make_unique<field::ScalarField>();
      const std::string path = spec.path.empty() ? "" : rt::io::findFile(spec.path, searchDirs);
      if (spec.source == "expression") {
        *f.scalar = scalarFromExpression(m, spec, options, w.mesh);
      } else if (isPicturePath(spec.path)) {
        field::Picture picture;
        if (!picture.load(path, error)) throw DeriveError{spec.loc, "R015", "field " + spec.name + ": " + error};
        *f.scalar = field::scalarFromPicture(w.mesh, picture);
      } else if (!field::loadScalarField(path, w.mesh.vertexCount(), *f.scalar, error)) {
        throw DeriveError{spec.loc, "R015", "field " + spec.name + ": " + error};
      }
      f.values = std::make_unique<field::TangentField>(f.scalar->gradientField(w.frames));
    } else if (spec.source == "file") {
      std::optional<field::TangentField> loaded;
      if (!field::loadField(rt::io::findFile(spec.path, searchDirs), w.frames, loaded, error))
        throw DeriveError{spec.loc, "R015", "field " + spec.name + ": " + error};
      if (loaded->type() != type)
        throw DeriveError{spec.loc, "R015",
                          "field " + spec.name + ": \"" + spec.path + "\" holds a " +
                              (loaded->isTensor() ? "tensor" : "vector") + " field, the declaration says " +
                              spec.kind};
      f.values = std::make_unique<field::TangentField>(std::move(*loaded));
    } else if (spec.source == "image") {
      f.picture = std::make_unique<field::Picture>();
      if (!f.picture->load(rt::io::findFile(spec.path, searchDirs), error))
        throw DeriveError{spec.loc, "R015", "field " + spec.name + ": " + error};
      f.values = std::make_unique<field::TangentField>(field::imageField(w.frames, *f.picture));
    } else if (spec.source == "curvature") {
      f.values = std::make_unique<field::TangentField>(field::curvatureTensor(w.frames));
      f.curvature = true;
    } else {
      if (!designer) designer = std::make_unique<field::FieldDesigner>(w.geometry->heatGeodesics());
      if (!designer->ok())
        throw DeriveError{spec.loc, "R015",
                          "field " + spec.name + ": geodesic distances cannot be computed on this "
                          "surface (its Laplacian does not factorise)"};
      f.values = std::make_unique<field::TangentField>(w.frames, type);
      int smoothing = 0;  // applied once the elements are summed, wherever `smooth` stands
      for (const ir::FieldDesignSpec& item : spec.design) {
        if (item.kind == "smooth") {
          const auto* n = word(item, "iterations");
          smoothing += n ? static_cast<int>((*n)[0]) : 0;
          continue;
        }
        field::DesignElement e;
        static const std::pair<const char*, field::ElementKind> kKinds[] = {
            {"regular", field::ElementKind::Regular}, {"wedge", field::ElementKind::Wedge},
            {"trisector", field::ElementKind::Trisector}, {"node", field::ElementKind::Node},
            {"centre", field::ElementKind::Centre}, {"saddle", field::ElementKind::Saddle}};
        for (const auto& [name, kind] : kKinds)
          if (item.kind == name) e.kind = kind;
        if (const auto* v = word(item, "vertex")) {
          const double index = (*v)[0];
          if (!(index >= 0) || index >= static_cast<double>(w.mesh.vertexCount()))
            throw DeriveError{item.loc, "R015",
                              "field " + spec.name + ": vertex " + std::to_string(int64_t(index)) +
                                  " does not exist (the surface has " +
                                  std::to_string(w.mesh.vertexCount()) + " vertices)"};
          e.at = rt::surface::atVertex(w.mesh, static_cast<int>(index));
        } else if (const auto* at = word(item, "at")) {
          e.at = w.locator->closestPoint(Vec3((*at)[0], (*at)[1], (*at)[2]));
          if (!e.at.valid())
            throw DeriveError{item.loc, "R015", "field " + spec.name + ": the point after 'at' is not a number"};
        } else {
          e.at = w.locator->closestPoint(w.start);
        }
        if (const auto* d = word(item, "decay")) e.decay = (*d)[0];
        if (const auto* s = word(item, "strength")) e.strength = (*s)[0];
        const Vec3 n = e.at.normal(w.mesh);
        if (const auto* dir = word(item, "direction")) {
          e.direction = Vec3((*dir)[0], (*dir)[1], (*dir)[2]);
        } else {
          // `angle a`: degrees counter-clockwise from the world X axis laid into the
          // tangent plane (the default direction).
          const auto* a = word(item, "angle");
          e.direction = rt::field::rotateAbout(tangent(Vec3::UnitX(), n, Vec3::UnitY()), n,
                                               a ? (*a)[0] * kPi / 180.0 : 0.0);
        }
        if (w.deadline) w.deadline->check();
        if (!designer->add(e, *f.values, error))
          throw DeriveError{item.loc, "R015", "field " + spec.name + ": " + error};
      }
      field::SmoothOptions smoothOptions;
      smoothOptions.deadline = w.deadline;
      if (smoothing > 0) field::smooth(*f.values, smoothing, smoothOptions);
    }
    w.fields.push_back(std::move(f));
  } catch (const rt::TimeLimitReached& limit) {
    // Nothing can be derived without the field: an error, not a kept (empty) result.
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%g", limit.seconds);
    throw DeriveError{spec.loc, "R021",
                      "field " + spec.name + ": designing it did not end within --max-seconds " + seconds +
                          " (its design elements and smoothing iterations take longer); nothing was derived"};
  }
  w.fieldOfEnv.assign(m.environment.size(), -1);
  for (size_t k = 0; k < m.environment.size(); ++k)
    for (size_t i = 0; i < w.fields.size(); ++i)
      if (m.environment[k].kind == "field" && m.environment[k].name == w.fields[i].name)
        w.fieldOfEnv[k] = static_cast<int>(i);
}

rt::Scope SurfaceWorld::startScope() const {
  rt::Scope s;
  const SurfacePoint p = impl_->locator->closestPoint(impl_->start);
  Vec3 x = Vec3::UnitX();
  if (!impl_->fields.empty()) impl_->fields[0].values->direction(p, x);  // else keep world X
  impl_->place(s, p, x);
  return s;
}

rt::Scope SurfaceWorld::startScopeAt(const Vec3& point, const Vec3* direction) const {
  rt::Scope s;
  const SurfacePoint p = impl_->locator->closestPoint(point);
  Vec3 x = Vec3::UnitX();
  if (direction)
    x = *direction;
  else if (!impl_->fields.empty())
    impl_->fields[0].values->direction(p, x);
  impl_->place(s, p, x);
  return s;
}

void SurfaceWorld::placeOn(rt::Scope& s, int face, const Vec3& bary, const Vec3& x) const {
  impl_->place(s, SurfacePoint{face, bary}, x);
}

const SurfaceMesh& SurfaceWorld::mesh() const { return impl_->mesh; }

void SurfaceWorld::translate(rt::Scope& s, double tx, double ty, double tz, rt::Deadline* deadline) const {
  const Impl& w = *impl_;
  s.lift += tz;
  const SurfacePoint from = w.pointOf(s);
  const Vec3 n = from.normal(w.mesh);
  const double length = std::hypot(tx, ty);
  const Vec3 along = s.axes * Vec3(tx, ty, 0);
  if (length == 0 || (along - n * n.dot(along)).norm() <= kTinyDirection * length) {
    w.place(s, from, s.axes.col(0));
    return;
  }
  const Vec3 d = tangent(along, n, s.axes.col(0));
  const Vec3 x = tangent(s.axes.col(0), n, s.axes.col(1));
  Vec3 u;
  double a = 0, b = 0, ax = 0, bx = 0;
  if (!w.fields.empty() && w.fields[0].values->isAsymmetric() &&
      rt::field::EigenBasisDirection::coordinates(*w.fields[0].values, from, d, a, b) &&
      rt::field::EigenBasisDirection::coordinates(*w.fields[0].values, from, x, ax, bx)) {
    // An asymmetric tensor field: the curve and the scope's X keep their coordinates in
    // the eigenvector basis (eigen_basis_direction.h).
    const rt::field::EigenBasisDirection guide(*w.fields[0].values, a, b);
    const rt::field::TraceResult r = rt::field::traceField(w.mesh, guide, from, d, 0.0, length, deadline);
    const rt::field::Eigen2 e = w.fields[0].values->eigen(r.end);
    const double sign = guide.combination(r.end).dot(r.direction) < 0 ? -1.0 : 1.0;
    const Vec3 xEnd = sign * (ax * e.vector1 + bx * e.vector2);
    w.place(s, r.end, xEnd.norm() > 0 ? xEnd : r.direction);
    return;
  }
  if (!w.fields.empty() && w.fields[0].values->direction(from, u)) {
    // Along the first field: the curve keeps the angle the move makes with the field,
    // and the scope keeps the angle its X axis makes with it (FGSG §4.3, Fig. 8).
    const rt::field::DirectionField& guide = *w.fields[0].values;
    if (guide.isLineField() && u.dot(d) < 0) u = -u;  // the eigenvector's sign on d's side
    const double angle = rt::field::orientedAngle(u, d, n);
    const double keepX = rt::field::orientedAngle(u, x, n);
    const rt::field::TraceResult r = rt::field::traceField(w.mesh, guide, from, d, angle, length, deadline);
    const Vec3 nEnd = r.end.normal(w.mesh);
    const Vec3 uEnd = r.fieldDirection.norm() > 0 ? r.fieldDirection
                                                  : rt::field::rotateAbout(r.direction, nEnd, -angle);
    w.place(s, r.end, rt::field::rotateAbout(uEnd, nEnd, keepX));
    return;
  }
  // Without a field the scope rides a straightest geodesic and keeps its angle to it.
  const double keep = rt::field::orientedAngle(d, x, n);
  const rt::field::TraceResult r = rt::field::traceGeodesic(w.mesh, from, d, length, deadline);
  const Vec3 nEnd = r.end.normal(w.mesh);
  w.place(s, r.end, rt::field::rotateAbout(r.direction, nEnd, keep));
}

void SurfaceWorld::rotateAboutNormal(rt::Scope& s, double degrees) const {
  const Vec3 n = impl_->pointOf(s).normal(impl_->mesh);
  s.axes = Eigen::AngleAxisd(degrees * kPi / 180.0, n).toRotationMatrix() * s.axes;
}

namespace {

// The signed curvature of the field's streamline (a tensor's hyperstreamline) through p:
// with u the unit direction and J the Jacobian of the field |value| u, the curve bends
// by (n x u) . (J u) / |value| (counter-clockwise about the normal positive, relative to u,
// whose sign a tensor field leaves arbitrary). Where the field vanishes: 0.
double streamlineCurvature(const rt::field::TangentField& f, const SurfacePoint& p,
                           const rt::Vec3& u, double value, rt::field::Eigenvector which) {
  if (!(std::abs(value) > 0)) return 0.0;
  const rt::Vec3 n = p.normal(f.mesh());
  return n.cross(u).dot(f.jacobianWorld(p, which) * u) / std::abs(value);
}

[[noreturn]] void notAnswered(ir::Loc at, const std::string& field, const std::string& member,
                              const std::string& why) {
  throw DeriveError{at, "R016", field + "." + member + ": " + why};
}

}  // namespace

const rt::field::TangentField& SurfaceWorld::fieldAt(uint32_t env, ir::Loc at) const {
  const int i = env < impl_->fieldOfEnv.size() ? impl_->fieldOfEnv[env] : -1;
  if (i < 0) throw DeriveError{at, "R900", "internal error: a field query without its field"};
  return *impl_->fields[i].values;
}

double SurfaceWorld::fieldNumber(const rt::Scope& s, uint32_t env, const std::string& member,
                                 ir::Loc at) const {
  namespace field = rt::field;
  const field::TangentField& f = fieldAt(env, at);
  const Impl::Field& named = impl_->fields[impl_->fieldOfEnv[env]];
  const SurfacePoint p = impl_->pointOf(s);
  if (named.scalar) {
    // A scalar field answers its value and its gradient's length; the direction queries
    // read its gradient field.
    if (member == "value" || member == "value1") return named.scalar->at(impl_->mesh, p);
    if (member == "length" || member == "length1") return named.scalar->gradient(impl_->mesh, p.face).norm();
    if (member == "value2" || member == "length2") return 0.0;
  }
  const field::Eigen2 e = f.eigen(p);
  if (member == "value" || member == "value1") return e.value1;
  if (member == "value2") return e.value2;
  if (member == "length" || member == "length1") return std::abs(e.value1);
  if (member == "length2") return std::abs(e.value2);
  if (member == "Xangle" || member == "Xangle1") return f.angle(p, s.axes.col(0));
  if (member == "Xangle2") return f.angle(p, s.axes.col(0), field::Eigenvector::Minor);
  if (member == "Yangle1") return f.angle(p, s.axes.col(1));
  if (member == "div" || member == "div1") return f.divergence(p);
  if (member == "div2") return f.divergence(p, field::Eigenvector::Minor);
  if (member == "streamcurv1" || member == "streamcurv2") {
    const bool minor = member == "streamcurv2";
    return streamlineCurvature(f, p, minor ? e.vector2 : e.vector1, minor ? e.value2 : e.value1,
                               minor ? field::Eigenvector::Minor : field::Eigenvector::Major);
  }
  if (member == "tensorXX" || member == "tensorXY" || member == "tensorYX" || member == "tensorYY") {
    // The tensor's components along the scope's X and Y axes, laid into the tangent plane.
    const Vec3 n = p.normal(impl_->mesh);
    const auto inPlane = [&](const Vec3& a) { return Vec3((a - a.dot(n) * n).normalized()); };
    const Vec3 x = inPlane(s.axes.col(0)), y = inPlane(s.axes.col(1));
    const rt::Mat3 t = f.tensorWorld(p);
    return member == "tensorXX"   ? x.dot(t * x)
           : member == "tensorXY" ? x.dot(t * y)
           : member == "tensorYX" ? y.dot(t * x)
                                  : y.dot(t * y);
  }
  // An asymmetric tensor's rotational part, and the angle between its eigenvectors
  // (degrees: 90 for a symmetric tensor, a vector field or the complex domain's
  // dual-eigenvectors; 0 where the eigenvectors meet).
  if (member == "rotation") return f.rotation(p);
  if (member == "eigenangle") {
    const double c = std::clamp(std::abs(e.vector1.dot(e.vector2)), 0.0, 1.0);
    return std::acos(c) * 180 / kPi;
  }
  if (member == "intensity") {
    if (!named.picture)
      notAnswered(at, named.name, member, "only a field made from a picture (`image(\"...\")`) has an "
                                          "intensity");
    return named.picture->under(impl_->mesh, p.position(impl_->mesh));
  }
  if (member == "mincurv" || member == "maxcurv" || member == "meancurv" || member == "gausscurv") {
    if (!named.curvature)
      notAnswered(at, named.name, member, "curvatures are answered by a curvature field (`field " +
                                              named.name + " = curvature;`)");
    const field::Curvatures c = field::curvaturesAt(f, p);
    return member == "mincurv" ? c.min : member == "maxcurv" ? c.max : member == "meancurv" ? c.mean : c.gauss;
  }
  notAnswered(at, named.name, member, "not a number-valued field member");
}

rt::Vec3 SurfaceWorld::fieldVector(const rt::Scope& s, uint32_t env, const std::string& member,
                                   ir::Loc at) const {
  namespace field = rt::field;
  const field::TangentField& f = fieldAt(env, at);
  const SurfacePoint p = impl_->pointOf(s);
  const Impl::Field& named = impl_->fields[impl_->fieldOfEnv[env]];
  if (named.scalar && (member == "gradient" || member == "vector" || member == "vector1"))
    return named.scalar->gradient(impl_->mesh, p.face);
  const field::Eigen2 e = f.eigen(p);
  const Vec3 n = p.normal(impl_->mesh);
  if (member == "vector") return f.isTensor() ? Vec3(e.value1 * e.vector1) : f.vector(p);
  if (member == "vector1") return e.value1 * e.vector1;
  if (member == "vector2") return e.value2 * e.vector2;
  if (member == "curl" || member == "curl1") return f.curl(p) * n;
  if (member == "curl2") return f.curl(p, field::Eigenvector::Minor) * n;
  if (member == "gradient") {
    // Of the major eigenvalue (a vector field: its length), as a world tangent vector:
    // J^T v for the unit direction v, with J the eigenvector field's Jacobian.
    return f.jacobianWorld(p).transpose() * e.vector1;
  }
  if (member == "rgb") {
    if (!named.picture)
      notAnswered(at, named.name, member, "only a field made from a picture (`image(\"...\")`) has colours");
    return named.picture->colourUnder(impl_->mesh, p.position(impl_->mesh));
  }
  if (member == "gradient2") return f.jacobianWorld(p, field::Eigenvector::Minor).transpose() * e.vector2;
  // The Jacobian applied to the scope's X or Y axis: how the (eigenvector) field changes
  // per unit of length along it.
  if (member == "jacobianX" || member == "jacobianY")
    return f.jacobianWorld(p) * s.axes.col(member == "jacobianX" ? 0 : 1).normalized();
  if (member == "jacobianX2" || member == "jacobianY2")
    return f.jacobianWorld(p, field::Eigenvector::Minor) * s.axes.col(member == "jacobianX2" ? 0 : 1).normalized();
  notAnswered(at, impl_->fields[impl_->fieldOfEnv[env]].name, member, "not a vector-valued field member");
}

void SurfaceWorld::environmentQuery(const Vec3& point, double* out, uint32_t n, ir::Loc at) const {
  const Impl& w = *impl_;
  if (w.fields.empty())
    throw DeriveError{at, "R016", "the environmental query ?E reads the first field: declare one (`field F = ...;`)"};
  const Impl::Field& first = w.fields.front();
  const SurfacePoint p = w.locator->closestPoint(point);
  if (first.scalar) {
    if (n > 0) out[0] = first.scalar->at(w.mesh, p);
    return;
  }
  const rt::field::TangentField& f = *first.values;
  Vec3 v;
  if (f.isTensor()) {
    const rt::field::Eigen2 e = f.eigen(p);
    v = e.value1 * e.vector1;
  } else {
    v = f.vector(p);
  }
  for (uint32_t k = 0; k < std::min<uint32_t>(n, 3); ++k) out[k] = v[k];
}

namespace {

// Fast marching's update of corner c from corners a and b of one triangle, whose
// distances da and db are known: the distance from a virtual point source unfolded into
// the triangle's plane, when its ray to c crosses the edge ab; else along an edge.
double marchUpdate(const Vec3& a, const Vec3& b, const Vec3& c, double da, double db) {
  const double viaEdges = std::min(da + (c - a).norm(), db + (c - b).norm());
  const Vec3 ab = b - a;
  const double L = ab.norm();
  if (L == 0) return viaEdges;
  const Vec3 e = ab / L;
  // Source s in the plane with |s - a| = da, |s - b| = db, on the far side of ab from c.
  const double x = (da * da - db * db + L * L) / (2 * L);
  const double h2 = da * da - x * x;
  if (h2 < 0) return viaEdges;
  const Vec3 ac = c - a;
  Vec3 n = ac - e * e.dot(ac);  // towards c, orthogonal to ab
  const double nLen = n.norm();
  if (nLen == 0) return viaEdges;
  n /= nLen;
  const Vec3 s = a + e * x - n * std::sqrt(h2);
  // The straight path s -> c must cross the segment ab (upwind condition).
  const double cx = e.dot(ac), cy = nLen, sy = -std::sqrt(h2);
  const double t = -sy / (cy - sy);  // where the path meets the line of ab
  const double crossX = x + t * (cx - x);
  if (crossX < 0 || crossX > L) return viaEdges;
  return std::min(viaEdges, (c - s).norm());
}

}  // namespace

double SurfaceWorld::geodesicDistance(const rt::Scope& a, const rt::Scope& b, double limit) const {
  const Impl& w = *impl_;
  const SurfaceMesh& m = w.mesh;
  const SurfacePoint p = w.pointOf(a), q = w.pointOf(b);
  const Vec3 from = p.position(m), to = q.position(m);
  if (p.face == q.face) return (from - to).norm();
  std::call_once(w.vertexFacesBuilt, [&] {
    w.vertexFaces.resize(m.vertexCount());
    for (size_t f = 0; f < m.faceCount(); ++f)
      for (int k = 0; k < 3; ++k) w.vertexFaces[m.faces[f][k]].push_back(static_cast<int>(f));
  });
  // Distances grow outward from p's corners (reached straight from p); a corner is final
  // when it leaves the queue, and updates the corners of its triangles from there.
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
  std::unordered_map<int, double> dist;
  std::unordered_map<int, bool> done;
  auto offer = [&](int v, double d) {
    auto it = dist.find(v);
    if (it == dist.end() || d < it->second) {
      dist[v] = d;
      open.push({d, v});
    }
  };
  for (int k = 0; k < 3; ++k) offer(m.faces[p.face][k], (m.vertices[m.faces[p.face][k]] - from).norm());
  double best = limit;
  const auto& target = m.faces[q.face];
  while (!open.empty()) {
    const auto [d, v] = open.top();
    open.pop();
    if (done[v] || d > dist[v]) continue;
    if (d >= best) break;
    done[v] = true;
    for (int k = 0; k < 3; ++k)
      if (target[k] == v) best = std::min(best, d + (m.vertices[v] - to).norm());
    for (int f : w.vertexFaces[v]) {
      const auto& t = m.faces[f];
      for (int k = 0; k < 3; ++k) {
        const int c = t[k];
        if (c == v || done[c]) continue;
        const int o = t[0] != v && t[0] != c ? t[0] : t[1] != v && t[1] != c ? t[1] : t[2];
        double dc = d + (m.vertices[c] - m.vertices[v]).norm();
        if (done[o]) dc = std::min(dc, marchUpdate(m.vertices[v], m.vertices[o], m.vertices[c], d, dist[o]));
        if (dc < best) offer(c, dc);
      }
    }
  }
  return best;
}

rt::Mesh SurfaceWorld::surfaceMesh() const {
  rt::Mesh out;
  const SurfaceMesh& m = impl_->mesh;
  for (size_t v = 0; v < m.vertexCount(); ++v)
    for (int k = 0; k < 3; ++k) {
      out.positions.push_back(static_cast<float>(m.vertices[v][k]));
      out.normals.push_back(static_cast<float>(m.vertexNormals[v][k]));
    }
  for (const auto& f : m.faces)
    for (int k = 0; k < 3; ++k) out.indices.push_back(static_cast<uint32_t>(f[k]));
  return out;
}

size_t SurfaceWorld::faceCount() const { return impl_->mesh.faceCount(); }

std::vector<std::pair<std::string, const rt::field::TangentField*>> SurfaceWorld::fields() const {
  std::vector<std::pair<std::string, const rt::field::TangentField*>> out;
  for (const auto& f : impl_->fields) out.emplace_back(f.name, f.values.get());
  return out;
}

}  // namespace fgsg::backend
