#include "cli/view_field_edit.h"

#include "frontend/ast.h"
#include "frontend/diagnostics.h"
#include "frontend/parse.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <vector>

namespace fgsg::cli {

namespace {

using frontend::FieldDesignItem;
using frontend::FieldDesignWord;
using frontend::SourceLoc;

// Byte offsets of the text's places, which the parser gives as line and column in
// characters (a UTF-8 sequence is one; a byte of none is one too, as the lexer counts).
class FieldEditOffsets {
 public:
  explicit FieldEditOffsets(const std::string& text) : text_(text) {
    lineStarts_.push_back(0);
    for (size_t i = 0; i < text.size(); ++i)
      if (text[i] == '\n') lineStarts_.push_back(i + 1);
  }
  // The first byte of the character at `at`.
  size_t begin(const SourceLoc& at) const {
    size_t i = lineStarts_.at(static_cast<size_t>(std::max(at.line, 1) - 1));
    for (int c = 1; c < at.col && i < text_.size(); ++c) i += charBytes(i);
    return i;
  }
  // One past the last byte of the character at `at` (a range's inclusive end).
  size_t end(const SourceLoc& at) const {
    const size_t i = begin(at);
    return std::min(text_.size(), i + charBytes(i));
  }

 private:
  size_t charBytes(size_t i) const {
    const auto lead = static_cast<unsigned char>(text_[i]);
    const size_t n = lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC0 ? 2 : 1;
    for (size_t k = 1; k < n; ++k)
      if (i + k >= text_.size() || (static_cast<unsigned char>(text_[i + k]) & 0xC0) != 0x80) return 1;
    return n;
  }
  const std::string& text_;
  std::vector<size_t> lineStarts_;
};

// A number in plain decimals, rounded to `step` (a power of ten): `-1.5`, `2`, `0.0001`.
std::string fieldEditNumber(double v, double scale) {
  v = std::round(v * scale) / scale;
  if (v == 0) v = 0;  // no "-0"
  char text[64];
  const auto end = std::to_chars(text, text + sizeof text, v, std::chars_format::fixed).ptr;
  return std::string(text, end);
}

std::string fieldEditPoint(const double (&p)[3], double scale) {
  return "(" + fieldEditNumber(p[0], scale) + ", " + fieldEditNumber(p[1], scale) + ", " +
         fieldEditNumber(p[2], scale) + ")";
}

bool isFieldDesignKeyword(const std::string& word) {
  static const char* const kWords[] = {"at", "vertex", "decay", "direction", "angle", "strength", "iterations"};
  return std::any_of(std::begin(kWords), std::end(kWords), [&](const char* k) { return word == k; });
}

// The words of `item` that say `keyword` and its value: the word itself, or with the next
// when the value is written apart (`at vertex 120`, `strength s` with s a const). Empty:
// not written.
struct FieldEditSpan {
  size_t begin = 0, end = 0;
  bool found = false;
};
FieldEditSpan keywordSpan(const FieldDesignItem& item, const std::string& keyword, const FieldEditOffsets& at) {
  FieldEditSpan span;
  for (size_t k = 0; k < item.words.size(); ++k) {
    const FieldDesignWord& w = item.words[k];
    if (w.keyword != keyword) continue;
    span.found = true;
    span.begin = at.begin(w.range.begin);
    span.end = at.end(w.range.end);
    if (!w.value && k + 1 < item.words.size()) {
      const FieldDesignWord& next = item.words[k + 1];
      if ((keyword == "at" && next.keyword == "vertex") ||
          (!next.keyword.empty() && !next.value && !isFieldDesignKeyword(next.keyword)))
        span.end = at.end(next.range.end);
    }
    break;
  }
  return span;
}

bool blank(char c) { return c == ' ' || c == '\t'; }

}  // namespace

bool editFieldDesignText(const std::string& fileName, const std::string& text, const std::string& fieldName,
                         const PageFieldElement& edit, const FieldEditBounds& bounds, std::string& out,
                         std::string& reason) {
  const frontend::SourceFile source = frontend::SourceFile::make(fileName, text);
  frontend::Program program;
  frontend::Diagnostics diags(&source);
  if (!frontend::parseProgram(source, program, diags) || diags.hasErrors()) {
    std::string first = diags.all().empty() ? "" : diags.format(diags.all().front());
    first = first.substr(0, std::min(first.find('\n'), size_t(200)));
    reason = "the grammar does not parse as it is now (" + first + "): fix it first";
    return false;
  }
  if (program.fields.empty()) {
    reason = "the grammar declares no field";
    return false;
  }
  const frontend::FieldDecl& field = program.fields.front();
  if (field.name != fieldName) {
    reason = "the grammar's first field is " + field.name + ", the overlay shows " +
             (fieldName.empty() ? std::string("none") : fieldName) + " (a module's?): ask for the overlay again";
    return false;
  }
  if (field.source != "design") {
    reason = "field " + field.name + " is not a design (`design tensor { ... }`): it has no elements to edit";
    return false;
  }
  std::vector<const FieldDesignItem*> elements;
  for (const FieldDesignItem& item : field.design)
    if (item.kind != "smooth") elements.push_back(&item);
  if (elements.empty() || field.design.empty()) {
    reason = "field " + field.name + " has no design elements";
    return false;
  }
  const bool add = edit.op == PageFieldElement::Op::Add;
  if (!add && edit.index >= elements.size()) {
    reason = "field " + field.name + " has " + std::to_string(elements.size()) + " design elements: no element " +
             std::to_string(edit.index);
    return false;
  }
  if (add && field.function == "vector" && (edit.kind == "wedge" || edit.kind == "trisector")) {
    reason = "a " + edit.kind + " is a tensor field's singularity; field " + field.name + " is a vector design";
    return false;
  }
  if (edit.op == PageFieldElement::Op::Delete && elements.size() == 1) {
    reason = "a design needs at least one element: field " + field.name + "'s last one stays";
    return false;
  }
  // A millionth of the surface's size, as the overlay's coordinates.
  const double diagonal = std::hypot(bounds.max[0] - bounds.min[0], bounds.max[1] - bounds.min[1],
                                     bounds.max[2] - bounds.min[2]);
  const int digits = std::clamp(5 - static_cast<int>(std::floor(std::log10(diagonal > 0 ? diagonal : 1))), -8, 12);
  const double scale = std::pow(10.0, digits);
  if (add || edit.op == PageFieldElement::Op::Move)
    for (int k = 0; k < 3; ++k)
      if (!(edit.position[k] >= bounds.min[k] - diagonal && edit.position[k] <= bounds.max[k] + diagonal)) {
        reason = "the position is off the surface (farther outside its bounding box than its diagonal)";
        return false;
      }

  const FieldEditOffsets offsets(text);
  std::string replacement;
  size_t from = 0, to = 0;  // the bytes replaced
  const std::string strength = "strength " + fieldEditNumber(edit.strength, 1e4);
  if (add) {
    std::string item = edit.kind + " at " + fieldEditPoint(edit.position, scale);
    if (edit.hasDirection) {
      const double n = std::hypot(edit.direction[0], edit.direction[1], edit.direction[2]);
      const double unit[3] = {edit.direction[0] / n, edit.direction[1] / n, edit.direction[2] / n};
      item += " direction " + fieldEditPoint(unit, 1e4);
    }
    if (edit.hasStrength) item += " " + strength;
    item += ";";
    // After the block's last item: on a line of its own when that one has its own line
    // (indented as it is, after a comment that ends the line), else after a space.
    const FieldDesignItem& last = field.design.back();
    const size_t lastBegin = offsets.begin(last.range.begin), lastEnd = offsets.end(last.range.end);
    size_t lineStart = lastBegin;
    while (lineStart > 0 && blank(text[lineStart - 1])) --lineStart;
    const bool ownLine = lineStart == 0 || text[lineStart - 1] == '\n';
    size_t after = lastEnd;
    while (after < text.size() && blank(text[after])) ++after;
    const bool restOfLineFree = after >= text.size() || text[after] == '\n' || text[after] == '\r' ||
                                text.compare(after, 2, "//") == 0;
    if (ownLine && restOfLineFree) {
      from = to = std::min(text.find('\n', lastEnd), text.size());
      if (from > lastEnd && text[from - 1] == '\r') --from, --to;  // CRLF: before the \r
      replacement = (text.find("\r\n") != std::string::npos ? "\r\n" : "\n") + text.substr(lineStart, lastBegin - lineStart) + item;
    } else {
      from = to = lastEnd;
      replacement = " " + item;
    }
  } else {
    const FieldDesignItem& item = *elements[edit.index];
    const size_t begin = offsets.begin(item.range.begin), end = offsets.end(item.range.end);
    if (edit.op == PageFieldElement::Op::Move) {
      const FieldEditSpan at = keywordSpan(item, "at", offsets);
      from = at.found ? at.begin : end;  // (a position is required: E039)
      to = at.found ? at.end : end;
      replacement = "at " + fieldEditPoint(edit.position, scale);
    } else if (edit.op == PageFieldElement::Op::Strength) {
      const FieldEditSpan s = keywordSpan(item, "strength", offsets);
      if (s.found) {
        from = s.begin, to = s.end;
        replacement = strength;
      } else {  // after the last word, before the ';'
        from = to = item.words.empty() ? offsets.end(item.kindRange.end) : offsets.end(item.words.back().range.end);
        replacement = " " + strength;
      }
    } else {  // delete: the item, and its line when it is alone on it (but for its comment)
      size_t lineStart = begin;
      while (lineStart > 0 && blank(text[lineStart - 1])) --lineStart;
      const bool first = lineStart == 0 || text[lineStart - 1] == '\n';
      size_t after = end;
      while (after < text.size() && blank(text[after])) ++after;
      const size_t lineEnd = std::min(text.find('\n', end), text.size());
      const bool commented = text.compare(after, 2, "//") == 0;
      if (commented || (after < text.size() && text[after] == '\r')) after = lineEnd;
      const bool alone = after >= text.size() || text[after] == '\n';
      if (first && alone) from = lineStart, to = std::min(after + 1, text.size());
      else if (first) from = begin, to = after;
      else from = lineStart, to = end;
    }
  }
  out = text.substr(0, from) + replacement + text.substr(to);
  return true;
}

}  // namespace fgsg::cli
