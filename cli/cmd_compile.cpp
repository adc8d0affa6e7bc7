// fgsg compile: a grammar compiled ahead of time into a shared library libNAME.so
// (exporting `fgsg_program_NAME`) and its C header NAME.h, to run through the C API of
// libfgsg.so (backend/aot/fgsg_api.h) with fgsg run's results.
#include "backend/aot/library_header.h"
#include "backend/aot/link_library.h"
#include "backend/codegen/program_codegen.h"
#include "backend/native/llvm_plugin.h"
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/compile_file.h"
#include "cli/derive_flags.h"
#include "cli/options.h"
#include "runtime/io/output_transaction.h"

#include <exception>
#include <filesystem>
#include <iostream>
#include <stdexcept>

namespace fgsg::cli {
namespace {

struct CompileOptions {
  std::string file;
  std::string output;
  std::string headerDir;  // empty: the library's folder
  bool quiet = false;
  std::string name;       // NAME of libNAME.so
  std::string startRule;  // --start-rule: the rule (and .cga style) the library derives with
};

CompileOptions parseCompileOptions(const Args& args) {
  CompileOptions o;
  CommandLine cl("compile");
  cl.input(o.file, "grammar file");
  cl.text("-o,--output", o.output);
  cl.option("--header", [&](const std::string& v) {
    if (v.empty()) throw UsageError{"--header needs a folder name"};
    o.headerDir = v;
  });
  cl.flag("-q,--quiet", o.quiet);
  startRuleFlag(cl, o.startRule);
  cl.parse(args);
  if (o.file.empty()) throw UsageError{"no grammar file given: fgsg compile FILE -o libNAME.so"};
  if (o.output.empty()) o.output = "lib" + std::filesystem::path(o.file).stem().string() + ".so";
  try {
    o.name = backend::aot::librarySymbolName(o.output);
  } catch (const std::invalid_argument& e) {
    throw UsageError{"-o " + std::string(e.what())};
  }
  return o;
}

}  // namespace

int compileCommand(const Args& args) {
  CompileOptions opt;
  try {
    opt = parseCompileOptions(args);
  } catch (const UsageError& e) {
    std::cerr << "fgsg compile: " << e.message << "\n";
    return 2;
  }
  // Found first: without libfgsg.so there is nothing to link against.
  std::string error;
  const std::string libDir = backend::aot::findRuntimeLibraryDir(error);
  if (libDir.empty()) {
    std::cerr << "fgsg compile: " << error << "\n";
    return 1;
  }

  auto compiled = compileFile(opt.file, !opt.quiet, opt.startRule);
  if (!compiled) return 1;

  backend::codegen::ProgramCodegenOptions codegen;
  codegen.tableSymbol = "fgsg_program_" + opt.name;
  codegen.embedSource = true;
  codegen.source = compiled->source.text;
  codegen.sourceName = opt.file;  // as fgsg run names it: diagnostics, the asset folders
  codegen.startRule = opt.startRule;  // the loader compiles the text again in this rule and style
  std::string object;
  try {
    object = backend::native::llvmPlugin().compileProgramObject(compiled->module, codegen,
                                                                backend::codegen::CpuTarget::Generic);
  } catch (const std::exception& e) {
    std::cerr << "fgsg compile: " << opt.file << ": " << e.what() << "\n";
    return 1;
  }

  // The header is staged before linking and committed after it: a header that cannot be
  // written leaves the old library in place, a failed link leaves the old header.
  const std::filesystem::path headerDir =
      !opt.headerDir.empty() ? std::filesystem::path(opt.headerDir)
                             : std::filesystem::path(opt.output).parent_path();
  const std::string header = (headerDir / (opt.name + ".h")).string();
  rt::io::OutputTransaction outputs;
  if (!outputs.stage(header, backend::aot::libraryHeader(opt.name), error)) {
    std::cerr << "fgsg compile: " << error << "\n";
    return 1;
  }
  if (!backend::aot::linkSharedLibrary(object, opt.output, libDir, error) || !outputs.commit(error)) {
    std::cerr << "fgsg compile: " << error << "\n";
    return 1;
  }
  if (!opt.quiet) std::cerr << "wrote " << opt.output << " and " << header << "\n";
  return 0;
}

}  // namespace fgsg::cli
