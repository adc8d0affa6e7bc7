#include "cli/scene_output.h"

#include "cli/options.h"
#include "runtime/output/gltf_writer.h"

namespace fgsg::cli {

namespace {

// The group of each rule: its label for --group-by rule; for --group-by label the label
// the grammar gave it, or its predecessor for an unlabelled rule (`Pred#n`), so that
// the rules of one symbol without labels are one group.
std::vector<std::string> ruleGroups(const ir::Module& m, rt::output::GroupBy by) {
  std::vector<std::string> names;
  for (const ir::Rule& r : m.rules) {
    std::string name = r.label;
    if (by == rt::output::GroupBy::Label && r.symbol < m.symbols.size()) {
      const std::string& pred = m.symbols[r.symbol].name;
      const bool numbered = name.size() > pred.size() + 1 && name.compare(0, pred.size() + 1, pred + "#") == 0 &&
                            name.find_first_not_of("0123456789", pred.size() + 1) == std::string::npos;
      if (numbered) name = pred;
    }
    names.push_back(std::move(name));
  }
  return names;
}

rt::output::StartInfo lotInfo(const rt::Lot& lot) {
  rt::output::StartInfo info;
  if (!lot.id.empty())
    info.name = lot.id;
  else
    info.name = (lot.isFace ? "face " : "feature ") + std::to_string(lot.feature);
  if (lot.part > 0) info.name += " polygon " + std::to_string(lot.part);
  info.numbers = lot.numbers;
  info.strings = lot.strings;
  return info;
}

}  // namespace

bool writesScene(const SceneFlags& flags, const std::string& path) {
  return !flags.flattened() || lowerExtension(path) == ".gltf";
}

bool stageScene(const SceneFlags& flags, const ir::Module& module, const rt::DeriveOptions& derive,
                const rt::DeriveResult& result, const rt::AssetLibrary& assets, const std::vector<int>& meshOf,
                const std::string& path, rt::io::OutputTransaction& outputs, std::string& error) {
  rt::output::SceneInput in;
  in.list = &result.instances;
  in.library = &assets;
  in.meshOf = &meshOf;
  in.groupBy = flags.groupBy;
  in.instancing = flags.instancing;
  if (flags.groupBy == rt::output::GroupBy::Rule || flags.groupBy == rt::output::GroupBy::Label)
    in.ruleGroups = ruleGroups(module, flags.groupBy);
  const size_t starts = result.instances.startBounds.size() > 1 ? result.instances.startBounds.size() - 1 : 1;
  for (size_t k = 0; k < starts; ++k) {
    if (!derive.lots.empty() && k < derive.lots.size())
      in.starts.push_back(lotInfo(derive.lots[k]));
    else if (starts > 1)
      in.starts.push_back({"seed " + std::to_string(k), {}, {}});
    else
      in.starts.push_back({"axiom", {}, {}});
  }
  const rt::output::Scene scene = rt::output::buildScene(in);
  return rt::output::stageGltf(scene, path, outputs, error);
}

}  // namespace fgsg::cli
