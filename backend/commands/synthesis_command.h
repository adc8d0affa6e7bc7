// Synthesize("example", nx, ny, nz): Merrell's model synthesis (runtime/synthesis/) fills
// the scope with an nx x ny x nz grid of pieces. A piece whose label names a symbol with
// rules becomes a shape of that symbol in its cell, to be derived further; any other
// piece places its asset. Examples are loaded once per derivation.
#pragma once

#include "backend/commands/command_family.h"
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

  Derivation& d_;
  std::map<std::string, rt::synthesis::Example> examples_;
};

}  // namespace fgsg::backend
