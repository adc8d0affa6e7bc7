// How deep native recursion may go on the calling thread: the address below which a frame
// must not start, measured against the thread's real stack (its size comes from the
// thread's attributes, so a host's small pthread stack is respected as well as
// `ulimit -s`). Code that recurses compares its frame address with it and, past it,
// falls back to an iterative path instead of overflowing.
#pragma once

#include <cstdint>

namespace fgsg::rt {

// The lowest frame address recursion may reach on this thread, keeping `reserve` bytes
// (at least) for the calls made after it stops. 0 when the stack's extent is unknown
// (then no limit is applied).
uintptr_t stackFloor(uintptr_t reserve = 0);

// True when the caller's frame already lies below `floor` (a floor of 0 never is).
inline bool belowStackFloor(uintptr_t floor) {
  return reinterpret_cast<uintptr_t>(__builtin_frame_address(0)) < floor;
}

}  // namespace fgsg::rt
