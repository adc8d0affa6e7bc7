#include "runtime/plugins/plugin_library.h"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>

namespace fgsg::rt {

namespace fs = std::filesystem;

std::string findLibraryDir(const std::string& fileName, std::string& error) {
  std::error_code ec;
  fs::path dir;
  const char* env = std::getenv("FGSG_LIBDIR");
  const bool fromEnv = env && *env;
  if (fromEnv) {
    dir = fs::absolute(env, ec);
  } else {
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (ec) {
      error = "cannot find the running fgsg executable (/proc/self/exe: " + ec.message() +
              "); set FGSG_LIBDIR to the folder that holds " + fileName;
      return "";
    }
    dir = exe.parent_path().parent_path() / "lib";
  }
  const fs::path lib = dir / fileName;
  if (!fs::is_regular_file(lib, ec)) {
    error = fileName + " is not in " + dir.lexically_normal().string() +
            (fromEnv ? " (FGSG_LIBDIR)" : " (the lib/ folder beside fgsg's bin/)") +
            ": build fgsg's libraries (cmake --build) or set FGSG_LIBDIR to the folder that holds it";
    return "";
  }
  const fs::path canonical = fs::canonical(dir, ec);
  return (ec ? dir.lexically_normal() : canonical).string();
}

void* openPlugin(const std::string& fileName, const char* entry) {
  std::string error;
  const std::string dir = findLibraryDir(fileName, error);
  if (dir.empty()) throw PluginError(error);
  const std::string file = dir + "/" + fileName;
  // Never closed: the plugin's static objects and threads may outlive any one use of it.
  void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    // dlopen says why only in words; mapping failures mean the address space ran out.
    const std::string why = dlerror();
    const bool noMemory = why.find("failed to map segment") != std::string::npos ||
                          why.find("Cannot allocate memory") != std::string::npos;
    throw PluginError("cannot load " + file + ": " + why, noMemory);
  }
  void* fn = dlsym(handle, entry);
  if (!fn) throw PluginError(file + " is not a plugin of this fgsg (it lacks " + entry + ")");
  return fn;
}

}  // namespace fgsg::rt
