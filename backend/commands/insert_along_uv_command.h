// CityEngine's insertAlongUV(uvSet, asset, height[, heightDirection, heightAlignment]) as
// fgsg's InsertAlongUV(uvSet, "asset", height[, "scope.y" | "vertex.normal"[, "alignPosition"
// | "keepPosition"]]) (an ir::OpKind::ShapeOperation named "InsertAlongUV", its asset in
// op.asset): the asset laid along the shape's uvs of that set (runtime/cga/insert_along_uv.h)
// becomes the shape's geometry, a baked mesh that a leaf outputs as its own geometry.
#pragma once

#include "backend/commands/command_family.h"

namespace fgsg::backend {

class Derivation;

// Whether `op` is an InsertAlongUV (its op.asset names an asset of the module).
bool isInsertAlongUv(const ir::Module& m, const ir::Op& op);

// a: the uv set, the asset's placeholder (op.asset holds it), the height, then optionally
// the direction (0 scope.y, 1 vertex.normal) and the alignment (0 alignPosition, 1
// keepPosition), as frontend/shape_operations.cpp codes them.
void applyInsertAlongUv(Derivation& d, const ir::Op& op, const double* a, uint32_t n, State& st);

}  // namespace fgsg::backend
