// fgsg fmt FILE... : rewrites grammars in their canonical layout (frontend/format_grammar.h).
// In place by default, each file replaced atomically; --check only says which files would
// change; --stdout (or the file `-`, read from stdin) prints the result instead.
#include "cli/commands.h"
#include "frontend/format_grammar.h"
#include "runtime/io/atomic_file.h"
#include "runtime/io/read_input.h"

#include <iostream>
#include <iterator>

namespace fgsg::cli {

namespace {

struct FmtOptions {
  bool check = false;
  bool toStdout = false;
  std::vector<std::string> files;
};

const char* const kFmtUsage = "fgsg fmt [--check] [--stdout] FILE... (or - for stdin)";

// Formats one file; returns 0 (done, or already formatted), 1 (errors, or --check finds
// a change). Nothing is written on an error.
int formatOne(const std::string& path, const FmtOptions& o) {
  const bool fromStdin = path == "-";
  const std::string shown = fromStdin ? "<stdin>" : path;
  std::string text, error;
  if (fromStdin) {
    text.assign(std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>());
    if (text.size() > rt::io::kMaxInputBytes) {
      std::cerr << "fgsg fmt: <stdin>: larger than " << (rt::io::kMaxInputBytes >> 20) << " MiB\n";
      return 1;
    }
  } else if (!rt::io::readInputFile(path, "a grammar file", text, error)) {
    std::cerr << "fgsg fmt: " << error << "\n";
    return 1;
  }
  const frontend::SourceFile file = frontend::SourceFile::make(shown, text);
  frontend::Diagnostics diags(&file);
  std::string formatted;
  if (!frontend::formatGrammar(file, formatted, diags)) {
    diags.print(std::cerr);
    std::cerr << "fgsg fmt: " << shown << " not formatted (" << diags.errorCount() << " error"
              << (diags.errorCount() == 1 ? "" : "s") << ")\n";
    return 1;
  }
  if (o.check) {
    if (formatted == text) return 0;
    std::cout << shown << "\n";  // would change
    return 1;
  }
  if (fromStdin || o.toStdout) {
    std::cout << formatted;
    return 0;
  }
  if (formatted == text) return 0;  // leaves the file (and its time) alone
  if (!rt::io::writeFileAtomically(path, formatted, error)) {
    std::cerr << "fgsg fmt: " << path << ": " << error << "\n";
    return 1;
  }
  return 0;
}

}  // namespace

int fmtCommand(const Args& args) {
  FmtOptions o;
  bool onlyFiles = false;  // after `--`
  for (const std::string& a : args) {
    if (!onlyFiles && a == "--") onlyFiles = true;
    else if (!onlyFiles && a == "--check") o.check = true;
    else if (!onlyFiles && a == "--stdout") o.toStdout = true;
    else if (!onlyFiles && a.size() > 1 && a[0] == '-') {
      std::cerr << "fgsg fmt: unknown option '" << a << "' (usage: " << kFmtUsage << ")\n";
      return 2;
    } else o.files.push_back(a);
  }
  if (o.files.empty()) {
    std::cerr << "fgsg fmt: no grammar file given (usage: " << kFmtUsage << ")\n";
    return 2;
  }
  int stdinCount = 0;
  for (const std::string& f : o.files) stdinCount += f == "-";
  if (stdinCount > 1) {
    std::cerr << "fgsg fmt: '-' (stdin) may be given once\n";
    return 2;
  }
  int status = 0;
  for (const std::string& f : o.files) status = std::max(status, formatOne(f, o));
  return status;
}

}  // namespace fgsg::cli
