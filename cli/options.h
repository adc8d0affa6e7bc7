// Small helpers for reading command-line options with clear errors: every bad flag or
// value ends in a message naming it and exit code 2 (usage error).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace fgsg::cli {

struct UsageError {
  std::string message;
};

// The extension of a file name, lower case, with its dot (".png"; "" when none): how
// every command tells the format the user asked for.
std::string lowerExtension(const std::string& path);

// Where a grammar's assets and data files are looked up: its folder, then its assets/.
std::vector<std::string> grammarDataDirs(const std::string& grammarFile);

// Walks the arguments after a subcommand name.
class OptionReader {
 public:
  explicit OptionReader(const std::vector<std::string>& args) : args_(args) {}

  bool done() const { return pos_ >= args_.size(); }
  const std::string& peek() const { return args_[pos_]; }
  std::string next() { return args_[pos_++]; }

  // The value of the option just read (`--seed 4` or `--seed=4`).
  std::string value(const std::string& flag);
  // A whole number from lo to hi; anything else (a sign, a fraction, too large) is a usage
  // error naming the flag and the range, never a wrapped or truncated value.
  uint64_t unsignedValue(const std::string& flag, uint64_t lo = 0, uint64_t hi = UINT64_MAX);
  double numberValue(const std::string& flag);
  // `--start 1,2.5,-3`: three finite numbers separated by commas (spaces allowed).
  void pointValue(const std::string& flag, double out[3]);

  // Splits `--flag=value` into flag and pending value.
  std::string flag();

  // When the next argument is not a flag, takes it as the grammar file and returns true;
  // a second file is a usage error.
  bool grammarFile(std::string& file);

 private:
  const std::vector<std::string>& args_;
  size_t pos_ = 0;
  std::string pending_;
  bool hasPending_ = false;
};

}  // namespace fgsg::cli
