#include "runtime/io/temp_cleanup.h"

#include <atomic>
#include <climits>
#include <csignal>
#include <cstring>
#include <mutex>
#include <unistd.h>

namespace fgsg::rt::io {

namespace {

// A slot is Free, Filling (its path being copied), or Ready (the handler may unlink it).
enum SlotState : int { Free = 0, Filling = 1, Ready = 2 };

constexpr int kSlots = 64;  // outputs of one command, times the C API's threads

struct Slot {
  std::atomic<int> state{Free};
  char path[PATH_MAX];
};

Slot slots[kSlots];

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

extern "C" void removeTempsAndReraise(int sig) {
  const int savedErrno = errno;
  for (Slot& s : slots)
    if (s.state.load(std::memory_order_acquire) == Ready) ::unlink(s.path);
  // Die (or do whatever the default is) as the signal intended: the exit status and the
  // shell's view of the process stay those of an interrupted run.
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  sigemptyset(&dfl.sa_mask);
  ::sigaction(sig, &dfl, nullptr);
  ::raise(sig);
  errno = savedErrno;
}

void installHandlers() {
  for (int sig : kSignals) {
    struct sigaction old {};
    if (::sigaction(sig, nullptr, &old) != 0 || (old.sa_flags & SA_SIGINFO) || old.sa_handler != SIG_DFL)
      continue;  // ignored or handled by the host program: leave it alone
    struct sigaction act {};
    act.sa_handler = removeTempsAndReraise;
    sigemptyset(&act.sa_mask);
    for (int other : kSignals) sigaddset(&act.sa_mask, other);
    ::sigaction(sig, &act, nullptr);
  }
  struct sigaction old {};
  if (::sigaction(SIGXFSZ, nullptr, &old) == 0 && !(old.sa_flags & SA_SIGINFO) && old.sa_handler == SIG_DFL) {
    struct sigaction ign {};
    ign.sa_handler = SIG_IGN;
    sigemptyset(&ign.sa_mask);
    ::sigaction(SIGXFSZ, &ign, nullptr);
  }
}

}  // namespace

int registerTempForCleanup(const char* path) {
  static std::once_flag installed;
  std::call_once(installed, installHandlers);
  const size_t n = std::strlen(path);
  if (n >= PATH_MAX) return -1;
  for (int i = 0; i < kSlots; ++i) {
    int expected = Free;
    if (!slots[i].state.compare_exchange_strong(expected, Filling, std::memory_order_acq_rel)) continue;
    std::memcpy(slots[i].path, path, n + 1);
    slots[i].state.store(Ready, std::memory_order_release);
    return i;
  }
  return -1;
}

void releaseTempCleanup(int slot) {
  if (slot < 0 || slot >= kSlots) return;
  slots[slot].state.store(Free, std::memory_order_release);
}

}  // namespace fgsg::rt::io
