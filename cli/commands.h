// The subcommands of the fgsg CLI, one file each (cmd_<name>.cpp). Each takes the
// arguments after the subcommand name and returns the process exit code.
#pragma once

#include <string>
#include <vector>

namespace fgsg::cli {

using Args = std::vector<std::string>;

int runCommand(const Args& args);    // fgsg run FILE ...
int checkCommand(const Args& args);  // fgsg check FILE
int irCommand(const Args& args);     // fgsg ir FILE
int synthCommand(const Args& args);  // fgsg synth EXAMPLE --size X Y Z ...
// fgsg synth EXAMPLE.obj ...: continuous synthesis, when the example is a mesh file.
int continuousSynthCommand(const Args& args);
const char* continuousSynthUsage();
int replCommand(const Args& args);   // fgsg repl (interactive, or a script on stdin)
int compileCommand(const Args& args);  // fgsg compile FILE -o libNAME.so (C API library)
int atlasCommand(const Args& args);    // fgsg atlas MESH (on-mesh marching's atlas)
int evolveCommand(const Args& args);   // fgsg evolve TILES.json (L-system tile patterns)
int fieldCommand(const Args& args);    // fgsg field FILE (a grammar's field: streamlines, singularities)
int viewCommand(const Args& args);     // fgsg view FILE (a live viewer in the browser)
int lspCommand(const Args& args);      // fgsg lsp (a language server on stdin/stdout)
int fmtCommand(const Args& args);      // fgsg fmt FILE... (canonical layout, in place)
// fgsg builtin-reference (hidden): the markdown of docs/language.md's "Builtin reference",
// generated from frontend/builtin_docs.cpp's table.
int builtinReferenceCommand(const Args& args);
int batchCommand(const Args& args);    // fgsg batch JOBS.json (python -m fgsg.batch: jobs on Dask)

// The usage lines of the commands with their own (fgsg synth --help, fgsg evolve --help).
const char* synthUsage();
const char* evolveUsage();

}  // namespace fgsg::cli
