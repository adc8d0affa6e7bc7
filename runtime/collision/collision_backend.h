// What CollisionWorld (collision_world.h) asks of its implementation: FCL's mesh tests
// and the centre test, in fcl_collision_world.cpp. That file is built into the plugin
// lib/libfgsg_fcl.so, which fgsg opens the first time a grammar places an obstacle, so
// that loading libfcl (and octomap, libccd) costs no other command (issue #18);
// executables that link it in (tests, benchmarks, libfgsg.so) never open it.
#pragma once

#include "runtime/assets.h"
#include "runtime/collision/collision_world.h"
#include "runtime/scope.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>

namespace fgsg::rt {

class CollisionBackend {
 public:
  virtual ~CollisionBackend() = default;
  virtual bool collides(int mesh, const Mat4& unitBoxToWorld, const std::function<bool(size_t obstacle)>& confirm) = 0;
  virtual size_t add(int mesh, const Mat4& unitBoxToWorld) = 0;
  virtual void move(size_t id, const Mat4& unitBoxToWorld) = 0;
  virtual void rollback(size_t mark) = 0;
  virtual size_t size() const = 0;
  virtual uint64_t narrowPhaseTests() const = 0;
};

// Bump with any change to this table or the interface above.
constexpr int kCollisionPluginVersion = 1;

struct CollisionPlugin {
  int version;
  std::unique_ptr<CollisionBackend> (*makeWorld)(const AssetLibrary& assets, CollisionTest test, double radius);
};

// The implementation linked into this executable, else lib/libfgsg_fcl.so's, loaded on
// the first call. Throws PluginError (plugins/plugin_library.h) when it cannot be used.
const CollisionPlugin& collisionPlugin();

}  // namespace fgsg::rt

// The plugin's entry point, defined by fcl_collision_world.cpp.
extern "C" const fgsg::rt::CollisionPlugin* fgsg_fcl_plugin();
