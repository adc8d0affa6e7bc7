#include "cli/check_data_files.h"
#include "cli/commands.h"
#include "cli/compile_file.h"

#include <iostream>

namespace fgsg::cli {

int checkCommand(const Args& args) {
  if (args.size() != 1 || args[0].rfind("-", 0) == 0) {
    std::cerr << "usage: fgsg check FILE\n";
    return 2;
  }
  auto compiled = compileFile(args[0]);
  if (!compiled) return 1;
  frontend::Diagnostics dataDiags(&compiled->source);
  checkDataFiles(compiled->module, args[0], dataDiags);
  if (dataDiags.hasErrors()) {
    dataDiags.print(std::cerr);
    std::cerr << dataDiags.errorCount() << " error" << (dataDiags.errorCount() == 1 ? "" : "s") << " in "
              << args[0] << "\n";
    return 1;
  }
  std::cout << args[0] << ": ok, " << compiled->module.rules.size() << " rule"
            << (compiled->module.rules.size() == 1 ? "" : "s") << ", " << compiled->warnings
            << " warning" << (compiled->warnings == 1 ? "" : "s") << "\n";
  return 0;
}

}  // namespace fgsg::cli
