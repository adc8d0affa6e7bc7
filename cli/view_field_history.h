// Undo and redo of fgsg view's field design edits (#49): each edit the page makes to the
// design elements (view_field_edit.h) is kept as the grammar's whole text before and after
// it, so an undo writes back exactly the bytes before — a deleted element comes back where
// it was with its kind, strength, comment and layout, a moved one at its old words — and a
// redo exactly the bytes after. The moves of one drag are one step. A step applies only
// while the file still holds what the last edit left: a grammar saved from an editor since
// is never overwritten (the history is dropped, the undo refused with the reason).
// {"type":"undo"|"redo", "history":"field"} (view_message.h); paint strokes keep their own
// (view_paint.h), the page picks one by its mode.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace fgsg::cli {

// At most this many edits are kept, and at most this many bytes of grammar text.
constexpr size_t kMaxFieldUndoSteps = 64;
constexpr size_t kMaxFieldUndoBytes = size_t(64) << 20;

// The grammar file's bytes, to be rewritten from the page. False with a reason when it is
// a symbolic link (fgsg view writes only the grammar's own file, never a link's target) or
// cannot be read. `what` starts the reason ("fieldElement", "undo" ...).
bool readGrammarToEdit(const std::string& path, const std::string& what, std::string& text, std::string& reason);

class ViewFieldHistory {
 public:
  // An edit written into the grammar: its text `before` and `after`. Edits by one page with
  // the same non-zero `drag` in a row are one step (the text before the first, after the
  // last). A text before that is not what the last step left (the file was edited outside
  // since) drops the older steps. Redo is cleared.
  void record(const std::string& before, const std::string& after, uint64_t page, uint64_t drag);
  // Writes the text before the last step (after the last undone one), atomically. False
  // with a reason, nothing written, when there is none, when the file no longer holds the
  // step's text after (before) it — then the whole history is dropped — or on a write error.
  bool undo(const std::string& grammarPath, std::string& reason);
  bool redo(const std::string& grammarPath, std::string& reason);

  size_t undoable() const { return undo_.size(); }
  size_t redoable() const { return redo_.size(); }

 private:
  struct Step {
    std::string before, after;
    uint64_t page = 0, drag = 0;
  };
  bool apply(bool undo, const std::string& grammarPath, std::string& reason);
  std::vector<Step> undo_, redo_;
};

}  // namespace fgsg::cli
