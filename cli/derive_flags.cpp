#include "cli/derive_flags.h"

#include "backend/interp/eval.h"

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

void stepFlag(CommandLine& cl, rt::DeriveOptions& derive) {
  cl.whole("--step", derive.parallelStep, 0, 2147483647);
}

bool checkStepFlag(const ir::Module& m, const std::string& file, rt::DeriveOptions& derive, std::string& error,
                   std::string& warning, const std::string& flag) {
  if (derive.parallelStep < 0) return true;
  const std::string step = flag + " " + std::to_string(derive.parallelStep);
  int length = -1;
  try {
    length = backend::parallelDerivationLength(m, derive.attrOverrides);
  } catch (const backend::DeriveError&) {
    return true;  // --set values that do not fit: the derivation says so (R010), located
  }
  if (length < 0) {
    error = step + ": " + file +
            " is no L-system: its derivation is sequential (derive breadthfirst or depthfirst), which has no "
            "steps; " + flag + " counts the steps of `derive parallel N;`";
    return false;
  }
  if (derive.parallelStep > length) {
    warning = step + " is past " + file + "'s derivation length " + std::to_string(length) + ": step " +
              std::to_string(length) + ", its last, is derived (as lpfg's animate mode stops there)";
    derive.parallelStep = length;
  }
  return true;
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
  cl.flag("--quantize", scene.quantize);
  cl.option("--split-output", [&scene](const std::string& v) {
    if (v.empty()) throw UsageError{"--split-output needs a folder"};
    scene.splitOutput = v;
  });
}

}  // namespace fgsg::cli
