// fgsg run's structured output: the scene (runtime/output/scene.h) built from the
// derivation, its start shapes named after the lots (or seeds, or the axiom) and its
// rule and label groups after the grammar's rules, written as glTF or OBJ, whole or a
// file per start shape (--split-output).
#pragma once

#include "cli/derive_flags.h"
#include "ir/ir.h"
#include "runtime/assets.h"
#include "runtime/derivation.h"
#include "runtime/io/output_transaction.h"

#include <string>
#include <vector>

namespace fgsg::cli {

// How a file is written under the flags, by its extension: .glb a scene unless
// `--instancing off --group-by none`; .gltf always a scene; .obj grouped (o/g, a .mtl
// per material) when --group-by other than none is given, else flattened; .ply flattened.
enum class OutputLayout { Flattened, GltfScene, ObjScene };

// The layout of `path` (empty: none, --split-output alone). Throws UsageError for an
// unknown extension, or a layout the format has not (instancing asked of OBJ, a scene of
// PLY, --split-output as PLY), and sets derive.recordOrigins where rule and label groups
// need them.
OutputLayout checkOutput(const SceneFlags& flags, const std::string& path, rt::DeriveOptions& derive);

// Whether `-o path` is written as a scene (else by rt::io::stageMesh, flattened).
bool writesScene(const SceneFlags& flags, const std::string& path);

// What stageScene and stageSplitOutput read of the run.
struct SceneSource {
  const ir::Module& module;
  const rt::DeriveOptions& derive;
  const rt::DeriveResult& result;
  const rt::AssetLibrary& assets;
  const std::vector<int>& meshOf;
};

// What a scene draws, for fgsg run's `wrote` line when no flattened mesh was assembled:
// its triangles (a shared mesh's in full for each instance, as the file draws them) and
// line segments.
struct SceneDrawn {
  size_t triangles = 0, lines = 0;
};

// Builds the scene of the run and stages it as `path` (.glb / .gltf / .obj with its .mtl)
// in `outputs`, and says what it draws in `drawn` (when given). False and a message (an
// image that cannot be embedded, a vertex not finite).
bool stageScene(const SceneFlags& flags, const SceneSource& run, const std::string& path,
                rt::io::OutputTransaction& outputs, std::string& error, SceneDrawn* drawn = nullptr);

// --split-output DIR: a file per start shape in DIR (created if missing), named after it
// (`lot-17.glb`; characters other than letters, digits, '-', '_' and '.' made '_', and
// `_N` after a name taken), in the format of `path` (.glb when it is empty or flattened
// .glb: the per-start scenes), and DIR/manifest.json listing them; all staged in
// `outputs`, so that they replace what was there together. `drawn` as stageScene's, for
// all the files together.
bool stageSplitOutput(const SceneFlags& flags, const SceneSource& run, const std::string& path,
                      rt::io::OutputTransaction& outputs, std::string& error, SceneDrawn* drawn = nullptr);

}  // namespace fgsg::cli
