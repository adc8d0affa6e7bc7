// Wavefront OBJ from a Scene (runtime/output/scene.h) built without instancing (OBJ has
// none: every part is baked into world space): `o` per start shape named after it, `g`
// per group (--group-by symbol / rule / label; none under GroupBy::None), `usemtl` per
// material, and a .mtl beside it defining each material the OBJ uses: `Kd` its colour
// (white where the colours vary per vertex: then the vertices carry `r g b`), `map_Kd`
// its image relative to the .mtl's folder, `Pr`/`Pm` roughness and metallic as the glTF
// material's. Names have no spaces (`g` takes several names); numbers as the flattened
// OBJ writes them. The bytes depend only on the scene and where the .mtl goes.
#pragma once

#include "runtime/io/byte_sink.h"
#include "runtime/io/output_transaction.h"
#include "runtime/output/scene.h"

#include <string>

namespace fgsg::rt::output {

// The OBJ into `out`, naming `mtlFileName` with `mtllib` (none when empty). False and a
// message for a vertex that is not finite.
bool writeObjScene(const Scene& scene, io::ByteSink& out, const std::string& mtlFileName, std::string& error);

// The .mtl of the materials the OBJ uses, image paths relative to `mtlFolder`.
std::string mtlSceneText(const Scene& scene, const std::string& mtlFolder);

// Stages `path` (.obj) and the .mtl of the same name beside it in `outputs` (the .mtl
// first, so that commit never shows an OBJ without its materials).
bool stageObjScene(const Scene& scene, const std::string& path, io::OutputTransaction& outputs, std::string& error);

}  // namespace fgsg::rt::output
