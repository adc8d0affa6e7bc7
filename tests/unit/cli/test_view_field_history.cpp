// fgsg view's undo and redo of field design edits (cli/view_field_history.h), on a real
// grammar file: each undo writes back the exact bytes before its edit, each redo those
// after, a drag's moves are one step, and a file changed outside is never overwritten.
#include "cli/view_field_history.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

using fgsg::cli::kMaxFieldUndoSteps;
using fgsg::cli::readGrammarToEdit;
using fgsg::cli::ViewFieldHistory;
namespace fs = std::filesystem;

namespace {

// A fresh folder holding g.fgsg with `text`, removed at the end.
struct FieldHistoryFolder {
  fs::path dir, grammar;
  explicit FieldHistoryFolder(const std::string& text) {
    dir = fs::temp_directory_path() / ("fgsg-field-history-" + std::to_string(std::random_device{}()));
    fs::create_directories(dir);
    grammar = dir / "g.fgsg";
    write(text);
  }
  ~FieldHistoryFolder() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  void write(const std::string& text) const { std::ofstream(grammar, std::ios::binary) << text; }
  std::string read() const {
    std::ifstream in(grammar, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }
};

// What the page's edits would write: the file goes from `before` to `after`, recorded.
void fieldHistoryEdit(const FieldHistoryFolder& f, ViewFieldHistory& h, const std::string& before,
                      const std::string& after, uint64_t page = 1, uint64_t drag = 0) {
  f.write(after);
  h.record(before, after, page, drag);
}

const std::string kFieldHistory0 = "// kept\nfield F = design tensor { trisector at (2, 0, 0) decay 1; };  // x\n";
const std::string kFieldHistory1 =
    "// kept\nfield F = design tensor { trisector at (2, 0, 0) decay 1; wedge at (-2, 0, 0); };  // x\n";
const std::string kFieldHistory2 =
    "// kept\nfield F = design tensor { trisector at (2, 0, 0) decay 1; wedge at (-3, 2, 0); };  // x\n";
const std::string kFieldHistory3 =
    "// kept\nfield F = design tensor { trisector at (2, 0, 0) decay 1; wedge at (-3, 2, 0) strength 2.5; };  // x\n";

}  // namespace

TEST_CASE("view field history: undo then redo gives each text back byte for byte (#49)") {
  FieldHistoryFolder f(kFieldHistory0);
  ViewFieldHistory h;
  std::string reason;
  CHECK_FALSE(h.undo(f.grammar.string(), reason));
  CHECK(reason == "undo: no field edit to undo");
  fieldHistoryEdit(f, h, kFieldHistory0, kFieldHistory1);  // add
  // A drag: three moves numbered 5 by page 1 are one step, from before the first to after the last.
  const std::string mid = "// kept\nfield F = design tensor { trisector at (2, 0, 0) decay 1; wedge at (-2.5, 1, 0); };  // x\n";
  fieldHistoryEdit(f, h, kFieldHistory1, mid, 1, 5);
  fieldHistoryEdit(f, h, mid, kFieldHistory2, 1, 5);
  fieldHistoryEdit(f, h, kFieldHistory2, kFieldHistory2, 1, 5);  // a move to where it is
  fieldHistoryEdit(f, h, kFieldHistory2, kFieldHistory3);        // strength
  fieldHistoryEdit(f, h, kFieldHistory3, kFieldHistory0);        // delete: the file as it was
  CHECK(h.undoable() == 4);
  const std::string states[] = {kFieldHistory0, kFieldHistory1, kFieldHistory2, kFieldHistory3, kFieldHistory0};
  for (int k = 3; k >= 0; --k) {
    REQUIRE(h.undo(f.grammar.string(), reason));
    CHECK(f.read() == states[k]);
  }
  CHECK_FALSE(h.undo(f.grammar.string(), reason));
  CHECK(reason == "undo: no field edit to undo");
  CHECK(f.read() == kFieldHistory0);
  for (int k = 1; k <= 4; ++k) {
    REQUIRE(h.redo(f.grammar.string(), reason));
    CHECK(f.read() == states[k]);
  }
  CHECK_FALSE(h.redo(f.grammar.string(), reason));
  CHECK(reason == "redo: no field edit to redo");
  // A new edit after an undo drops the redo.
  REQUIRE(h.undo(f.grammar.string(), reason));
  fieldHistoryEdit(f, h, kFieldHistory3, kFieldHistory2);
  CHECK(h.redoable() == 0);
  CHECK(h.undoable() == 4);
}

TEST_CASE("view field history: a drag's moves merge only for its own page and number (#49)") {
  FieldHistoryFolder f(kFieldHistory1);
  ViewFieldHistory h;
  fieldHistoryEdit(f, h, kFieldHistory1, kFieldHistory2, 1, 5);
  fieldHistoryEdit(f, h, kFieldHistory2, kFieldHistory3, 2, 5);  // another page's drag 5
  CHECK(h.undoable() == 2);
  fieldHistoryEdit(f, h, kFieldHistory3, kFieldHistory2, 2, 6);
  fieldHistoryEdit(f, h, kFieldHistory2, kFieldHistory3, 2, 6);  // back where the drag began: no step
  CHECK(h.undoable() == 2);
  // An undone drag step comes back by redo as its own: a later move of that drag is a new step.
  std::string reason;
  REQUIRE(h.undo(f.grammar.string(), reason));
  REQUIRE(h.redo(f.grammar.string(), reason));
  fieldHistoryEdit(f, h, kFieldHistory3, kFieldHistory1, 2, 5);
  CHECK(h.undoable() == 3);
}

TEST_CASE("view field history: a grammar changed outside is never overwritten (#49)") {
  FieldHistoryFolder f(kFieldHistory0);
  ViewFieldHistory h;
  fieldHistoryEdit(f, h, kFieldHistory0, kFieldHistory1);
  fieldHistoryEdit(f, h, kFieldHistory1, kFieldHistory2);
  const std::string saved = kFieldHistory2 + "// saved from an editor\n";
  f.write(saved);
  std::string reason;
  CHECK_FALSE(h.undo(f.grammar.string(), reason));
  CHECK(reason.find("undo: g.fgsg was changed outside the viewer") == 0);
  CHECK(f.read() == saved);
  CHECK(h.undoable() == 0);
  CHECK(h.redoable() == 0);
  // The same for redo; and an edit whose text before is not the last one's after starts afresh.
  fieldHistoryEdit(f, h, saved, kFieldHistory1);
  REQUIRE(h.undo(f.grammar.string(), reason));
  CHECK(f.read() == saved);
  f.write(kFieldHistory3);
  CHECK_FALSE(h.redo(f.grammar.string(), reason));
  CHECK(reason.find("redo: g.fgsg was changed outside") == 0);
  CHECK(f.read() == kFieldHistory3);
  fieldHistoryEdit(f, h, kFieldHistory0, kFieldHistory1);
  fieldHistoryEdit(f, h, kFieldHistory3, kFieldHistory2);  // kFieldHistory3 written outside between
  CHECK(h.undoable() == 1);
  REQUIRE(h.undo(f.grammar.string(), reason));
  CHECK(f.read() == kFieldHistory3);
}

TEST_CASE("view field history: at most 64 steps kept, a symbolic link never written (#49)") {
  FieldHistoryFolder f("0");
  ViewFieldHistory h;
  for (int k = 0; k < 70; ++k) fieldHistoryEdit(f, h, std::to_string(k), std::to_string(k + 1));
  CHECK(h.undoable() == kMaxFieldUndoSteps);
  std::string reason, text;
  while (h.undo(f.grammar.string(), reason)) {
  }
  CHECK(f.read() == "6");  // the first 6 edits are forgotten
  const fs::path link = f.dir / "linked.fgsg";
  fs::create_symlink(f.grammar, link);
  CHECK_FALSE(readGrammarToEdit(link.string(), "undo", text, reason));
  CHECK(reason == "undo: linked.fgsg is a symbolic link; fgsg view writes only the grammar's own file");
  h.record("6", "7", 1, 0);
  f.write("7");
  CHECK_FALSE(h.undo(link.string(), reason));
  CHECK(f.read() == "7");
  CHECK(reason.find("symbolic link") != std::string::npos);
  REQUIRE(readGrammarToEdit(f.grammar.string(), "undo", text, reason));
  CHECK(text == "7");
}
