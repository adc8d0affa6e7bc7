#include "frontend/incremental_lex.h"
#include "frontend/statement_reuse.h"

#include <algorithm>
#include <cstddef>

namespace fgsg::frontend {

using antlr4::Token;

namespace {

bool incrementalLexIsContinuationByte(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

// Characters (code points: the stream's indices) in bytes [from, to) of valid UTF-8.
size_t incrementalLexCharacters(const std::string& s, size_t from, size_t to) {
  size_t n = 0;
  for (size_t i = from; i < to; ++i) n += !incrementalLexIsContinuationByte(s[i]);
  return n;
}

size_t incrementalLexNewlines(const std::string& s, size_t from, size_t to) {
  return static_cast<size_t>(std::count(s.begin() + static_cast<std::ptrdiff_t>(from),
                                        s.begin() + static_cast<std::ptrdiff_t>(to), '\n'));
}

size_t incrementalLexShifted(size_t index, std::ptrdiff_t delta) {
  return static_cast<size_t>(static_cast<std::ptrdiff_t>(index) + delta);  // EOF's stop may be start - 1
}

}  // namespace

std::vector<std::unique_ptr<Token>> IncrementalLexCache::lex(fgsg_grammar::FgsgLexer& lexer,
                                                             LookaheadTrackingStream& input,
                                                             const std::string& text) {
  const auto source = std::make_pair(static_cast<antlr4::TokenSource*>(&lexer), static_cast<antlr4::CharStream*>(&input));
  const auto make = [&](const RawToken& t) {
    auto token = std::make_unique<antlr4::CommonToken>(source, t.type, t.channel, t.start, t.stop);
    token->setLine(t.line);
    token->setCharPositionInLine(t.column);
    token->setText(t.text);
    return token;
  };
  std::vector<std::unique_ptr<Token>> out;
  std::vector<RawToken> next;
  reused_ = lexed_ = 0;

  // The edit: the bytes before `prefix` and the last `suffix` bytes are the same in both
  // texts, cut at character boundaries.
  size_t kept = 0, newEditEnd = 0, oldEditEndLine = 0;
  std::ptrdiff_t delta = 0, lineDelta = 0;
  if (valid_) {
    const std::string& old = text_;
    const size_t common = std::min(old.size(), text.size());
    size_t prefix = static_cast<size_t>(std::mismatch(old.begin(), old.begin() + static_cast<std::ptrdiff_t>(common),
                                                      text.begin()).first - old.begin());
    while (prefix > 0 && ((prefix < old.size() && incrementalLexIsContinuationByte(old[prefix])) ||
                          (prefix < text.size() && incrementalLexIsContinuationByte(text[prefix]))))
      --prefix;
    size_t suffix = 0;
    while (suffix < common - prefix && old[old.size() - 1 - suffix] == text[text.size() - 1 - suffix]) ++suffix;
    while (suffix > 0 && incrementalLexIsContinuationByte(old[old.size() - suffix])) --suffix;
    const size_t editStart = incrementalLexCharacters(text, 0, prefix);
    const size_t oldEditEnd = editStart + incrementalLexCharacters(old, prefix, old.size() - suffix);
    newEditEnd = editStart + incrementalLexCharacters(text, prefix, text.size() - suffix);
    delta = static_cast<std::ptrdiff_t>(newEditEnd) - static_cast<std::ptrdiff_t>(oldEditEnd);
    oldEditEndLine = 1 + incrementalLexNewlines(old, 0, old.size() - suffix);
    lineDelta = static_cast<std::ptrdiff_t>(incrementalLexNewlines(text, prefix, text.size() - suffix)) -
                static_cast<std::ptrdiff_t>(incrementalLexNewlines(old, prefix, old.size() - suffix));
    // The tokens whose lexing read nothing from the edit stay (`lookedTo` only grows).
    kept = static_cast<size_t>(std::partition_point(tokens_.begin(), tokens_.end(),
                                                    [&](const RawToken& t) { return t.lookedTo < editStart; }) -
                               tokens_.begin());
  }
  next.reserve(tokens_.size() + 16);
  out.reserve(tokens_.size() + 16);
  size_t line = 1, column = 0, restart = 0, lookedTo = 0;
  for (size_t i = 0; i < kept; ++i) {
    out.push_back(make(tokens_[i]));
    next.push_back(std::move(tokens_[i]));
  }
  if (kept > 0) {  // lexing goes on where the last kept token ends
    const RawToken& last = next.back();
    restart = last.stop + 1, line = last.line, column = last.column, lookedTo = last.lookedTo;
    for (char c : last.text) {
      if (c == '\n') ++line, column = 0;
      else column += !incrementalLexIsContinuationByte(c);
    }
  }
  input.jumpTo(restart);
  lexer.setLine(line);
  lexer.setCharPositionInLine(column);

  size_t old = kept;  // the first old token not before the new one
  for (;;) {
    input.furthest = 0;
    std::unique_ptr<Token> token = lexer.nextToken();
    lookedTo = std::max(lookedTo, input.furthest);
    if (valid_ && token->getType() != Token::EOF && token->getStartIndex() >= newEditEnd) {
      const size_t oldStart = incrementalLexShifted(token->getStartIndex(), -delta);
      while (old < tokens_.size() && tokens_[old].start < oldStart) ++old;
      // Synchronised: from here the old tokens are lexed from the same text.
      if (old < tokens_.size() && tokens_[old].start == oldStart && tokens_[old].line > oldEditEndLine &&
          tokens_[old].type == token->getType()) {
        for (; old < tokens_.size(); ++old) {
          RawToken t = std::move(tokens_[old]);
          t.start = incrementalLexShifted(t.start, delta);
          t.stop = incrementalLexShifted(t.stop, delta);
          t.line = incrementalLexShifted(t.line, lineDelta);
          lookedTo = t.lookedTo = std::max(lookedTo, incrementalLexShifted(t.lookedTo, delta));
          out.push_back(make(t));
          next.push_back(std::move(t));
          ++reused_;
        }
        break;
      }
    }
    next.push_back(RawToken{token->getType(), token->getChannel(), token->getStartIndex(), token->getStopIndex(),
                            token->getLine(), token->getCharPositionInLine(), lookedTo, token->getText()});
    ++lexed_;
    const bool end = token->getType() == Token::EOF;
    out.push_back(std::move(token));
    if (end) break;
  }
  reused_ += kept;
  text_ = text;
  tokens_ = std::move(next);
  valid_ = true;
  return out;
}

IncrementalLexCache& StatementReuse::tokens() {
  if (!tokens_) tokens_ = std::make_shared<IncrementalLexCache>();
  return *tokens_;
}

}  // namespace fgsg::frontend
