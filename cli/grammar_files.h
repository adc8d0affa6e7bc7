// The files a grammar reads besides its own text — its surface mesh, field files, textures,
// asset meshes, synthesis examples, images named in strings — as paths that exist now:
// what fgsg view watches so that saving any of them derives again.
#pragma once

#include "ir/ir.h"

#include <string>
#include <vector>

namespace fgsg::cli {

// Every name the grammar writes that could be a file (the surface's and fields' paths, the
// environment's, assets and string constants) looked up as a run looks it up: in the
// grammar's folder, its assets/ folder, then the working folder; `extra` (--surface) too.
std::vector<std::string> grammarDataFiles(const ir::Module& module, const std::string& grammarPath,
                                          const std::vector<std::string>& extra = {});

}  // namespace fgsg::cli
