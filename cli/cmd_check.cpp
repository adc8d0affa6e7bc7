#include "cli/check_data_files.h"
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/compile_file.h"
#include "cli/derive_flags.h"

#include <iostream>

namespace fgsg::cli {

int checkCommand(const Args& args) {
  std::string file;
  std::string startRule;
  try {
    CommandLine cl("check");
    cl.input(file, "grammar file");
    startRuleFlag(cl, startRule);
    cl.parse(args);
    if (file.empty()) throw UsageError{"no grammar file given: fgsg check FILE"};
  } catch (const UsageError& e) {
    std::cerr << "fgsg check: " << e.message << "\n";
    return 2;
  }
  auto compiled = compileFile(file, true, startRule);
  if (!compiled) return 1;
  frontend::Diagnostics dataDiags(&compiled->source);
  checkDataFiles(compiled->module, file, dataDiags);
  if (dataDiags.hasErrors()) {
    dataDiags.print(std::cerr);
    std::cerr << dataDiags.errorCount() << " error" << (dataDiags.errorCount() == 1 ? "" : "s") << " in "
              << file << "\n";
    return 1;
  }
  std::cout << file << ": ok, " << compiled->module.rules.size() << " rule"
            << (compiled->module.rules.size() == 1 ? "" : "s") << ", " << compiled->warnings
            << " warning" << (compiled->warnings == 1 ? "" : "s") << "\n";
  return 0;
}

}  // namespace fgsg::cli
