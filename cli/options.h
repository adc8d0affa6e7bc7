// What every command's option handling shares: the usage error (exit 2) and how file
// names are read. Options themselves are parsed by CommandLine (cli/command_line.h).
#pragma once

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

}  // namespace fgsg::cli
