// fgsg: the command-line front door. Each subcommand lives in cmd_<name>.cpp.
#include "cli/commands.h"
#include "cli/option_help.h"
#include "runtime/out_of_resources.h"

#include <algorithm>
#include <cstring>
#include <exception>
#include <new>
#include <iostream>

namespace {

const char* kHelp = R"(fgsg - field-guided shape grammars: grow geometry from .fgsg grammars

usage:
  fgsg run FILE [-o out.glb|.obj|.ply] [--seed N] [--set name=value]...
                [--preview out.png] [--instances out.json] [--lines lines.json] [--max-shapes N]
                [--max-depth N] [--step N] [--max-seconds S] [--max-memory SIZE] [--collide-all]
                [--stats] [--quiet] [--surface mesh.off] [--surface-size S] [--repair-surface] [--start x,y,z]
                [--engine jit|interp] [--seed-points FILE|x,y,z;...] [--march-candidates N]
                [--lots lots.geojson] [--start-rule NAME] [--report reports.json]
                [--atlas-resolution N] [--march-units surface|texels] [--seed-density T --seed-count N]
                [--instancing auto|on|nodes|off] [--group-by symbol|rule|label|none] [--split-output DIR]
                [--quantize]
  fgsg check FILE [--start-rule NAME]
                           report errors and warnings; exit 1 on errors
  fgsg ir FILE [--llvm]    print the typed IR after constant folding (or the LLVM IR)
  fgsg synth EXAMPLE --size X Y Z [...]   example-based model synthesis
  fgsg repl [--engine=E]   build a grammar interactively (:help inside; a script on stdin)
  fgsg compile FILE [-o libNAME.so] [--header DIR] [--start-rule NAME] [--quiet]
                           compile to a shared library and its C header NAME.h
  fgsg atlas MESH [--preview atlas.png] [--resolution N] [--paint x,y,z,r]...
                 [--paint-slab x,y,z,nx,ny,nz,w]... [--mask m.png]
                           lay MESH out for on-mesh marching (cached); draw the atlas, or
                           paint a mask for a texture context with brushes
  fgsg evolve TILES.json [--k K] [--generation G] [--p4] [--seed N] [--json out.json]
                 [--preview out.png] [--lsystem '{...}'] [...]
                           evolve a 2D L-system tile pattern (Chan & Hui; docs/evolve.md)
  fgsg field FILE [-o field.glb|.obj|.ply] [--preview field.png] [--field NAME]
                 [--singularities s.json] [--seeds N] [--length L] [--step S] [--minor]
                 [--surface mesh.off]
                           show FILE's field: streamlines and singularities (listed)
  fgsg view FILE [--port N] [--host ADDRESS] [--seed N] [--set name=value]... [--surface mesh.off]
                 [--steps] [--step N]
                           a live viewer in the browser: re-derives when FILE is saved or
                           an attribute is changed in the page (fgsg view --help)
  fgsg batch JOBS.json [--scheduler tcp://host:port] [--workers N]
                           run many jobs (grammar, seed, attrs, output) on Dask, resumable,
                           with a manifest of every job's outcome (docs/scale.md)
  fgsg lsp                 a language server for editors: LSP on stdin and stdout
                           (diagnostics, completion, hover, definition; docs/editors.md)
  fgsg fmt FILE... [--check] [--stdout]
                           rewrite grammars in the canonical layout, in place (- : stdin to
                           stdout); --check lists the files that would change, exit 1
  fgsg --help | --version

fgsg CMD --help describes each of CMD's options (run: -o, --seed, --set, --preview ...).
compile writes lib + FILE's stem + .so when -o is not given, and NAME.h beside the
library (or in --header DIR); the library runs through the C API of libfgsg.so with
the same results as fgsg run (docs/cli.md).
Grammars import modules (import "std/cga/facade" as facade;): beside the grammar, in the
folders of FGSG_PATH (':'-separated), and "std/..." in the standard library (FGSG_STDLIB
overrides where it is); --set facade.floor_height=3.5 sets a module's attr.
Exit codes: 0 success, 1 errors in the grammar or while deriving, 2 bad usage.
Documentation: docs/language.md, docs/cli.md.
)";

const char* const kCommands[] = {"run",     "check", "ir",    "synth", "repl", "compile",
                                 "atlas",   "evolve", "field", "view",  "batch", "lsp", "fmt"};

// What `fgsg CMD --help` prints: the command's lines of the overall help (from "  fgsg
// CMD" to the next command; synth and evolve have their own usage), a line on each of its
// options (cli/option_help.cpp), and where to read more.
std::string commandHelp(const std::string& cmd) {
  std::string out;
  if (cmd == "synth") {
    out = fgsg::cli::synthUsage();
  } else if (cmd == "evolve") {
    out = fgsg::cli::evolveUsage();
  } else {
    const std::string help = kHelp;
    out = "usage:\n";
    const size_t at = help.find("\n  fgsg " + cmd + " ");
    if (at != std::string::npos) {
      size_t end = help.find("\n  fgsg ", at + 1);
      out += help.substr(at + 1, (end == std::string::npos ? help.size() : end) - at - 1) + "\n";
    }
  }
  out += fgsg::cli::optionHelp(cmd);
  if (cmd == "compile") {
    const std::string help = kHelp;
    const size_t a = help.find("compile writes lib"), b = help.find("Grammars import", a);
    if (a != std::string::npos && b != std::string::npos) out += "\n" + help.substr(a, b - a);
  }
  return out + "\nExit codes: 0 success, 1 errors in the grammar or while deriving, 2 bad usage.\n"
               "Documentation: docs/cli.md (fgsg " + cmd + ").\n";
}

}  // namespace

int main(int argc, char** argv) {
  fgsg::cli::Args args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    std::cout << kHelp;
    return args.empty() ? 2 : 0;
  }
  if (args[0] == "--version") {
    std::cout << "fgsg 0.1.0\n";
    return 0;
  }
  const std::string cmd = args[0];
  args.erase(args.begin());
  // `fgsg CMD --help` (or -h) anywhere in the arguments: the command's usage, exit 0.
  const bool known = std::find(std::begin(kCommands), std::end(kCommands), cmd) != std::end(kCommands);
  if (known && cmd != "view" && cmd != "batch" && std::find_if(args.begin(), args.end(), [](const std::string& a) {
                                  return a == "--help" || a == "-h";
                                }) != args.end()) {
    std::cout << commandHelp(cmd);
    return 0;
  }
  // The one boundary every command's exceptions stop at: a message and exit 1, never an
  // abort. Commands report what they expect themselves; this is for what they did not.
  try {
    if (cmd == "run") return fgsg::cli::runCommand(args);
    if (cmd == "check") return fgsg::cli::checkCommand(args);
    if (cmd == "ir") return fgsg::cli::irCommand(args);
    if (cmd == "synth") return fgsg::cli::synthCommand(args);
    if (cmd == "repl") return fgsg::cli::replCommand(args);
    if (cmd == "compile") return fgsg::cli::compileCommand(args);
    if (cmd == "atlas") return fgsg::cli::atlasCommand(args);
    if (cmd == "evolve") return fgsg::cli::evolveCommand(args);
    if (cmd == "field") return fgsg::cli::fieldCommand(args);
    if (cmd == "view") return fgsg::cli::viewCommand(args);
    if (cmd == "batch") return fgsg::cli::batchCommand(args);
    if (cmd == "lsp") return fgsg::cli::lspCommand(args);
    if (cmd == "fmt") return fgsg::cli::fmtCommand(args);
    // Hidden (not in --help): prints docs/language.md's generated "Builtin reference".
    if (cmd == "builtin-reference") return fgsg::cli::builtinReferenceCommand(args);
  } catch (const std::bad_alloc&) {
    std::cerr << "fgsg " << cmd << ": out of memory; nothing was written\n";
    return 1;
  } catch (const std::exception& e) {
    if (const std::string why = fgsg::rt::outOfResources(e); !why.empty()) {
      std::cerr << "fgsg " << cmd << ": out of memory (" << why << "); nothing was written\n";
      return 1;
    }
    std::cerr << "fgsg " << cmd << ": internal error: " << e.what() << " (please report it)\n";
    return 1;
  }
  std::cerr << "fgsg: unknown command '" << cmd << "' (run, check, ir, synth, repl, compile, atlas, evolve, field, view, batch, lsp, fmt; see fgsg --help)\n";
  return 2;
}
