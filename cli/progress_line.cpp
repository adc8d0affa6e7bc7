#include "cli/progress_line.h"

#include <cstdio>
#include <cstdlib>
#include <unistd.h>

namespace fgsg::cli {

namespace {

constexpr auto kRefresh = std::chrono::milliseconds(250);

// Short work shows nothing: a phase appears after a second, or $FGSG_PROGRESS_DELAY
// seconds (0: at once).
std::chrono::steady_clock::duration quietFor() {
  const char* text = std::getenv("FGSG_PROGRESS_DELAY");
  char* end = nullptr;
  const double seconds = text && *text ? std::strtod(text, &end) : 1.0;
  const bool valid = !text || !*text || (end && *end == '\0' && seconds >= 0 && seconds < 1e6);
  return std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(valid ? seconds : 1.0));
}

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
  const auto quiet = quietFor();
  std::unique_lock<std::mutex> lock(mutex_);
  while (!wake_.wait_for(lock, kRefresh, [this] { return stopping_; })) {
    const char* name = phase_;
    const auto running = std::chrono::steady_clock::now() - since_;
    if (!name || running < quiet) continue;
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
