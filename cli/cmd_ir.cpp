#include "cli/commands.h"
#include "cli/compile_file.h"
#include "ir/printer.h"

#include <iostream>

namespace fgsg::cli {

int irCommand(const Args& args) {
  if (args.size() != 1 || args[0].rfind("-", 0) == 0) {
    std::cerr << "usage: fgsg ir FILE\n";
    return 2;
  }
  auto compiled = compileFile(args[0], false);
  if (!compiled) return 1;
  std::cout << ir::printModule(compiled->module);
  return 0;
}

}  // namespace fgsg::cli
