#include "runtime/collision/collision_world.h"

#include "runtime/collision/collision_backend.h"
#include "runtime/plugins/plugin_library.h"

#include <mutex>
#include <stdexcept>

// Defined where fcl_collision_world.cpp is linked in; null in fgsg, which opens the plugin.
extern "C" __attribute__((weak)) const fgsg::rt::CollisionPlugin* fgsg_fcl_plugin();

namespace fgsg::rt {

const CollisionPlugin& collisionPlugin() {
  static std::mutex mutex;
  static const CollisionPlugin* loaded = nullptr;  // a failure is thrown again on the next call
  std::lock_guard<std::mutex> lock(mutex);
  if (!loaded) {
    using Entry = const CollisionPlugin* (*)();
    const Entry entry = fgsg_fcl_plugin ? &fgsg_fcl_plugin
                                        : reinterpret_cast<Entry>(openPlugin("libfgsg_fcl.so", "fgsg_fcl_plugin"));
    const CollisionPlugin* plugin = entry();
    if (!plugin || plugin->version != kCollisionPluginVersion)
      throw PluginError("libfgsg_fcl.so is not the collision plugin of this fgsg (another build or version)");
    loaded = plugin;
  }
  return *loaded;
}

CollisionWorld::CollisionWorld(const AssetLibrary& assets, CollisionTest test, double radius)
    : assets_(assets), test_(test), radius_(radius) {}

CollisionWorld::~CollisionWorld() = default;

CollisionBackend& CollisionWorld::backend() {
  if (!impl_) impl_ = collisionPlugin().makeWorld(assets_, test_, radius_);
  return *impl_;
}

// Before the first obstacle there is nothing to collide with, and nothing is loaded.
bool CollisionWorld::collides(int mesh, const Mat4& unitBoxToWorld, const std::function<bool(size_t)>& confirm) {
  return impl_ && impl_->collides(mesh, unitBoxToWorld, confirm);
}

size_t CollisionWorld::add(int mesh, const Mat4& unitBoxToWorld) { return backend().add(mesh, unitBoxToWorld); }

void CollisionWorld::move(size_t id, const Mat4& unitBoxToWorld) { backend().move(id, unitBoxToWorld); }

size_t CollisionWorld::mark() const { return size(); }

void CollisionWorld::rollback(size_t mark) {
  if (impl_) impl_->rollback(mark);
}

size_t CollisionWorld::size() const { return impl_ ? impl_->size() : 0; }
uint64_t CollisionWorld::narrowPhaseTests() const { return impl_ ? impl_->narrowPhaseTests() : 0; }

}  // namespace fgsg::rt
