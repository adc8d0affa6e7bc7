#include "backend/synthesis_examples.h"

#include "runtime/io/find_file.h"

#include <algorithm>
#include <functional>

namespace fgsg::backend {

std::vector<SynthesizeCall> synthesizeCalls(const ir::Module& m) {
  std::vector<SynthesizeCall> calls;
  std::function<void(const ir::Block&)> inBlock = [&](const ir::Block& b) {
    for (const auto& op : b) {
      if (op.kind == ir::OpKind::Synthesize) calls.push_back({m.strings[op.str], op.loc});
      for (const auto& body : op.bodies) inBlock(body);
    }
  };
  inBlock(m.axiom);
  for (const auto& r : m.rules)
    for (const auto& alt : r.alternatives) inBlock(alt.ops);
  std::stable_sort(calls.begin(), calls.end(), [](const SynthesizeCall& a, const SynthesizeCall& b) {
    return a.at.line != b.at.line ? a.at.line < b.at.line : a.at.col < b.at.col;
  });
  return calls;
}

bool loadSynthesisExample(const std::string& name, const std::vector<std::string>& dirs,
                          rt::synthesis::Example& out, std::string& message) {
  rt::synthesis::Diagnostics diags;
  if (rt::synthesis::loadExample(rt::io::findFile(name, dirs), out, diags)) return true;
  std::string details = rt::synthesis::formatDiagnostics(diags);
  while (!details.empty() && details.back() == '\n') details.pop_back();  // the caret follows
  message = "Synthesize: cannot use the example \"" + name + "\":\n" + details;
  return false;
}

bool loadContinuousExample(const std::string& name, const std::vector<std::string>& dirs,
                           rt::synthesis::continuous::ExampleSolid& out, std::string& message,
                           rt::Deadline* deadline) {
  std::string error;
  if (rt::synthesis::continuous::loadExampleSolid(rt::io::findFile(name, dirs), out, error, deadline)) return true;
  message = "Synthesize: cannot use the example \"" + name + "\": " + error;
  return false;
}

}  // namespace fgsg::backend
