#include "runtime/evolve/lsystem2d.h"

#include <array>
#include <cmath>

namespace fgsg::rt::evolve {

namespace {

bool isLetter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

std::string listLetters(std::string_view letters) {
  std::string s;
  for (size_t i = 0; i < letters.size(); ++i) {
    if (i) s += ", ";
    s += letters[i];
  }
  return s;
}

std::string sizeText(int n) { return std::to_string(n) + "x" + std::to_string(n); }

[[noreturn]] void syntax(size_t column, const std::string& message) { throw LSystemSyntaxError(column, message); }

struct Part {
  size_t column = 0;  // 1-based column of its first character
  std::vector<Allele> alleles;
};

}  // namespace

LSystemSyntaxError::LSystemSyntaxError(size_t col, const std::string& message)
    : std::runtime_error("column " + std::to_string(col) + ": " + message), column(col) {}

AlleleGrid turnGrid(const AlleleGrid& g, int quarterTurns) {
  const int t = ((quarterTurns % 4) + 4) % 4;
  if (t == 0) return g;
  const int n = g.side;
  AlleleGrid out(n);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) {
      int rr = r, cc = c;
      for (int i = 0; i < t; ++i) {  // one counter-clockwise turn: (r, c) -> (n-1-c, r)
        const int nr = n - 1 - cc, nc = rr;
        rr = nr, cc = nc;
      }
      Allele a = g.at(r, c);
      a.turns = uint8_t((a.turns + t) % 4);
      out.at(rr, cc) = a;
    }
  return out;
}

size_t LSystem2D::length() const {
  size_t n = axiom.cells.size();
  for (const AlleleGrid& r : rules) n += r.cells.size();
  return n;
}

Allele& LSystem2D::allele(size_t position) {
  return const_cast<Allele&>(static_cast<const LSystem2D&>(*this).allele(position));
}

const Allele& LSystem2D::allele(size_t position) const {
  for (const AlleleGrid& r : rules) {
    if (position < r.cells.size()) return r.cells[position];
    position -= r.cells.size();
  }
  if (position < axiom.cells.size()) return axiom.cells[position];
  throw std::out_of_range("allele position " + std::to_string(position) + " is past the end of the L-system (" +
                          std::to_string(length()) + " alleles)");
}

LSystem2D parseLSystem(std::string_view text, std::string_view letters) {
  if (letters.empty()) syntax(1, "no symbols to parse against");
  std::array<int, 128> symbolOf;
  symbolOf.fill(-1);
  for (size_t i = 0; i < letters.size(); ++i) {
    if (!isLetter(letters[i])) syntax(1, std::string("symbol '") + letters[i] + "' is not a letter");
    symbolOf[size_t(letters[i])] = int(i);
  }

  size_t i = 0;
  auto col = [&](size_t at) { return at + 1; };
  auto skipSpace = [&] {
    while (i < text.size() && isSpace(text[i])) ++i;
  };
  skipSpace();
  const bool braced = i < text.size() && text[i] == '{';
  const size_t openAt = i;
  if (braced) ++i;

  std::vector<Part> parts;
  parts.push_back(Part{});
  bool closed = false;
  for (;;) {
    skipSpace();
    if (parts.back().alleles.empty()) parts.back().column = col(i);
    if (i >= text.size()) break;
    const char ch = text[i];
    if (ch == '}') {
      if (!braced) syntax(col(i), "'}' without an opening '{'");
      closed = true;
      ++i;
      break;
    }
    if (ch == '.') {
      if (parts.back().alleles.empty())
        syntax(col(i), "part " + std::to_string(parts.size()) + " is empty (two dots, or a dot first)");
      ++i;
      parts.push_back(Part{});
      continue;
    }
    if (isDigit(ch) || ch == '_') syntax(col(i), "an orientation must follow a symbol letter");
    if (!isLetter(ch)) syntax(col(i), std::string("unexpected character '") + ch + "' (expected a symbol letter, '.' or '}')");
    const int symbol = symbolOf[size_t(ch)];
    if (symbol < 0) syntax(col(i), std::string("unknown symbol '") + ch + "' (symbols: " + listLetters(letters) + ")");
    const size_t symbolAt = i++;
    if (i < text.size() && text[i] == '_') {
      ++i;
      if (i >= text.size() || !isDigit(text[i])) syntax(col(i), "expected an orientation after '_'");
    }
    int turns = 0;
    if (i < text.size() && isDigit(text[i])) {
      const size_t start = i;
      long degrees = 0;
      while (i < text.size() && isDigit(text[i]) && i - start < 6) degrees = degrees * 10 + (text[i++] - '0');
      if ((i < text.size() && isDigit(text[i])) || (degrees != 0 && degrees != 90 && degrees != 180 && degrees != 270))
        syntax(col(start), "orientation " + std::string(text.substr(start, i - start)) + " of '" + text[symbolAt] +
                               "' is not 0, 90, 180 or 270");
      turns = int(degrees / 90);
    }
    parts.back().alleles.push_back(Allele{uint8_t(symbol), uint8_t(turns)});
  }
  if (braced && !closed) syntax(col(openAt), "'{' is not closed by '}'");
  skipSpace();
  if (i < text.size()) syntax(col(i), "unexpected text after the L-system");
  if (parts.back().alleles.empty()) {
    if (parts.size() == 1) syntax(col(i), "empty L-system");
    syntax(col(i), "part " + std::to_string(parts.size()) + " is empty (a dot at the end)");
  }

  const size_t expected = letters.size() + 1;
  if (parts.size() != expected)
    syntax(parts.size() > expected ? parts[expected].column : col(i),
           "expected " + std::to_string(expected) + " parts (" + std::to_string(letters.size()) + " rule" +
               (letters.size() == 1 ? "" : "s") + ", for " + listLetters(letters) + ", then the axiom), got " +
               std::to_string(parts.size()));

  LSystem2D ls;
  for (size_t p = 0; p < parts.size(); ++p) {
    const size_t count = parts[p].alleles.size();
    const int side = int(std::lround(std::sqrt(double(count))));
    if (size_t(side) * size_t(side) != count)
      syntax(parts[p].column, "part " + std::to_string(p + 1) + " has " + std::to_string(count) +
                                  " alleles, not a square k x k array");
    AlleleGrid g(side);
    g.cells = parts[p].alleles;
    if (p + 1 < parts.size()) {
      if (!ls.rules.empty() && side != ls.ruleSide())
        syntax(parts[p].column, "rule " + std::to_string(p + 1) + " (" + letters[p] + ") is " + sizeText(side) +
                                    " but rule 1 is " + sizeText(ls.ruleSide()) + ": all rules have one size");
      ls.rules.push_back(std::move(g));
    } else {
      ls.axiom = std::move(g);
    }
  }
  return ls;
}

LSystem2D parseLSystem(std::string_view text) {
  size_t dots = 0;
  for (char c : text) dots += c == '.';
  if (dots == 0) syntax(1, "expected rules and an axiom separated by dots, e.g. {ABAA.ABBA.A}");
  if (dots > size_t(kMaxSymbols)) syntax(1, std::to_string(dots) + " rules; at most " + std::to_string(kMaxSymbols));
  std::string letters;
  for (size_t s = 0; s < dots; ++s) letters += s < 26 ? char('A' + s) : char('a' + (s - 26));
  return parseLSystem(text, letters);
}

std::string formatGrid(const AlleleGrid& g, std::string_view letters) {
  std::string s;
  for (const Allele& a : g.cells) {
    s += a.symbol < letters.size() ? letters[a.symbol] : '?';
    if (a.turns) s += std::to_string(90 * a.turns);
  }
  return s;
}

std::string formatLSystem(const LSystem2D& ls, std::string_view letters) {
  std::string s = "{";
  for (const AlleleGrid& r : ls.rules) s += formatGrid(r, letters) + ".";
  return s + formatGrid(ls.axiom, letters) + "}";
}

void checkLSystem(const LSystem2D& ls) {
  if (ls.rules.empty()) throw std::invalid_argument("2D L-system without rules");
  if (ls.rules.size() > size_t(kMaxSymbols)) throw std::invalid_argument("2D L-system with more than 52 rules");
  const int k = ls.ruleSide();
  if (k < 1) throw std::invalid_argument("2D L-system with an empty rule");
  auto checkGrid = [&](const AlleleGrid& g, const std::string& what) {
    if (g.side < 1 || g.cells.size() != size_t(g.side) * size_t(g.side))
      throw std::invalid_argument(what + " is not a square array");
    for (const Allele& a : g.cells) {
      if (a.symbol >= ls.rules.size())
        throw std::invalid_argument(what + " uses symbol " + std::to_string(a.symbol) + " which has no rule");
      if (a.turns > 3) throw std::invalid_argument(what + " has an orientation beyond 3 quarter turns");
    }
  };
  for (size_t s = 0; s < ls.rules.size(); ++s) {
    if (ls.rules[s].side != k)
      throw std::invalid_argument("rule " + std::to_string(s + 1) + " is " + sizeText(ls.rules[s].side) +
                                  " but rule 1 is " + sizeText(k));
    checkGrid(ls.rules[s], "rule " + std::to_string(s + 1));
  }
  checkGrid(ls.axiom, "the axiom");
}

int expandedSide(const LSystem2D& ls, int generation, int maxSide) {
  if (generation < 0) throw std::invalid_argument("negative L-system generation " + std::to_string(generation));
  long long side = ls.axiom.side;
  const int k = ls.ruleSide();
  for (int g = 0; g < generation && k > 1; ++g) {
    side *= k;
    if (side > maxSide)
      throw std::length_error("generation " + std::to_string(generation) + " of a " + sizeText(k) +
                              "-rule L-system is wider than " + std::to_string(maxSide) + " cells");
  }
  return int(side);
}

AlleleGrid expand(const LSystem2D& ls, int generation, size_t maxCells) {
  checkLSystem(ls);
  const int side = expandedSide(ls, generation);
  if (size_t(side) * size_t(side) > maxCells)
    throw std::length_error("generation " + std::to_string(generation) + " has " + std::to_string(side) + "x" +
                            std::to_string(side) + " cells, more than the limit of " + std::to_string(maxCells));
  const int k = ls.ruleSide();
  std::vector<AlleleGrid> turned(ls.rules.size() * 4);
  for (size_t s = 0; s < ls.rules.size(); ++s)
    for (int t = 0; t < 4; ++t) turned[s * 4 + size_t(t)] = turnGrid(ls.rules[s], t);

  AlleleGrid cur = ls.axiom;
  for (int g = 0; g < generation; ++g) {
    const int n = cur.side;
    AlleleGrid next(n * k);
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c) {
        const AlleleGrid& rule = turned[size_t(cur.at(r, c).index())];
        for (int i = 0; i < k; ++i) {
          const Allele* src = &rule.cells[size_t(i) * size_t(k)];
          Allele* dst = &next.at(r * k + i, c * k);
          for (int j = 0; j < k; ++j) dst[j] = src[j];
        }
      }
    cur = std::move(next);
  }
  return cur;
}

}  // namespace fgsg::rt::evolve
