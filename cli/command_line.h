// A subcommand's options, parsed by CLI11 (Debian: libcli11-dev) with fgsg's conventions:
// `--flag value` and `--flag=value`, the last of a repeated single-value option wins, every
// bad flag or value is a UsageError naming it (exit 2) — never a wrapped or truncated value.
// `fgsg CMD --help` is answered before a command runs (main.cpp), so CLI11's help is off.
#pragma once

#include "cli/commands.h"
#include "cli/options.h"

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace fgsg::cli {

class CommandLine {
 public:
  // `command` names the subcommand in messages ("run": see fgsg run --help).
  explicit CommandLine(std::string command);
  ~CommandLine();

  // The one positional argument, `what` naming it ("grammar file"); a second is an error.
  void input(std::string& file, std::string what);

  // `names`: CLI11's "-o,--output". A switch: present means true.
  void flag(const std::string& names, bool& target);
  void text(const std::string& names, std::string& target);
  // A whole number from lo to hi (plain digits only: no sign, no fraction, no blank).
  template <class Integer>
  void whole(const std::string& names, Integer& target, uint64_t lo = 0,
             uint64_t hi = std::numeric_limits<Integer>::max()) {
    option(names, [&target, lo, hi, flag = longName(names)](const std::string& v) {
      target = static_cast<Integer>(parseWhole(flag, v, lo, hi));
    });
  }
  // A finite number.
  void number(const std::string& names, double& target);
  // `--start 1,2.5,-3`: three finite numbers separated by commas.
  void point(const std::string& names, double (&target)[3]);
  // Any other value: `use` checks the text and applies it (throwing UsageError).
  void option(const std::string& names, std::function<void(const std::string&)> use);
  // Repeatable: `use` gets each occurrence's value in command-line order.
  void repeated(const std::string& names, std::function<void(const std::string&)> use);
  // minCount to maxCount values after the flag (`--size X Y Z`); `use` gets them all and
  // checks how many (CLI11 takes fewer than minCount when the arguments end).
  void values(const std::string& names, int minCount, int maxCount,
              std::function<void(const std::vector<std::string>&)> use);

  // Parses `args`; every problem is a UsageError. Options apply in the order they were
  // declared above, after all arguments have been read.
  void parse(const Args& args);

  // The first long name of "-o,--output": how messages name an option.
  static std::string longName(const std::string& names);

  // The value parsers, for options read elsewhere (the REPL's :commands, JSON job files).
  static uint64_t parseWhole(const std::string& flag, const std::string& v, uint64_t lo, uint64_t hi);
  static double parseNumber(const std::string& flag, const std::string& v);
  static void parsePoint(const std::string& flag, const std::string& v, double out[3]);

 private:
  std::string command_;
  std::unique_ptr<CLI::App> app_;
  std::vector<std::string> inputs_;
  std::string* input_ = nullptr;
  std::string inputWhat_;
};

}  // namespace fgsg::cli
