#include "cli/lsp/lsp_documents.h"

#include "cli/lsp/lsp_text.h"

#include <utility>

namespace fgsg::cli::lsp {

void DocumentStore::open(const std::string& uri, std::string text, int version) {
  documents_[uri] = Document{pathOfUri(uri), std::move(text), version, nullptr};
}

bool DocumentStore::change(const std::string& uri, const Json& change, int version) {
  auto it = documents_.find(uri);
  if (it == documents_.end() || !change.is_object() || !change.contains("text") || !change["text"].is_string())
    return false;
  Document& doc = it->second;
  const std::string& replacement = change["text"].get_ref<const std::string&>();
  if (change.contains("range") && change["range"].is_object()) {
    const Json& range = change["range"];
    auto offset = [&](const char* which) {
      const Json& p = range.value(which, Json::object());
      return offsetAt(doc.text, std::max(p.value("line", 0), 0), std::max(p.value("character", 0), 0));
    };
    size_t from = offset("start"), to = offset("end");
    if (to < from) std::swap(from, to);
    doc.text.replace(from, to - from, replacement);
  } else {
    doc.text = replacement;
  }
  doc.version = version;
  if (doc.analysis) doc.previous = std::move(doc.analysis);
  doc.analysis = nullptr;
  return true;
}

void DocumentStore::close(const std::string& uri) { documents_.erase(uri); }

const std::string* DocumentStore::text(const std::string& uri) const {
  auto it = documents_.find(uri);
  return it == documents_.end() ? nullptr : &it->second.text;
}

std::shared_ptr<const Analysis> DocumentStore::analysis(const std::string& uri) {
  auto it = documents_.find(uri);
  if (it == documents_.end()) return nullptr;
  Document& doc = it->second;
  if (!doc.analysis) doc.analysis = analyze(doc.path, doc.text, std::exchange(doc.previous, nullptr));
  return it->second.analysis;
}

}  // namespace fgsg::cli::lsp
