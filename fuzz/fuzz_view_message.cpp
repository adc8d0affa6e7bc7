// libFuzzer target: the messages a page sends `fgsg view` (cli/view_message.h), checked
// before they change anything. Oracles: no exception leaves parsePageRequest; a rejection
// has a short reason (quoting at most 60 bytes of the message); an accepted message is a
// JSON object nested at most kMaxPageMessageDepth deep within kMaxPageMessageBytes, with
// at most kMaxPageAttrs names of at most kMaxPageNameBytes and values of at most
// kMaxPageValueBytes without NUL; written back as JSON it is accepted again as the same
// request; jsonNestingWithin agrees with the depth of every text that parses.
#include "cli/view_message.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz_view_message finding: %s\n", what.c_str());
  std::abort();
}

int depthOf(const nlohmann::json& j) {
  int d = 0;
  if (j.is_structured())
    for (const auto& c : j) d = std::max(d, depthOf(c));
  return j.is_structured() ? d + 1 : 0;
}

bool same(const fgsg::cli::PageRequest& a, const fgsg::cli::PageRequest& b) {
  return a.kind == b.kind && a.hasAttrs == b.hasAttrs && a.attrs == b.attrs && a.hasSeed == b.hasSeed &&
         a.seed == b.seed && a.instance == b.instance;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace fgsg::cli;
  if (size > kMaxPageMessageBytes + 16) return -1;
  const std::string text(reinterpret_cast<const char*>(data), size);
  PageRequest request;
  std::string reason;
  bool ok = false;
  try {
    ok = parsePageRequest(text, request, reason);
  } catch (const std::exception& e) {
    finding(std::string("an exception left the parser: ") + e.what());
  }
  // The nesting scan against the parser, on texts the parser takes.
  const bool within = jsonNestingWithin(text, kMaxPageMessageDepth);
  // (nlohmann's parser stops at a NUL byte: only texts without one are compared.)
  if (const auto j = nlohmann::json::parse(text, nullptr, false);
      text.find('\0') == std::string::npos && !j.is_discarded() && within != (depthOf(j) <= kMaxPageMessageDepth))
    finding("jsonNestingWithin says " + std::string(within ? "within" : "beyond") + " for depth " + std::to_string(depthOf(j)));
  if (!ok) {
    if (reason.empty()) finding("a rejection without a reason");
    if (reason.size() > 256) finding("a reason of " + std::to_string(reason.size()) + " bytes");
    return 0;
  }
  if (text.size() > kMaxPageMessageBytes) finding("a message past the size cap was accepted");
  if (!within) finding("a message past the nesting cap was accepted");
  if (text.find('\0') != std::string::npos) finding("a message with a NUL byte was accepted");
  if (request.attrs.size() > kMaxPageAttrs) finding("too many attrs accepted");
  nlohmann::json back = {{"type", request.kind == PageRequest::Kind::Pick ? "pick" : "set"}};
  if (request.kind == PageRequest::Kind::Pick) back["instance"] = request.instance;
  if (request.hasSeed) back["seed"] = request.seed;
  if (request.hasAttrs) {
    back["attrs"] = nlohmann::json::object();
    for (const auto& [name, value] : request.attrs) {
      if (name.empty() || name.size() > kMaxPageNameBytes) finding("an attr name of " + std::to_string(name.size()) + " bytes accepted");
      if (value.size() > kMaxPageValueBytes || value.find('\0') != std::string::npos) finding("an attr value accepted: " + value.substr(0, 60));
      back["attrs"][name] = value;  // as text: the same --set text again
    }
  }
  std::string written;
  try {
    written = back.dump();
  } catch (const std::exception& e) {
    finding(std::string("an accepted request cannot be written as JSON: ") + e.what());
  }
  PageRequest again;
  std::string againReason;
  if (!parsePageRequest(written, again, againReason)) finding("a request written back is rejected: " + againReason);
  // (A name given twice in one message is taken once, as the JSON object keeps it.)
  if (!same(request, again)) finding("a request written back reads differently: " + written);
  return 0;
}
