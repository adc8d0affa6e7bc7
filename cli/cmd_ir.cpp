#include "backend/native/llvm_plugin.h"
#include "cli/commands.h"
#include "cli/compile_file.h"
#include "ir/printer.h"

#include <iostream>

namespace fgsg::cli {

int irCommand(const Args& args) {
  std::string file;
  bool llvmText = false;
  for (const std::string& a : args) {
    if (a == "--llvm") {
      llvmText = true;
    } else if (a.rfind("-", 0) == 0 || !file.empty()) {
      std::cerr << "usage: fgsg ir FILE [--llvm]\n";
      return 2;
    } else {
      file = a;
    }
  }
  if (file.empty()) {
    std::cerr << "usage: fgsg ir FILE [--llvm]\n";
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
