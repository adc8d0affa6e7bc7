// Where fgsg keeps what it can rebuild (the JIT's objects, marching surfaces):
// $FGSG_CACHE_DIR, else $XDG_CACHE_HOME/fgsg, else ~/.cache/fgsg. FGSG_CACHE_DIR=off
// turns caching off (an empty folder). A cache that cannot be written is not an error.
#pragma once

#include <string>

namespace fgsg::rt::io {

std::string cacheFolder();

}  // namespace fgsg::rt::io
