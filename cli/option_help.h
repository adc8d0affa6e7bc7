// What `fgsg CMD --help` says about each of CMD's options: one line (or a few) per option,
// each starting with the option, so that every option a command accepts is described
// (tests/cli/help_describes_options.sh checks it against what the commands accept).
#pragma once

#include <string>

namespace fgsg::cli {

// The "options:" block of `command` ("run", "synth", ...); "" for a command without options.
std::string optionHelp(const std::string& command);

}  // namespace fgsg::cli
