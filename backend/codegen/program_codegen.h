// A whole grammar to LLVM IR: one function per block (the axiom, each rule alternative,
// each split / roof / Lock body), one per guard and per non-constant probability, and
// the FgsgProgram constant that lists them (runtime/abi.h). Successors call the
// runtime's op entry points (runtime/abi.def) with their arguments computed inline,
// in the interpreter's order, so the engine sees exactly the same values.
// program_codegen_internal.h lists the files that emit each part.
#pragma once

#include "ir/ir.h"

#include <string>

namespace llvm {
class Module;
}

namespace fgsg::backend::codegen {

struct ProgramCodegenOptions {
  std::string tableSymbol = "fgsg_program";  // the FgsgProgram constant's (exported) name
  // Compiled libraries carry the grammar's text (the engine rebuilds its tables from it).
  bool embedSource = false;
  std::string source;
  std::string sourceName;
  std::string startRule;  // fgsg compile --start-rule (FgsgProgram::startRule); "": none
};

void emitProgram(llvm::Module& out, const ir::Module& m, const ProgramCodegenOptions& options);

// Where compiled code will run: the JIT targets this machine's CPU; a library the
// baseline of the architecture, so it runs on any machine of that kind.
enum class CpuTarget { Host, Generic };

// Optimized: the O2 pipeline and every optimisation of machine code (libraries, the
// JIT's cache). Baseline: the JIT's first tier, runnable soonest: a short pipeline
// (registers for stack slots, redundancy, constant branches) and fast instruction
// selection and register allocation.
enum class CodeQuality { Baseline, Optimized };

// Seconds spent in each step of compileProgramObject.
struct ObjectCompileTimes {
  double emit = 0.0;      // IR -> LLVM IR
  double optimize = 0.0;  // the O2 pipeline
  double machine = 0.0;   // instruction selection to the object file
};

// The grammar's LLVM IR as text, after the O2 pipeline (`fgsg ir --llvm`).
std::string programLLVMText(const ir::Module& m);

// The grammar compiled (O2) to a relocatable position-independent ELF object, as bytes.
// Throws std::runtime_error when LLVM cannot set up the target.
std::string compileProgramObject(const ir::Module& m, const ProgramCodegenOptions& options,
                                 CpuTarget cpu, CodeQuality quality = CodeQuality::Optimized,
                                 ObjectCompileTimes* times = nullptr);

}  // namespace fgsg::backend::codegen
