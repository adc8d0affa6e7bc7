#include "backend/native/llvm_plugin.h"

#include "runtime/plugins/plugin_library.h"

#include <atomic>
#include <mutex>
#include <stdexcept>

namespace fgsg::backend::native {
namespace {

std::atomic<const LlvmPlugin*> loaded{nullptr};

const LlvmPlugin* load() {
  using Entry = const LlvmPlugin* (*)();
  const LlvmPlugin* plugin = reinterpret_cast<Entry>(rt::openPlugin("libfgsg_llvm.so", kLlvmPluginEntry))();
  if (!plugin || plugin->version != kLlvmPluginVersion)
    throw rt::PluginError("libfgsg_llvm.so is not the compiler of this fgsg (another build or version)");
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
