// Compiled grammars kept on disk between runs: one object file per key, where the key
// hashes everything the code depends on (the grammar's IR and source, the LLVM
// version, this CPU and this build of fgsg). A hit skips code generation entirely.
//
// Folder: $FGSG_CACHE_DIR, else $XDG_CACHE_HOME/fgsg, else ~/.cache/fgsg.
// FGSG_CACHE_DIR=off disables it. A cache that cannot be written is not an error: the
// code is compiled each time.
#pragma once

#include "ir/ir.h"

#include <optional>
#include <string>

namespace fgsg::backend::jit {

class ObjectCache {
 public:
  ObjectCache();  // the folder from the environment, as above
  explicit ObjectCache(std::string folder);  // empty: disabled

  // The key of a grammar's compiled code for this machine and build.
  static std::string key(const ir::Module& m, const std::string& source);

  std::optional<std::string> load(const std::string& key) const;
  void store(const std::string& key, const std::string& object) const;  // best effort

  const std::string& folder() const { return folder_; }

 private:
  std::string path(const std::string& key) const;
  std::string folder_;
};

}  // namespace fgsg::backend::jit
