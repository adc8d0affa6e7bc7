// fgsg repl: build a grammar interactively, evaluate expressions, derive and export.
// With a terminal on stdin it reads lines with libedit (history, `fgsg> ` and `...> `
// prompts); otherwise it reads a script line by line and prints only results and
// diagnostics, exiting 1 when any input failed.
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/derive_flags.h"
#include "cli/derive_stats.h"
#include "cli/options.h"
#include "cli/repl_session.h"
#include "ir/pipeline.h"
#include "ir/printer.h"
#include "runtime/io/atomic_file.h"
#include "runtime/io/write_mesh.h"
#include "runtime/out_of_resources.h"

#include <editline/readline.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <new>
#include <sstream>

namespace fgsg::cli {
namespace {

const char* kCommandList =
    ":derive [N]  :seed N  :step N|off  :set name=value  :lots [FILE]  :load FILE  :save FILE  :export FILE  "
    ":stats  :ir RULE  :rules  :reset  :help  :quit";

const char* kReplHelp = R"(Type declarations and rules to add them to the session grammar: a rule for a
symbol that already has rules replaces them, and `const`/`attr` redefine. Type an
expression to evaluate it with the session's constants and attributes. A line with
unbalanced brackets or ending in `~>`, `->`, `=`, `,`, an operator or `\` continues on the
next line (an empty line ends it).
  :derive [N]       derive from the axiom (N: --max-depth) and print the statistics
  :seed N           the random seed of later derivations (default 1)
  :step N           an L-system's later derivations stop after step N (0: the axiom),
                    like fgsg run --step; past its length, the length (a warning)
  :step off         back to the whole derivation (:step alone says which is in force)
  :set name=value   override an attribute, like fgsg run --set
  :lots [FILE]      derive once per lot of a GeoJSON or mesh file, like fgsg run --lots
                    (no FILE: back to one derivation)
  :load FILE        add the statements of a .fgsg file
  :save FILE        write the session grammar as a .fgsg file
  :export FILE      derive and write the mesh (.glb, .obj or .ply by extension)
  :stats            the statistics of the last derivation
  :ir RULE          the typed IR of RULE's rules
  :rules            list the session's rules
  :reset            start again with an empty session
  :help             this text
  :quit             leave (also Ctrl-D)
)";

// True while `text` needs another line: open brackets, or a trailing token that needs more.
bool incomplete(const std::string& text) {
  int depth = 0;
  bool inString = false, blockComment = false;
  char lastSignificant = 0, beforeLast = 0;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (blockComment) {
      if (c == '*' && i + 1 < text.size() && text[i + 1] == '/') blockComment = false, ++i;
      continue;
    }
    if (inString) {
      if (c == '\\') ++i;
      else if (c == '"' || c == '\n') inString = false;
      continue;
    }
    if (c == '/' && i + 1 < text.size() && text[i + 1] == '/') {
      while (i < text.size() && text[i] != '\n') ++i;
      continue;
    }
    if (c == '/' && i + 1 < text.size() && text[i + 1] == '*') {
      blockComment = true, ++i;
      continue;
    }
    if (c == '"') inString = true;
    if (c == '(' || c == '[' || c == '{') ++depth;
    if (c == ')' || c == ']' || c == '}') --depth;
    if (!std::isspace(static_cast<unsigned char>(c))) beforeLast = lastSignificant, lastSignificant = c;
  }
  if (depth > 0 || blockComment) return true;
  if (lastSignificant == '>' && (beforeLast == '~' || beforeLast == '-')) return true;
  return std::string("=,+-*/%^&|<>?.").find(lastSignificant) != std::string::npos &&
         lastSignificant != 0;
}

std::string trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  const size_t e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

void printStats(const rt::DeriveStats& s, size_t triangles) {
  printDeriveStats(s, triangles);
  std::fflush(stdout);
}

bool parseUnsigned(const std::string& s, uint64_t& out) {
  if (s.empty() || !std::all_of(s.begin(), s.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
    return false;
  try {
    out = std::stoull(s);
  } catch (...) {
    return false;
  }
  return true;
}

class Repl {
 public:
  explicit Repl(bool interactive) : interactive_(interactive) {}
  repl::Session& session() { return session_; }

  // Handles one complete input; false when it failed. Whatever it throws ends that input,
  // never the session: the grammar typed so far is kept.
  bool handle(const std::string& raw, bool& quit) {
    try {
      return handleInput(raw, quit);
    } catch (const std::bad_alloc&) {
      std::cerr << "error: out of memory; the session and its grammar are kept\n";
    } catch (const std::exception& e) {
      if (const std::string why = rt::outOfResources(e); !why.empty()) {
        std::cerr << "error: out of memory (" << why << "); the session and its grammar are kept\n";
        return false;
      }
      std::cerr << "error: internal error: " << e.what() << " (please report it; the session is kept)\n";
    }
    return false;
  }

 private:
  bool handleInput(const std::string& raw, bool& quit) {
    const std::string text = trim(raw);
    if (text.empty()) return true;
    ++inputs_;
    if (text[0] == ':') return command(text, quit);
    auto source = std::make_shared<frontend::SourceFile>(
        frontend::SourceFile::make("<repl:" + std::to_string(inputs_) + ">", raw));
    if (repl::Session::looksLikeStatements(raw)) return session_.addStatements(source, std::cerr);
    std::string value;
    if (!session_.evaluate(source, value, std::cerr)) return false;
    std::cout << "= " << value << std::endl;
    return true;
  }

  bool fail(const std::string& message) {
    std::cerr << "error: " << message << "\n";
    return false;
  }

  bool command(const std::string& text, bool& quit) {
    std::istringstream in(text);
    std::string name, arg;
    in >> name;
    std::getline(in, arg);
    arg = trim(arg);
    if (name == ":quit" || name == ":q" || name == ":exit") {
      quit = true;
      return true;
    }
    if (name == ":help") {
      std::cout << kReplHelp << std::flush;
      return true;
    }
    if (name == ":derive") {
      uint64_t depth = 0;
      if (!arg.empty() && (!parseUnsigned(arg, depth) || depth == 0 || depth > 1'000'000))
        return fail(":derive takes an optional maximum depth (a whole number from 1 to 1000000), got '" + arg + "'");
      rt::DeriveResult result;
      size_t triangles = 0;
      if (!session_.derive(static_cast<uint32_t>(depth), result, triangles, std::cerr)) return false;
      last_ = result.stats;
      lastTriangles_ = triangles;
      haveStats_ = true;
      printStats(result.stats, triangles);
      return true;
    }
    if (name == ":stats") {
      if (!haveStats_) return fail("no derivation yet (use :derive)");
      printStats(last_, lastTriangles_);
      return true;
    }
    if (name == ":seed") {
      uint64_t seed = 0;
      if (!parseUnsigned(arg, seed)) return fail(":seed takes a whole number from 0 to 18446744073709551615, got '" + arg + "'");
      session_.setSeed(seed);
      return true;
    }
    if (name == ":step") {
      if (arg.empty()) {
        const int32_t step = session_.step();
        std::cout << (step < 0 ? std::string("step off: the whole derivation") : "step " + std::to_string(step))
                  << "\n";
        return true;
      }
      if (arg == "off") {
        session_.setStep(-1);
        return true;
      }
      uint64_t step = 0;
      if (!parseUnsigned(arg, step) || step > 2147483647)
        return fail(":step takes a whole number from 0 to 2147483647 or off, got '" + arg + "'");
      session_.setStep(static_cast<int32_t>(step));
      return true;
    }
    if (name == ":set") {
      const size_t eq = arg.find('=');
      if (eq == std::string::npos || eq == 0) return fail(":set expects name=value, got '" + arg + "'");
      std::string error;
      if (!session_.setAttribute(trim(arg.substr(0, eq)), trim(arg.substr(eq + 1)), error))
        return fail(error);
      return true;
    }
    if (name == ":lots") {
      std::string error;
      if (!session_.setLots(arg, error)) return fail(error);
      std::cout << (arg.empty() ? std::string("no lots: one derivation")
                                : std::to_string(session_.lotCount()) + " lots from " + arg)
                << "\n";
      return true;
    }
    if (name == ":load") {
      if (arg.empty()) return fail(":load needs a file name");
      auto source = std::make_shared<frontend::SourceFile>();
      std::string error;
      if (!ir::readSourceFile(arg, *source, error)) return fail(error);
      if (!session_.addStatements(source, std::cerr)) return false;
      if (interactive_) std::cout << "loaded " << arg << "\n";
      return true;
    }
    if (name == ":save") {
      if (arg.empty()) return fail(":save needs a file name");
      std::string error;
      if (!rt::io::writeFileAtomically(arg, session_.grammarText(), error)) return fail(error);
      if (interactive_) std::cout << "saved " << arg << "\n";
      return true;
    }
    if (name == ":export") {
      if (arg.empty()) return fail(":export needs a file name (.glb, .obj or .ply)");
      const std::string ext = lowerExtension(arg);
      const auto& known = rt::io::supportedMeshExtensions();
      if (std::find(known.begin(), known.end(), ext) == known.end())
        return fail(":export " + arg + ": unknown output format (use .glb, .obj or .ply)");
      rt::DeriveResult result;
      size_t triangles = 0;
      if (!session_.derive(0, result, triangles, std::cerr, arg)) return false;
      last_ = result.stats;
      lastTriangles_ = triangles;
      haveStats_ = true;
      std::cout << "wrote " << arg << " (" << result.instances.instances.size() << " instances, "
                << triangles << " triangles)" << std::endl;
      return true;
    }
    if (name == ":ir") {
      const ir::Module* m = session_.module();
      const int sym = m && !arg.empty() ? m->findSymbol(arg) : -1;
      if (sym < 0 || m->symbols[sym].rules.empty())
        return fail(":ir: no rules for '" + arg + "' in the session");
      for (uint32_t r : m->symbols[sym].rules) std::cout << ir::printRule(*m, m->rules[r]);
      std::cout << std::flush;
      return true;
    }
    if (name == ":rules") {
      for (const auto& s : session_.statements())
        if (s.key.rfind("rule:", 0) == 0)
          std::cout << (s.priority ? "priority " + std::to_string(s.priority) + ": " : "") << s.text
                    << ";\n";
      std::cout << std::flush;
      return true;
    }
    if (name == ":reset") {
      session_.reset();
      haveStats_ = false;
      return true;
    }
    return fail("unknown command '" + name + "' (commands: " + kCommandList + ")");
  }

  bool interactive_;
  repl::Session session_;
  int inputs_ = 0;
  rt::DeriveStats last_;
  size_t lastTriangles_ = 0;
  bool haveStats_ = false;
};

}  // namespace

int replCommand(const Args& args) {
  backend::Engine engine = backend::Engine::Jit;
  try {
    CommandLine cl("repl");
    engineFlag(cl, engine);
    cl.parse(args);
  } catch (const UsageError& e) {
    std::cerr << "fgsg repl: " << e.message << "\n";
    return 2;
  }
  const bool interactive = isatty(STDIN_FILENO);
  Repl repl(interactive);
  repl.session().setEngine(engine);
  bool anyFailed = false;
  bool quit = false;
  std::string pending;
  bool more = false;  // pending holds an incomplete input

  if (interactive) {
    std::cout << "fgsg repl - :help for commands, :quit to leave\n";
    using_history();
  }
  while (!quit) {
    std::string line;
    bool eof = false;
    if (interactive) {
      char* raw = readline(more ? "...> " : "fgsg> ");
      if (!raw) {
        eof = true;
      } else {
        line = raw;
        std::free(raw);
      }
    } else {
      eof = !std::getline(std::cin, line);
    }
    if (eof) {
      if (!pending.empty()) {
        std::cerr.flush();
        if (!repl.handle(pending, quit)) anyFailed = true;
      }
      if (interactive) std::cout << "\n";
      break;
    }
    if (!line.empty() && line.back() == '\r') line.pop_back();
    // An empty line ends an incomplete input; a trailing '\' asks for more.
    bool forceMore = false;
    if (!line.empty() && line.back() == '\\') {
      line.back() = ' ';
      forceMore = true;
    }
    const bool blank = trim(line).empty();
    if (!pending.empty()) pending += "\n";
    pending += line;
    if (!forceMore && !blank && trim(pending)[0] != ':' && incomplete(pending)) {
      more = true;
      continue;
    }
    if (forceMore) {
      more = true;
      continue;
    }
    more = false;
    const std::string input = pending;
    pending.clear();
    if (trim(input).empty()) continue;
    if (interactive) add_history(input.c_str());
    if (!repl.handle(input, quit)) anyFailed = true;
    std::cout.flush();
    std::cerr.flush();
  }
  return interactive ? 0 : (anyFailed ? 1 : 0);
}

}  // namespace fgsg::cli
