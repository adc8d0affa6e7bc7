#include "cli/view_field_history.h"

#include "runtime/io/atomic_file.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fgsg::cli {

namespace fs = std::filesystem;

bool readGrammarToEdit(const std::string& path, const std::string& what, std::string& text, std::string& reason) {
  // The grammar is written in place of itself: never through a link to somewhere else.
  std::error_code ec;
  if (fs::is_symlink(fs::symlink_status(path, ec))) {
    reason = what + ": " + fs::path(path).filename().string() +
             " is a symbolic link; fgsg view writes only the grammar's own file";
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (!in) {
    reason = what + ": cannot read " + path;
    return false;
  }
  text = bytes.str();
  return true;
}

void ViewFieldHistory::record(const std::string& before, const std::string& after, uint64_t page, uint64_t drag) {
  redo_.clear();
  if (!undo_.empty() && undo_.back().after != before) undo_.clear();  // edited outside since: no way back
  if (drag != 0 && !undo_.empty() && undo_.back().page == page && undo_.back().drag == drag) {
    undo_.back().after = after;  // the drag goes on: still one step
    if (undo_.back().before == after) undo_.pop_back();  // and came back where it started
    return;
  }
  if (before == after) return;  // nothing to undo
  undo_.push_back({before, after, page, drag});
  size_t bytes = 0;
  for (const Step& s : undo_) bytes += s.before.size() + s.after.size();
  while (undo_.size() > kMaxFieldUndoSteps || (bytes > kMaxFieldUndoBytes && undo_.size() > 1)) {
    bytes -= undo_.front().before.size() + undo_.front().after.size();
    undo_.erase(undo_.begin());
  }
}

bool ViewFieldHistory::apply(bool undo, const std::string& grammarPath, std::string& reason) {
  const std::string what = undo ? "undo" : "redo";
  std::vector<Step>& from = undo ? undo_ : redo_;
  std::vector<Step>& to = undo ? redo_ : undo_;
  if (from.empty()) {
    reason = what + ": no field edit to " + what;
    return false;
  }
  std::string text;
  if (!readGrammarToEdit(grammarPath, what, text, reason)) return false;
  Step& step = from.back();
  const std::string& expected = undo ? step.after : step.before;
  if (text != expected) {
    undo_.clear();
    redo_.clear();
    reason = what + ": " + fs::path(grammarPath).filename().string() +
             " was changed outside the viewer since the last field edit; its field edits can no longer be " +
             (undo ? "undone" : "redone");
    return false;
  }
  std::string error;
  if (!rt::io::writeFileAtomically(grammarPath, undo ? step.before : step.after, error)) {
    reason = what + ": " + error;
    return false;
  }
  step.drag = 0;  // a later move of the same drag is a step of its own
  to.push_back(std::move(step));
  from.pop_back();
  return true;
}

bool ViewFieldHistory::undo(const std::string& grammarPath, std::string& reason) {
  return apply(true, grammarPath, reason);
}

bool ViewFieldHistory::redo(const std::string& grammarPath, std::string& reason) {
  return apply(false, grammarPath, reason);
}

}  // namespace fgsg::cli
