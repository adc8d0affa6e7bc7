// fgsg run's structured glTF output: the scene (runtime/output/scene.h) built from the
// derivation, its start shapes named after the lots (or seeds, or the axiom) and its
// rule and label groups after the grammar's rules.
#pragma once

#include "cli/derive_flags.h"
#include "ir/ir.h"
#include "runtime/assets.h"
#include "runtime/derivation.h"
#include "runtime/io/output_transaction.h"

#include <string>
#include <vector>

namespace fgsg::cli {

// Whether `-o path` is written as a scene: asked by the flags, or a .gltf (which has no
// flattened writer).
bool writesScene(const SceneFlags& flags, const std::string& path);

// Builds the scene of `result` and stages it as `path` (.glb / .gltf) in `outputs`.
// False and a message (an image that cannot be embedded, a vertex not finite).
bool stageScene(const SceneFlags& flags, const ir::Module& module, const rt::DeriveOptions& derive,
                const rt::DeriveResult& result, const rt::AssetLibrary& assets, const std::vector<int>& meshOf,
                const std::string& path, rt::io::OutputTransaction& outputs, std::string& error);

}  // namespace fgsg::cli
