// Incremental lexing (frontend/incremental_lex.h): after each edit of a sequence, the tokens
// lexed with the previous text's cache are the tokens of a fresh lex of the new text - type,
// text, line, column and offsets - with the same diagnostics, and only the edited region
// was lexed again. Each edit of the original text is undone before the next.
#include <catch2/catch.hpp>

#include "frontend/incremental_lex.h"
#include "frontend/lex.h"

#include <sstream>
#include <string>
#include <vector>

using namespace fgsg::frontend;

namespace {

std::string incrementalLexDump(const LexedSource& lexed, const Diagnostics& diags) {
  std::ostringstream out;
  for (const auto& t : lexed.tokens)
    out << t->getType() << ' ' << t->getLine() << ':' << t->getCharPositionInLine() << ' ' << t->getStartIndex() << '-'
        << t->getStopIndex() << " [" << t->getText() << "]\n";
  for (const auto& [line, section] : lexed.sectionStarts) out << "section " << line << ' ' << int(section) << '\n';
  diags.print(out);
  return out.str();
}

std::string incrementalLexLines(int from, int to) {
  std::string s;
  for (int i = from; i < to; ++i) s += "R" + std::to_string(i) + " ~> T(0, 0, w * " + std::to_string(i) + ") R" + std::to_string(i + 1) + ";\n";
  return s;
}

}  // namespace

TEST_CASE("incremental lexing gives the tokens of a fresh lex, edit after edit", "[parse][reuse][lex]") {
  const std::string head = "attr w = 1;\n/* a block\n   comment */\nattr s = \"a string\";\n";
  const std::string body = incrementalLexLines(0, 12);
  const std::string tail = "// last\nR12 ~> I(\"cube\");\n";
  const std::string original = head + body + tail;
  struct Edit {
    std::string what;
    std::string text;
    size_t maxLexed;  // at most this many tokens lexed again (a fresh lex: about 200)
  };
  const std::vector<Edit> edits = {
      {"a number changed in the middle", head + incrementalLexLines(0, 6) +
                                             "R6 ~> T(0, 0, w * 60) R7;\n" + incrementalLexLines(7, 12) + tail, 20},
      {"Enter in the middle of a line (lines after it move)", head + incrementalLexLines(0, 6) +
                                             "R6 ~> T(0, 0,\n w * 6) R7;\n" + incrementalLexLines(7, 12) + tail, 20},
      {"Enter at the start of a line", head + incrementalLexLines(0, 6) + "\n" + incrementalLexLines(6, 12) + tail, 20},
      {"Enter at the end of a line", head + incrementalLexLines(0, 6) + "\n" + incrementalLexLines(6, 12) + tail, 20},
      {"Enter splitting a name", head + incrementalLexLines(0, 6) + "R\n6 ~> T(0, 0, w * 6) R7;\n" +
                                     incrementalLexLines(7, 12) + tail, 20},
      {"two names merged", head + incrementalLexLines(0, 6) + "R6 ~> T(0, 0, w * 6)R7;\n" + incrementalLexLines(7, 12) + tail,
       20},
      {"two names merged into one", head + incrementalLexLines(0, 6) + "R6 ~> T(0, 0, w * 6) R7R8;\n" +
                                        incrementalLexLines(7, 12) + tail, 20},
      {"an edit inside the block comment", "attr w = 1;\n/* a blo\nck\n   comment */\nattr s = \"a string\";\n" + body + tail,
       12},
      {"the block comment opened further up", "attr w = 1; /*\n/* a block\n   comment */\nattr s = \"a string\";\n" + body +
                                                  tail, 12},
      {"the block comment left unterminated", "attr w = 1;\n/* a block\n   comment *\nattr s = \"a string\";\n" + body + tail,
       1000},
      {"an edit inside the string", "attr w = 1;\n/* a block\n   comment */\nattr s = \"a s\ntring\";\n" + body + tail, 20},
      {"the string left unterminated", "attr w = 1;\n/* a block\n   comment */\nattr s = \"a string;\n" + body + tail, 20},
      {"a character of two bytes", "attr w = 1;\n/* a bl\xC3\xA9ock\n   comment */\nattr s = \"a \xC3\xA9string\";\n" + body +
                                       tail, 30},
      {"a line deleted", head + incrementalLexLines(0, 3) + incrementalLexLines(4, 12) + tail, 30},
      {"the same text", original, 2},
      {"the first character", "Attr w = 1;\n/* a block\n   comment */\nattr s = \"a string\";\n" + body + tail, 20},
      {"text appended", original + "R13 ~> R14;", 20},
      {"a lexical error", head + incrementalLexLines(0, 6) + "R6 ~> T(0, 0, w # 6) R7;\n" + incrementalLexLines(7, 12) + tail,
       20},
      {"an lpfg section header", head + "decomposition:\n" + body + tail, 20},
      {"everything replaced", "A ~> B;\n", 1000},
  };
  IncrementalLexCache cache;
  {
    SourceFile file = SourceFile::make("test.fgsg", original);
    Diagnostics diags(&file);
    lexText("test.fgsg", original, diags, {}, &cache);
  }
  // Each edit is made to the original text, then undone (an edit of the same size back).
  std::vector<Edit> steps;
  for (const Edit& edit : edits) {
    steps.push_back(edit);
    steps.push_back(Edit{"undone: " + edit.what, original, edit.maxLexed});
  }
  for (const Edit& edit : steps) {
    INFO(edit.what << ":\n" << edit.text);
    SourceFile file = SourceFile::make("test.fgsg", edit.text);
    Diagnostics freshDiags(&file), cachedDiags(&file);
    const LexedSource fresh = lexText("test.fgsg", edit.text, freshDiags);
    const LexedSource cached = lexText("test.fgsg", edit.text, cachedDiags, {}, &cache);
    CHECK(incrementalLexDump(cached, cachedDiags) == incrementalLexDump(fresh, freshDiags));
    CHECK(cache.lexedCount() <= edit.maxLexed);
    IncrementalLexCache empty;  // lexes everything
    Diagnostics ignored(&file);
    lexText("test.fgsg", edit.text, ignored, {}, &empty);
    CHECK(empty.reusedCount() == 0);
    CHECK(cache.lexedCount() + cache.reusedCount() == empty.lexedCount());  // each raw token one way or the other
  }
}
