#include "backend/native/object_cache.h"

#include "backend/aot/link_library.h"
#include "ir/printer.h"
#include "runtime/abi.h"
#include "runtime/io/atomic_file.h"
#include "runtime/io/cache_folder.h"
#include "runtime/io/content_hash.h"
#include "runtime/plugins/plugin_library.h"

// The version of the LLVM the plugin compiles with: a header, nothing is linked.
#include <llvm/Config/llvm-config.h>

#include <dlfcn.h>
#include <sys/stat.h>
#include <sys/utsname.h>

#if defined(__x86_64__) || defined(__i386__)
#include <cpuid.h>
#endif

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fgsg::backend::native {
namespace {

std::string fileIdentity(const std::string& path) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) return path + ":missing";
  return path + ":" + std::to_string(st.st_size) + ":" + std::to_string(st.st_mtim.tv_sec) + "." +
         std::to_string(st.st_mtim.tv_nsec);
}

// Identifies this build of fgsg: the file holding this code (the executable or
// libfgsg.so) and the code generator's plugin beside it, by size and modification time.
// A rebuilt code generator is a new file, so its objects never mix with the old one's.
std::string buildIdentity() {
  std::string id;
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&buildIdentity), &info) && info.dli_fname) id = fileIdentity(info.dli_fname);
  std::string error;
  if (const std::string dir = rt::findLibraryDir("libfgsg_llvm.so", error); !dir.empty())
    id.append("|").append(fileIdentity(dir + "/libfgsg_llvm.so"));
  return id.empty() ? "unknown-build" : id;
}

// This CPU as the code generator sees it (the host CPU name and features LLVM derives
// from the same words), read without LLVM: on x86 the CPUID leaves and the OS's saved
// register state, elsewhere the kernel's description of the first processor.
void addCpuIdentity(rt::io::ContentHash& h) {
  utsname u{};
  if (uname(&u) == 0) h.bytes(u.machine, std::strlen(u.machine));
#if defined(__x86_64__) || defined(__i386__)
  unsigned a, b, c, d;
  for (unsigned leaf : {0u, 1u, 7u, 0xdu, 0x80000000u, 0x80000001u}) {
    if (!__get_cpuid_count(leaf, 0, &a, &b, &c, &d)) continue;
    if (leaf == 1) b &= 0x00ffffffu;  // bits 24-31: the APIC id of the core this runs on
    for (unsigned w : {leaf, a, b, c, d}) h.word(w);
  }
  if (__get_cpuid(1, &a, &b, &c, &d) && (c & bit_OSXSAVE)) {
    unsigned lo, hi;
    __asm__ volatile("xgetbv" : "=a"(lo), "=d"(hi) : "c"(0));
    h.word((uint64_t(hi) << 32) | lo);
  }
#else
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line) && !line.empty();)
    if (line.rfind("cpu MHz", 0) != 0 && line.rfind("BogoMIPS", 0) != 0) h.bytes(line.data(), line.size());
#endif
}

}  // namespace

ObjectCache::ObjectCache() : folder_(rt::io::cacheFolder()) {}
ObjectCache::ObjectCache(std::string folder) : folder_(std::move(folder)) {}

std::string ObjectCache::key(const ir::Module& m, const std::string& source) {
  static const std::string build = buildIdentity();
  rt::io::ContentHash h;
  auto add = [&](const std::string& part) { h.bytes(part.data(), part.size()); };
  add(ir::printModule(m));
  add(source);  // the IR's text leaves out source locations, which errors report
  add(LLVM_VERSION_STRING);
  addCpuIdentity(h);
  h.word(FGSG_ABI_VERSION);
  add(build);
  return h.hex();
}

std::string ObjectCache::path(const std::string& key, const char* extension) const {
  return folder_ + "/" + key + extension;
}

std::optional<std::string> ObjectCache::load(const std::string& key) const {
  if (folder_.empty()) return std::nullopt;
  std::ifstream in(path(key, ".o"), std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream bytes;
  bytes << in.rdbuf();
  std::string object = bytes.str();
  // A truncated or foreign file is a miss (the caller recompiles and replaces it).
  if (object.size() < 64 || object.compare(0, 4, "\x7f" "ELF") != 0) return std::nullopt;
  return object;
}

bool ObjectCache::store(const std::string& key, const std::string& object) const {
  if (folder_.empty()) return false;
  std::error_code ec;
  std::filesystem::create_directories(folder_, ec);
  std::string error;
  return rt::io::writeFileAtomically(path(key, ".o"), object, error);
}

bool ObjectCache::storeLibrary(const std::string& key, const std::string& object) const {
  if (folder_.empty()) return false;
  std::string error;
  return aot::linkSharedLibrary(object, path(key, ".so"), "", error);
}

std::optional<CompiledProgram> ObjectCache::loadLibrary(const std::string& key) const {
  if (folder_.empty()) return std::nullopt;
  const std::string file = path(key, ".so");
  struct stat st {};
  if (stat(file.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return std::nullopt;
  void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) return std::nullopt;
  std::shared_ptr<void> unit(handle, [](void* h) { dlclose(h); });
  const auto* program = static_cast<const FgsgProgram*>(dlsym(handle, "fgsg_program"));
  if (!program || program->abiVersion != FGSG_ABI_VERSION) return std::nullopt;
  return CompiledProgram(program, std::move(unit), true, true);
}

}  // namespace fgsg::backend::native
