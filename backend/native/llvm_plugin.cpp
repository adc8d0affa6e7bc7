#include "backend/native/llvm_plugin.h"

#include "backend/aot/link_library.h"

#include <dlfcn.h>

#include <atomic>
#include <mutex>
#include <stdexcept>

namespace fgsg::backend::native {
namespace {

std::atomic<const LlvmPlugin*> loaded{nullptr};

const LlvmPlugin* load() {
  std::string error;
  const std::string dir = aot::findLibraryDir("libfgsg_llvm.so", error);
  if (dir.empty()) throw std::runtime_error(error);
  const std::string file = dir + "/libfgsg_llvm.so";
  // Never closed: LLVM's static objects and a background compile's thread outlive any
  // one use of it.
  void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) throw std::runtime_error(std::string("cannot load ") + file + ": " + dlerror());
  using Entry = const LlvmPlugin* (*)();
  auto entry = reinterpret_cast<Entry>(dlsym(handle, kLlvmPluginEntry));
  const LlvmPlugin* plugin = entry ? entry() : nullptr;
  if (!plugin || plugin->version != kLlvmPluginVersion)
    throw std::runtime_error(file + " is not the compiler of this fgsg (another build or version)");
  return plugin;
}

}  // namespace

const LlvmPlugin& llvmPlugin() {
  static std::mutex mutex;
  std::lock_guard<std::mutex> lock(mutex);
  if (!loaded.load()) loaded.store(load());  // a failure is thrown again on the next call
  return *loaded.load();
}

bool llvmPluginLoaded() { return loaded.load() != nullptr; }

}  // namespace fgsg::backend::native
