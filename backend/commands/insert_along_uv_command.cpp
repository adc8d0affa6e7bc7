#include "backend/commands/insert_along_uv_command.h"

#include "backend/engine/derivation.h"
#include "runtime/cga/insert_along_uv.h"

#include <cmath>
#include <string>

namespace fgsg::backend {

bool isInsertAlongUv(const ir::Module& m, const ir::Op& op) {
  return op.kind == ir::OpKind::ShapeOperation && op.str < m.strings.size() && m.strings[op.str] == "InsertAlongUV";
}

void applyInsertAlongUv(Derivation& d, const ir::Op& op, const double* a, uint32_t n, State& st) {
  const double set = a[0];
  if (!(set >= 0 && set <= 9 && set == std::floor(set)))
    throw DeriveError{op.loc, "R002", "InsertAlongUV: the uv set must be a whole number from 0 to 9"};
  const uint32_t uvSet = static_cast<uint32_t>(set);
  const rt::cga::UvProjection* projection = d.uvProjection(st.scope.projection, uvSet);
  if (!projection || !projection->coordinates)
    throw DeriveError{op.loc, "R002",
                      "InsertAlongUV: the shape has no uvs in set " + std::to_string(uvSet) +
                          (projection ? " (deleteUV took them away)"
                                      : " (no setupProjection, texture or Texture above it set one up)")};
  const ir::Module& m = d.module();
  if (op.asset >= m.assets.size()) throw DeriveError{op.loc, "R900", "internal: InsertAlongUV without its asset"};
  std::string error;
  const int mesh = d.assets().resolve(m.assets[op.asset], error);
  if (mesh < 0) throw DeriveError{op.loc, "R003", error};
  rt::cga::AlongUvOptions options;
  options.height = a[2];
  options.vertexNormals = n > 3 && a[3] == 1;
  options.keepPosition = n > 4 && a[4] == 1;
  options.up = st.scope.Y();
  options.deadline = &d.deadline();
  rt::cga::Part part;
  bool inserted = false;
  try {
    inserted = rt::cga::insertAlongUv(st.scope, st.geom, d.arena(), *projection, d.assets().mesh(mesh),
                                      d.assets().sourceBox(mesh), options, part, error);
  } catch (const rt::TimeLimitReached&) {  // --max-seconds inside one shape's insertion: R004 here
    LimitReached limit = d.timeLimit();
    limit.loc = op.loc;
    throw limit;
  }
  if (!inserted) throw DeriveError{op.loc, "R002", error};
  st.scope = part.scope;
  st.geom = part.geom;
}

}  // namespace fgsg::backend
