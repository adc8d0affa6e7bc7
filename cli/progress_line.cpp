#include "cli/progress_line.h"

#include <cstdio>
#include <unistd.h>

namespace fgsg::cli {

namespace {

constexpr auto kQuietFor = std::chrono::seconds(1);       // short work shows nothing
constexpr auto kRefresh = std::chrono::milliseconds(250);

}  // namespace

ProgressLine::ProgressLine(std::string command, bool enabled) : command_(std::move(command)) {
  if (enabled && isatty(STDERR_FILENO)) thread_ = std::thread([this] { run(); });
}

ProgressLine::~ProgressLine() { done(); }

void ProgressLine::phase(const char* name) {
  std::lock_guard<std::mutex> lock(mutex_);
  since_ = std::chrono::steady_clock::now();
  phase_ = name;
}

void ProgressLine::clear() {
  std::lock_guard<std::mutex> lock(mutex_);
  phase_ = nullptr;
  if (shown_) {
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
    shown_ = false;
  }
}

void ProgressLine::done() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void ProgressLine::run() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!wake_.wait_for(lock, kRefresh, [this] { return stopping_; })) {
    const char* name = phase_;
    const auto running = std::chrono::steady_clock::now() - since_;
    if (!name || running < kQuietFor) continue;
    std::fprintf(stderr, "\r\033[K%s: %s %.1f s", command_.c_str(), name,
                 std::chrono::duration<double>(running).count());
    std::fflush(stderr);
    shown_ = true;
  }
  if (shown_) {
    std::fprintf(stderr, "\r\033[K");  // the command's own lines start on a clean line
    std::fflush(stderr);
  }
}

}  // namespace fgsg::cli
