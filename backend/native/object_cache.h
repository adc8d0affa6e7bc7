// Compiled grammars kept on disk between runs, under a key that hashes everything the
// code depends on (the grammar's IR and source, the LLVM version, this CPU and this
// build of fgsg). Each entry is the object file the JIT links (KEY.o) and, where the
// system's C compiler can link it, the same code as a shared library (KEY.so) that a
// run loads with dlopen alone: a cached run never loads LLVM (issue #18).
//
// Folder: $FGSG_CACHE_DIR, else $XDG_CACHE_HOME/fgsg, else ~/.cache/fgsg.
// FGSG_CACHE_DIR=off disables it. A cache that cannot be written is not an error: the
// code is compiled each time.
#pragma once

#include "backend/native/program_compiler.h"
#include "ir/ir.h"

#include <optional>
#include <string>

namespace fgsg::backend::native {

class ObjectCache {
 public:
  ObjectCache();  // the folder from the environment, as above
  explicit ObjectCache(std::string folder);  // empty: disabled

  // The key of a grammar's compiled code for this machine and build (32 hex digits).
  static std::string key(const ir::Module& m, const std::string& source);

  std::optional<std::string> load(const std::string& key) const;
  bool store(const std::string& key, const std::string& object) const;  // best effort: false if not stored

  // KEY.so linked from `object` ($FGSG_CC or cc; best effort, false if not stored).
  bool storeLibrary(const std::string& key, const std::string& object) const;
  // The program in KEY.so, loaded without LLVM; nothing when there is none or it cannot
  // be loaded (a stale or foreign file: the caller compiles and replaces it). Needs the
  // process to export the runtime's entry points (fgsg_rt_*, CMake: fgsg_export_runtime_abi).
  std::optional<CompiledProgram> loadLibrary(const std::string& key) const;

  const std::string& folder() const { return folder_; }

 private:
  std::string path(const std::string& key, const char* extension) const;
  std::string folder_;
};

}  // namespace fgsg::backend::native
