#include "cli/derive_flags.h"

namespace fgsg::cli {

void engineFlag(CommandLine& cl, backend::Engine& engine) {
  cl.option("--engine", [&engine](const std::string& name) {
    const auto parsed = backend::parseEngine(name);
    if (!parsed) throw UsageError{"--engine " + name + ": unknown engine (use interp or jit)"};
    engine = *parsed;
  });
}

void setFlag(CommandLine& cl, rt::DeriveOptions& derive) {
  cl.repeated("--set", [&derive](const std::string& kv) {
    const auto eq = kv.find('=');
    if (eq == std::string::npos || eq == 0) throw UsageError{"--set expects name=value, got '" + kv + "'"};
    derive.attrOverrides.push_back({kv.substr(0, eq), kv.substr(eq + 1)});
  });
}

void startRuleFlag(CommandLine& cl, std::string& startRule) {
  cl.option("--start-rule", [&startRule](const std::string& v) {
    if (v.empty()) throw UsageError{"--start-rule needs a rule name"};
    startRule = v;
  });
}

void surfaceFlags(CommandLine& cl, rt::DeriveOptions& derive) {
  cl.option("--surface", [&derive](const std::string& v) {
    if (v.empty()) throw UsageError{"--surface needs a mesh file name"};
    derive.surfaceOverride = v;
  });
  cl.option("--surface-size", [&derive](const std::string& v) {
    derive.surfaceSize = CommandLine::parseNumber("--surface-size", v);
    if (!(derive.surfaceSize > 0)) throw UsageError{"--surface-size must be a positive number"};
  });
  cl.flag("--repair-surface", derive.repairSurface);
}

void sceneFlags(CommandLine& cl, SceneFlags& scene) {
  cl.option("--instancing", [&scene](const std::string& v) {
    if (!rt::output::parseInstancing(v, scene.instancing))
      throw UsageError{"--instancing " + v + ": use auto, on, nodes or off"};
    scene.instancingGiven = true;
  });
  cl.option("--group-by", [&scene](const std::string& v) {
    if (!rt::output::parseGroupBy(v, scene.groupBy))
      throw UsageError{"--group-by " + v + ": use symbol, rule, label or none"};
    scene.groupByGiven = true;
  });
  cl.option("--split-output", [&scene](const std::string& v) {
    if (v.empty()) throw UsageError{"--split-output needs a folder"};
    scene.splitOutput = v;
  });
}

}  // namespace fgsg::cli
