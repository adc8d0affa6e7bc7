#pragma once
// OpenMesh's readers are process-wide singletons with per-read state (the OBJ reader keeps the
// file's path and materials) and its log streams are global switches, so threads that read meshes
// at once (Python threads, parallel batch jobs) must take turns. QuietOpenMesh holds the turn and
// silences omerr/omlog for its lifetime: we report problems ourselves, located.

#include <OpenMesh/Core/System/omstream.hh>

#include <mutex>

namespace fgsg::rt::io {

class QuietOpenMesh {
 public:
  QuietOpenMesh() : lock_(mutex()), errWasOn_(omerr().is_enabled()), logWasOn_(omlog().is_enabled()) {
    omerr().disable();
    omlog().disable();
  }
  ~QuietOpenMesh() {
    if (errWasOn_) omerr().enable();
    if (logWasOn_) omlog().enable();
  }
  QuietOpenMesh(const QuietOpenMesh&) = delete;
  QuietOpenMesh& operator=(const QuietOpenMesh&) = delete;

 private:
  static std::mutex& mutex() {
    static std::mutex m;
    return m;
  }
  std::lock_guard<std::mutex> lock_;
  bool errWasOn_, logWasOn_;
};

}  // namespace fgsg::rt::io
