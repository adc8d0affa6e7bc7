// Text from an input file quoted in a message. A word or line may be of any length (a
// 50 MB line of digits in a field file): it is cut to kMaxQuotedChars, with "..." and its
// size in bytes, so a message never carries a whole file.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace fgsg::rt::io {

constexpr size_t kMaxQuotedChars = 200;

namespace detail {
// Where to cut `text` (at most kMaxQuotedChars bytes), before a UTF-8 continuation byte
// so the message stays valid text.
inline size_t quoteCut(std::string_view text) {
  size_t cut = kMaxQuotedChars;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
  return cut;
}
}  // namespace detail

// 'text' when it is short; else 'its first kMaxQuotedChars bytes...' (N bytes).
inline std::string quoteText(std::string_view text) {
  if (text.size() <= kMaxQuotedChars) return "'" + std::string(text) + "'";
  return "'" + std::string(text.substr(0, detail::quoteCut(text))) + "...' (" + std::to_string(text.size()) +
         " bytes)";
}

// The same without the quotes: text, or its first bytes... (N bytes).
inline std::string clipText(std::string_view text) {
  if (text.size() <= kMaxQuotedChars) return std::string(text);
  return std::string(text.substr(0, detail::quoteCut(text))) + "... (" + std::to_string(text.size()) + " bytes)";
}

}  // namespace fgsg::rt::io
