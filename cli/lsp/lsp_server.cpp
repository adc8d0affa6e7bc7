#include "cli/lsp/lsp_server.h"

#include "cli/lsp/lsp_documents.h"
#include "cli/lsp/lsp_features.h"
#include "cli/lsp/lsp_framing.h"
#include "cli/lsp/lsp_text.h"
#include "cli/view_message.h"

#include <iostream>
#include <set>

namespace fgsg::cli::lsp {
namespace {

// JSON-RPC's and LSP's error codes.
constexpr int kParseError = -32700, kInvalidRequest = -32600, kMethodNotFound = -32601, kInvalidParams = -32602,
              kInternalError = -32603,
              kServerNotInitialized = -32002, kRequestFailed = -32803;
// Deeper JSON than any LSP message has is refused before it is parsed.
constexpr int kMaxJsonDepth = 64;

class Server {
 public:
  Server(int in, int out) : reader_(in), out_(out) {}

  int run() {
    for (;;) {
      if (!dirty_.empty() && !reader_.inputPending()) publishDirty();
      std::string body, error;
      switch (reader_.next(body, error)) {
        case MessageReader::Status::End: return shutdown_ ? 0 : 1;
        case MessageReader::Status::Malformed: sendError(nullptr, kInvalidRequest, "fgsg lsp: " + error); break;
        case MessageReader::Status::Message: handle(body); break;
      }
      if (exitCode_ >= 0 || outputGone_) return exitCode_ >= 0 ? exitCode_ : 1;
    }
  }

 private:
  void send(const Json& message) {
    if (!writeMessage(out_, message.dump(-1, ' ', false, Json::error_handler_t::replace))) outputGone_ = true;
  }
  void sendResult(const Json& id, const Json& result) { send(Json{{"jsonrpc", "2.0"}, {"id", id}, {"result", result}}); }
  void sendError(const Json& id, int code, const std::string& message) {
    send(Json{{"jsonrpc", "2.0"}, {"id", id}, {"error", Json{{"code", code}, {"message", message}}}});
  }

  void handle(const std::string& body) {
    if (!jsonNestingWithin(body, kMaxJsonDepth)) {
      sendError(nullptr, kParseError, "fgsg lsp: JSON nested deeper than " + std::to_string(kMaxJsonDepth));
      return;
    }
    const Json message = Json::parse(body, nullptr, false);
    if (message.is_discarded()) {
      sendError(nullptr, kParseError, "fgsg lsp: the message is not JSON");
      return;
    }
    const bool hasId = message.is_object() && message.contains("id");
    const Json id = hasId && (message["id"].is_number_integer() || message["id"].is_string()) ? message["id"] : Json();
    if (!message.is_object() || !message.contains("method") || !message["method"].is_string()) {
      // A response to a request of ours (we send none) is dropped; anything else is wrong.
      if (!(message.is_object() && (message.contains("result") || message.contains("error"))))
        sendError(id, kInvalidRequest, "fgsg lsp: a request needs a method");
      return;
    }
    if (hasId && id.is_null()) {
      sendError(nullptr, kInvalidRequest, "fgsg lsp: a request's id is a number or a string");
      return;
    }
    const std::string method = message["method"];
    const Json params = message.contains("params") ? message["params"] : Json::object();
    try {
      if (hasId) {
        request(id, method, params);
      } else {
        notification(method, params);
      }
    } catch (const std::exception& e) {
      // A field of the wrong type (nlohmann's type_error) or a bug: this message fails, the
      // server goes on.
      if (hasId) sendError(id, kInternalError, std::string("fgsg lsp: ") + e.what());
      else std::cerr << "fgsg lsp: " << method << ": " << e.what() << "\n";
    }
  }

  void request(const Json& id, const std::string& method, const Json& params) {
    if (method == "initialize") {
      initialized_ = true;
      sendResult(id, Json{{"capabilities",
                           Json{{"textDocumentSync", Json{{"openClose", true}, {"change", 2}}},  // incremental
                                {"completionProvider", Json{{"triggerCharacters", Json::array({".", "\"", "/"})}}},
                                {"hoverProvider", true},
                                {"definitionProvider", true},
                                {"documentSymbolProvider", true},
                                {"referencesProvider", true},
                                {"renameProvider", true},
                                {"documentFormattingProvider", true},
                                {"semanticTokensProvider",
                                 Json{{"legend", semanticTokensLegend()}, {"full", true}, {"range", true}}}}},
                          {"serverInfo", Json{{"name", "fgsg"}, {"version", "0.1.0"}}}});
      return;
    }
    if (!initialized_) return sendError(id, kServerNotInitialized, "fgsg lsp: initialize first");
    if (shutdown_) return sendError(id, kInvalidRequest, "fgsg lsp: shut down; only exit is left");
    if (method == "shutdown") {
      shutdown_ = true;
      return sendResult(id, nullptr);
    }
    const bool positional = method == "textDocument/completion" || method == "textDocument/hover" ||
                            method == "textDocument/definition" || method == "textDocument/references" ||
                            method == "textDocument/rename";
    const bool tokens = method == "textDocument/semanticTokens/full" || method == "textDocument/semanticTokens/range";
    if (!positional && !tokens && method != "textDocument/documentSymbol" && method != "textDocument/formatting")
      return sendError(id, kMethodNotFound, "fgsg lsp: no method " + method);
    const std::string uri = params.at("textDocument").at("uri").get<std::string>();
    if (method == "textDocument/formatting") {  // from the text alone: no analysis needed
      const std::string* text = documents_.text(uri);
      if (!text) return sendResult(id, nullptr);
      std::string error;
      const Json edits = formatting(pathOfUri(uri), *text, error);
      return edits.is_null() ? sendError(id, kRequestFailed, "fgsg lsp: " + error) : sendResult(id, edits);
    }
    const auto analysis = documents_.analysis(uri);
    if (!analysis) return sendResult(id, nullptr);  // not open: nothing known of it
    if (method == "textDocument/documentSymbol") return sendResult(id, documentSymbols(*analysis));
    if (tokens) {
      const Json range = params.contains("range") ? params["range"] : Json();
      return sendResult(id, semanticTokens(*analysis, *documents_.text(uri), range));
    }
    const std::string& text = *documents_.text(uri);
    const int line = params.at("position").at("line").get<int>();
    const int character = params.at("position").at("character").get<int>();
    if (method == "textDocument/completion") return sendResult(id, completion(*analysis, text, line, character));
    if (method == "textDocument/hover") return sendResult(id, hover(*analysis, text, line, character));
    if (method == "textDocument/references") {
      const bool declaration = params.value("context", Json::object()).value("includeDeclaration", true);
      return sendResult(id, references(*analysis, text, line, character, declaration));
    }
    if (method == "textDocument/rename") {
      std::string error;
      const Json edit = rename(*analysis, text, line, character, params.at("newName").get<std::string>(), error);
      return edit.is_null() ? sendError(id, kInvalidParams, "fgsg lsp: " + error) : sendResult(id, edit);
    }
    sendResult(id, definition(*analysis, text, line, character));
  }

  void notification(const std::string& method, const Json& params) {
    if (method == "exit") {
      exitCode_ = shutdown_ ? 0 : 1;
      return;
    }
    if (!initialized_ || shutdown_) return;
    if (method == "textDocument/didOpen") {
      const Json& doc = params.at("textDocument");
      const std::string uri = doc.at("uri").get<std::string>();
      documents_.open(uri, doc.at("text").get<std::string>(), doc.value("version", 0));
      dirty_.insert(uri);
    } else if (method == "textDocument/didChange") {
      const std::string uri = params.at("textDocument").at("uri").get<std::string>();
      const int version = params.at("textDocument").value("version", 0);
      for (const Json& change : params.at("contentChanges"))
        if (!documents_.change(uri, change, version)) break;
      if (documents_.isOpen(uri)) dirty_.insert(uri);
    } else if (method == "textDocument/didClose") {
      const std::string uri = params.at("textDocument").at("uri").get<std::string>();
      documents_.close(uri);
      dirty_.erase(uri);
      send(Json{{"jsonrpc", "2.0"},
                {"method", "textDocument/publishDiagnostics"},
                {"params", Json{{"uri", uri}, {"diagnostics", Json::array()}}}});
    }
    // initialized, $/cancelRequest, $/setTrace, didSave ...: nothing to do.
  }

  void publishDirty() {
    for (const std::string& uri : dirty_) {
      const auto analysis = documents_.analysis(uri);
      if (analysis)
        send(Json{{"jsonrpc", "2.0"},
                  {"method", "textDocument/publishDiagnostics"},
                  {"params", diagnosticsParams(*analysis, uri)}});
    }
    dirty_.clear();
  }

  MessageReader reader_;
  int out_;
  DocumentStore documents_;
  std::set<std::string> dirty_;
  bool initialized_ = false;
  bool shutdown_ = false;
  bool outputGone_ = false;
  int exitCode_ = -1;
};

}  // namespace

int serve(int in, int out) { return Server(in, out).run(); }

}  // namespace fgsg::cli::lsp
