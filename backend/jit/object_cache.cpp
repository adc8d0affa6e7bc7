#include "backend/jit/object_cache.h"

#include "ir/printer.h"
#include "runtime/abi.h"
#include "runtime/io/cache_folder.h"
#include "runtime/io/atomic_file.h"

#include <llvm/ADT/StringMap.h>
#include <llvm/ADT/StringRef.h>
#include <llvm/Config/llvm-config.h>
#include <llvm/Support/SHA256.h>
#include <llvm/TargetParser/Host.h>

#include <dlfcn.h>
#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fgsg::backend::jit {
namespace {

// Identifies this build of fgsg: the file holding this code (the executable or
// libfgsg.so) by its size and modification time. A rebuilt code generator is a new
// file, so its objects never mix with the old one's.
std::string buildIdentity() {
  Dl_info info{};
  struct stat st {};
  if (dladdr(reinterpret_cast<void*>(&buildIdentity), &info) && info.dli_fname &&
      stat(info.dli_fname, &st) == 0)
    return std::string(info.dli_fname) + ":" + std::to_string(st.st_size) + ":" +
           std::to_string(st.st_mtim.tv_sec) + "." + std::to_string(st.st_mtim.tv_nsec);
  return "unknown-build";
}

}  // namespace

ObjectCache::ObjectCache() : folder_(rt::io::cacheFolder()) {}
ObjectCache::ObjectCache(std::string folder) : folder_(std::move(folder)) {}

std::string ObjectCache::key(const ir::Module& m, const std::string& source) {
  static const std::string build = buildIdentity();
  llvm::SHA256 hash;
  auto add = [&](const std::string& part) {
    hash.update(llvm::StringRef(part));
    hash.update(llvm::StringRef("\0", 1));
  };
  add(ir::printModule(m));
  add(source);  // the IR's text leaves out source locations, which errors report
  add(LLVM_VERSION_STRING);
  add(llvm::sys::getProcessTriple());
  add(llvm::sys::getHostCPUName().str());
  std::string features;
  for (const auto& [name, on] : llvm::sys::getHostCPUFeatures())
    if (on) features += name.str() + ",";
  add(features);
  add(std::to_string(FGSG_ABI_VERSION));
  add(build);
  static const char* digits = "0123456789abcdef";
  std::string hex;
  for (uint8_t byte : hash.final()) {
    hex += digits[byte >> 4];
    hex += digits[byte & 15];
  }
  return hex.substr(0, 32);
}

std::string ObjectCache::path(const std::string& key) const { return folder_ + "/" + key + ".o"; }

std::optional<std::string> ObjectCache::load(const std::string& key) const {
  if (folder_.empty()) return std::nullopt;
  std::ifstream in(path(key), std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream bytes;
  bytes << in.rdbuf();
  std::string object = bytes.str();
  // A truncated or foreign file is a miss (the caller recompiles and replaces it).
  if (object.size() < 64 || object.compare(0, 4, "\x7f" "ELF") != 0) return std::nullopt;
  return object;
}

void ObjectCache::store(const std::string& key, const std::string& object) const {
  if (folder_.empty()) return;
  std::error_code ec;
  std::filesystem::create_directories(folder_, ec);
  std::string error;
  rt::io::writeFileAtomically(path(key), object, error);  // best effort: a miss next time
}

}  // namespace fgsg::backend::jit
