#include "frontend/query_modules.h"

#include "FgsgLexer.h"

namespace fgsg::frontend {

using antlr4::Token;
using fgsg_grammar::FgsgLexer;

bool isQueryModuleName(const std::string& name, bool letterOnly) {
  if (!letterOnly && (name.size() != 2 || name[0] != '?')) return false;
  const std::string letter = letterOnly ? name : name.substr(1);
  return letter == "P" || letter == "H" || letter == "U" || letter == "L" || letter == "E";
}

void joinQueryModules(std::vector<std::unique_ptr<Token>>& tokens) {
  const auto adjacent = [](const Token* a, const Token* b) { return a->getStopIndex() + 1 == b->getStartIndex(); };
  std::vector<std::unique_ptr<Token>> out;
  out.reserve(tokens.size());
  for (size_t i = 0; i < tokens.size(); ++i) {
    Token* t = tokens[i].get();
    if (t->getType() == FgsgLexer::QUESTION && i + 2 < tokens.size() && tokens[i + 1]->getType() == FgsgLexer::ID &&
        isQueryModuleName(tokens[i + 1]->getText(), true) && tokens[i + 2]->getType() == FgsgLexer::LPAREN &&
        adjacent(t, tokens[i + 1].get()) && adjacent(tokens[i + 1].get(), tokens[i + 2].get())) {
      auto* joined = static_cast<antlr4::CommonToken*>(t);
      joined->setType(FgsgLexer::ID);
      joined->setText("?" + tokens[i + 1]->getText());
      joined->setStopIndex(tokens[i + 1]->getStopIndex());
      out.push_back(std::move(tokens[i]));
      ++i;
      continue;
    }
    out.push_back(std::move(tokens[i]));
  }
  tokens = std::move(out);
}

}  // namespace fgsg::frontend
