#include "backend/commands/scatter_command.h"

#include "backend/engine/derivation.h"
#include "runtime/cga/scatter.h"

#include <charconv>
#include <cmath>
#include <string>

namespace fgsg::backend {

void applyScatter(Derivation& d, const ir::Op& op, const double* a, uint32_t n, State& st, Exec& ex, Frame& f) {
  auto fail = [&](const std::string& why) { throw DeriveError{op.loc, "R002", "Scatter: " + why}; };
  auto text = [](double v) {  // the shortest digits that read back as v
    char buf[32];
    return std::string(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
  };
  const double count = a[1];
  if (!(std::isfinite(count) && count >= 0))
    fail("the number of points must be 0 or more, not " + text(count));
  // CityEngine's nPoints is a float: its whole part. Each point is a shape (--max-shapes).
  const double points = std::floor(count);
  if (points > static_cast<double>(d.options().maxShapes))
    fail(text(points) + " points are more shapes than --max-shapes (" +
         std::to_string(d.options().maxShapes) + ") allows");
  // The words arrive as their codes (frontend/shape_operations.cpp); fgsg's dialect also
  // lets a number stand there, which must be one of them.
  auto code = [&](uint32_t k, int last, const char* words) {
    if (!(a[k] >= 0 && a[k] <= last && a[k] == std::floor(a[k]))) fail(std::string("this argument is ") + words);
    return static_cast<int>(a[k]);
  };
  rt::cga::ScatterSpec spec;
  spec.domain = static_cast<rt::cga::ScatterDomain>(code(0, 2, "\"surface\", \"volume\" or \"scope\""));
  spec.gaussian = code(2, 1, "\"uniform\" or \"gaussian\"") == 1;
  if (!spec.gaussian && n > 3) fail("a mean and a deviation belong to the \"gaussian\" distribution");
  if (n > 3) spec.mean = static_cast<rt::cga::ScatterMean>(code(3, 6, "\"center\", \"front\", \"back\", \"left\", "
                                                                     "\"right\", \"top\" or \"bottom\""));
  if (n > 4) spec.stddev = a[4], spec.relative = n > 5 && code(5, 1, "\"absolute\" or \"relative\"") == 1;
  rt::cga::ScatterSampler sampler;
  std::string error;
  if (!sampler.prepare(st.scope, st.geom, d.arena(), spec, error)) throw DeriveError{op.loc, "R002", error};
  if (points == 0 || sampler.empty()) return;  // a surface without area has no points (an edge)
  // The points' own stream: the shape's gives up one number for it.
  rt::RandomStream stream{rt::keyWithSalt(ex.rng->key, rt::mix64(ex.rng->counter++ ^ 0x5ca77e7ull)), 0};
  rt::Scope point;
  for (uint64_t i = 0, total = static_cast<uint64_t>(points); i < total; ++i) {
    if (d.deadline().expired()) throw d.timeLimit();  // --max-seconds, also between bodies that draw little
    bool drawn = false;
    try {
      drawn = sampler.next(stream, point, error, &d.deadline());
    } catch (const rt::TimeLimitReached&) {  // within one point's draws
      throw d.timeLimit();
    }
    if (!drawn) throw DeriveError{op.loc, "R002", error};
    d.runBody(op, 0, point, rt::GeomRef{}, st, ex, f);
    if (ex.culled) return;
  }
}

}  // namespace fgsg::backend
