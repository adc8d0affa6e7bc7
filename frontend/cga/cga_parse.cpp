// Parsing a `.cga` file: the CGA lexer and parser (grammar/Cga.g4), their errors as E001 /
// E002 diagnostics, then the translator (cga_translator.h) builds the AST.
#include "frontend/cga/cga_parse.h"

#include "frontend/cga/cga_translator.h"
#include "frontend/two_stage_parse.h"

#include "CgaLexer.h"
#include "CgaParser.h"

#include <algorithm>
#include <cctype>

namespace fgsg::frontend {

namespace {

constexpr int kMaxCgaErrors = 50;

// ANTLR's recognition errors as E002, at most kMaxCgaErrors; its messages name tokens as the
// grammar spells them, which for CGA's small grammar reads well enough.
class CgaErrorListener : public antlr4::BaseErrorListener {
 public:
  explicit CgaErrorListener(Diagnostics& diags) : diags_(diags) {}
  void syntaxError(antlr4::Recognizer*, antlr4::Token* offending, size_t line, size_t col,
                   const std::string& msg, std::exception_ptr) override {
    if (++count_ > kMaxCgaErrors) return;
    SourceRange at{{int(line), int(col) + 1}, {int(line), int(col) + 1}};
    if (offending && offending->getType() != antlr4::Token::EOF) at = cga::rangeOf(offending);
    std::string m = msg;
    for (const char* from : {"mismatched input", "extraneous input", "no viable alternative at input"})
      if (m.rfind(from, 0) == 0) m = "unexpected" + m.substr(std::string(from).size());
    diags_.error("E002", at, m + " (CityEngine CGA)");
  }

 private:
  Diagnostics& diags_;
  int count_ = 0;
};

bool isValidUtf8(const std::string& s) {
  const auto* p = reinterpret_cast<const unsigned char*>(s.data());
  for (size_t i = 0, n = s.size(); i < n;) {
    const unsigned c = p[i];
    const size_t len = c < 0x80 ? 1 : (c & 0xE0) == 0xC0 ? 2 : (c & 0xF0) == 0xE0 ? 3 : (c & 0xF8) == 0xF0 ? 4 : 0;
    if (len == 0 || i + len > n) return false;
    for (size_t k = 1; k < len; ++k)
      if ((p[i + k] & 0xC0) != 0x80) return false;
    i += len;
  }
  return true;
}

}  // namespace

bool isCgaSource(const std::string& name, const std::string& text) {
  if (name.size() >= 4 && name.compare(name.size() - 4, 4, ".cga") == 0) return true;
  // `dialect cga;` as the first thing after blank lines and comments.
  size_t i = 0;
  while (i < text.size()) {
    if (std::isspace(static_cast<unsigned char>(text[i]))) {
      ++i;
    } else if (text.compare(i, 2, "//") == 0 || text[i] == '#') {
      i = text.find('\n', i);
      if (i == std::string::npos) return false;
    } else if (text.compare(i, 2, "/*") == 0) {
      i = text.find("*/", i + 2);
      if (i == std::string::npos) return false;
      i += 2;
    } else {
      break;
    }
  }
  if (text.compare(i, 7, "dialect") != 0) return false;
  i += 7;
  while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
  return text.compare(i, 3, "cga") == 0 && (i + 3 == text.size() || !std::isalnum(static_cast<unsigned char>(text[i + 3])));
}

int cgaLookingLine(const std::string& text) {
  int line = 1;
  size_t start = 0;
  while (start <= text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string l = text.substr(start, end - start);
    const size_t first = l.find_first_not_of(" \t");
    const bool comment = first != std::string::npos && l.compare(first, 2, "//") == 0;
    if (!comment && (l.find("-->") != std::string::npos || l.find("@StartRule") != std::string::npos ||
                     (first != std::string::npos && l.compare(first, 9, "version \"") == 0)))
      return line;
    if (end == text.size()) break;
    start = end + 1;
    ++line;
  }
  return 0;
}

bool isCityEngineOperationName(const std::string& name) { return cga::isCityEngineOperation(name); }
std::vector<std::string> cityEngineOperationNames() { return cga::cityEngineOperations(); }
std::vector<std::pair<std::string, std::string>> cityEngineFunctionSignatures() { return cga::cityEngineFunctions(); }
std::vector<std::string> cityEngineGeometryFunctionNames() { return cga::cityEngineGeometryFunctions(); }

bool parseCgaText(const std::string& name, const std::string& text, Program& out, Diagnostics& diags,
                  const std::string& startRule, bool styleFromImporter) {
  out.fileName = name;
  const int before = diags.errorCount();
  if (!isValidUtf8(text)) {
    diags.error("E001", SourceRange{{1, 1}, {1, 1}}, "the file is not valid UTF-8 text");
    return false;
  }
  antlr4::ANTLRInputStream input(text);
  fgsg_grammar::CgaLexer lexer(&input);
  lexer.removeErrorListeners();
  antlr4::CommonTokenStream tokens(&lexer);
  tokens.fill();
  int lexical = 0;
  for (antlr4::Token* t : tokens.getTokens()) {
    const size_t type = t->getType();
    if (type != fgsg_grammar::CgaLexer::UNKNOWN_CHAR && type != fgsg_grammar::CgaLexer::UNTERMINATED_STRING &&
        type != fgsg_grammar::CgaLexer::UNTERMINATED_COMMENT)
      continue;
    if (++lexical > 20) break;
    const std::string what = type == fgsg_grammar::CgaLexer::UNKNOWN_CHAR          ? "unexpected character '" + t->getText() + "'"
                             : type == fgsg_grammar::CgaLexer::UNTERMINATED_STRING ? std::string("unterminated string")
                                                                                   : std::string("unterminated comment");
    diags.error("E001", cga::rangeOf(t), what);
  }
  if (lexical > 0) return false;

  // Two stages (frontend/two_stage_parse.h): the second, which reports, only after a syntax error.
  fgsg_grammar::CgaParser firstStage(&tokens);
  makeFirstStage(firstStage);
  fgsg_grammar::CgaParser parser(&tokens);
  parser.removeErrorListeners();
  CgaErrorListener listener(diags);
  parser.addErrorListener(&listener);
  cga::P::CgaFileContext* tree = tryFirstStage([&] { return firstStage.cgaFile(); });
  if (!tree) {
    tokens.seek(0);
    tree = parser.cgaFile();
    if (diags.errorCount() != before) return false;
  }
  cga::Translator(out, diags, name, startRule, styleFromImporter).run(tree);
  return diags.errorCount() == before;
}

}  // namespace fgsg::frontend
