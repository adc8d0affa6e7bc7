// Synthesize("example", nx, ny, nz): Merrell's model synthesis (runtime/synthesis/) fills
// the scope with an nx x ny x nz grid of pieces. A piece whose label names a symbol with
// rules becomes a shape of that symbol in its cell, to be derived further; any other
// piece places its asset. Examples are loaded once per derivation.
#pragma once

#include "backend/commands/command_family.h"
#include "runtime/synthesis/continuous/example_solid.h"
#include "runtime/synthesis/synthesis.h"

#include <map>
#include <string>

namespace fgsg::backend {

class Derivation;

class SynthesisCommand final : public CommandFamily {
 public:
  explicit SynthesisCommand(Derivation& derivation) : d_(derivation) {}

  std::vector<ir::OpKind> kinds() const override { return {ir::OpKind::Synthesize}; }
  void apply(const ir::Op& op, const double* a, uint32_t n, State& st, Exec& ex, Frame& f) override;

 private:
  const rt::synthesis::Example& loadExample(const std::string& name, ir::Loc at);
  uint32_t pieceAsset(const std::string& asset, ir::Loc at);
  // A polygonal example (synthesis_command_continuous.cpp): a solid grown in the scope,
  // its parts shapes of the op's symbol (their faces their geometry) or, with none, one
  // generated asset.
  void applyContinuous(const ir::Op& op, const int n[3], State& st, Exec& ex);
  const rt::synthesis::continuous::ExampleSolid& loadSolid(const std::string& name, ir::Loc at);

  Derivation& d_;
  std::map<std::string, rt::synthesis::Example> examples_;
  std::map<std::string, rt::synthesis::continuous::ExampleSolid> solids_;
  int synthesized_ = 0;  // generated assets made so far
};

}  // namespace fgsg::backend
