// The documents the editor has open: their text as the editor holds it (full or
// incremental changes applied), and their analysis, redone only when the text changed.
#pragma once

#include "cli/lsp/lsp_analysis.h"

#include <map>
#include <memory>
#include <set>
#include <string>

namespace fgsg::cli::lsp {

class DocumentStore {
 public:
  void open(const std::string& uri, std::string text, int version);
  // One entry of didChange's contentChanges: with a range, that range's text replaced;
  // without one, the whole text. False for a document that is not open.
  bool change(const std::string& uri, const Json& change, int version);
  void close(const std::string& uri);
  bool isOpen(const std::string& uri) const { return documents_.count(uri) > 0; }
  const std::string* text(const std::string& uri) const;
  // The analysis of the document's current text (null when it is not open).
  std::shared_ptr<const Analysis> analysis(const std::string& uri);

 private:
  struct Document {
    std::string path;
    std::string text;
    int version = 0;
    std::shared_ptr<Analysis> analysis;  // of `text`; null: not yet or stale
    // The last analysis before the text changed: the next one takes over its unchanged
    // statements (statement reuse), then drops it.
    std::shared_ptr<Analysis> previous;
  };
  std::map<std::string, Document> documents_;
};

}  // namespace fgsg::cli::lsp
