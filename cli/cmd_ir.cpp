#include "backend/native/llvm_plugin.h"
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/compile_file.h"
#include "ir/printer.h"

#include <iostream>

namespace fgsg::cli {

int irCommand(const Args& args) {
  std::string file;
  bool llvmText = false;
  try {
    CommandLine cl("ir");
    cl.input(file, "grammar file");
    cl.flag("--llvm", llvmText);
    cl.parse(args);
    if (file.empty()) throw UsageError{"no grammar file given: fgsg ir FILE [--llvm]"};
  } catch (const UsageError& e) {
    std::cerr << "fgsg ir: " << e.message << "\n";
    return 2;
  }
  auto compiled = compileFile(file, false);
  if (!compiled) return 1;
  if (!llvmText) {
    std::cout << ir::printModule(compiled->module);
    return 0;
  }
  try {
    std::cout << backend::native::llvmPlugin().programLLVMText(compiled->module);
  } catch (const std::exception& e) {
    std::cerr << "fgsg ir: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace fgsg::cli
