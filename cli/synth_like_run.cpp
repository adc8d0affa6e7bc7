#include "cli/synth_like_run.h"

#include <cstdio>
#include <filesystem>

namespace fgsg::cli {

void synthMaxSecondsFlag(CommandLine& cl, double& seconds) {
  auto check = [&seconds](const char* flag, const std::string& v) {
    seconds = CommandLine::parseNumber(flag, v);
    if (!(seconds > 0 && seconds <= 1e9)) throw UsageError{std::string(flag) + " needs seconds greater than 0, at most 1e9"};
  };
  cl.option("--max-seconds", [check](const std::string& v) { check("--max-seconds", v); });
  // A single-value option: CLI11 applies only its last occurrence, so this says it once.
  cl.option("--time-limit", [check](const std::string& v) {
    std::fputs("fgsg synth: warning: --time-limit is deprecated, use --max-seconds (as fgsg run)\n", stderr);
    check("--time-limit", v);
  });
}

std::string defaultModelOutput(const std::string& example) {
  return std::filesystem::path(example).stem().string() + ".glb";
}

void printStat(const char* name, uint64_t value) { std::printf("%s %llu\n", name, (unsigned long long)value); }

void printStatSeconds(const char* name, double seconds) { std::printf("time.%s %.6f\n", name, seconds); }

}  // namespace fgsg::cli
