// A one-line progress report for a command's long work: once a phase has run for a
// second, "fgsg run: deriving 3.4 s" on stderr, refreshed four times a second and erased
// when the command moves on or ends. Only when stderr is a terminal and not --quiet, so
// piped or redirected output stays clean.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace fgsg::cli {

class ProgressLine {
 public:
  // `command` prefixes the line ("fgsg run"); `enabled` false (--quiet): never prints.
  ProgressLine(std::string command, bool enabled);
  ~ProgressLine();  // erases the line
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  // The phase now running ("deriving"); its clock starts now. A string literal.
  void phase(const char* name);
  // Erases the line until the next phase (before the command prints messages).
  void clear();
  // Erases the line and prints nothing more (before the command's own output).
  void done();

 private:
  void run();

  std::string command_;
  std::atomic<const char*> phase_{nullptr};
  std::chrono::steady_clock::time_point since_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  bool shown_ = false;  // a line is on the terminal
  std::thread thread_;
};

}  // namespace fgsg::cli
