// CGA's report(key, value) and print(value) (Report, Print): what the grammar tells about
// the model while it is derived. Reports are collected per start shape — the --lots lot,
// the seed derived apart or the one axiom whose derivation runs them — in the order they
// ran, which is the same for every engine; printed lines are kept with the place of their
// Print, for the caller to show (fgsg run writes them to stderr). Neither changes the shape.
#pragma once

#include "backend/commands/command_family.h"
#include "runtime/reports.h"

#include <vector>

namespace fgsg::backend {

class Derivation;

class ReportCommands final : public CommandFamily {
 public:
  explicit ReportCommands(Derivation& derivation) : d_(derivation) {}

  std::vector<ir::OpKind> kinds() const override { return {ir::OpKind::Report, ir::OpKind::Print}; }
  void apply(const ir::Op& op, const double* a, uint32_t n, State& st, Exec& ex, Frame& f) override;

  // What ran so far, taken out (the derivation's result; a seed plant's, to be merged).
  std::vector<rt::Report> takeReports() { return std::move(reports_); }
  std::vector<rt::PrintLine> takePrints() { return std::move(prints_); }
  // Appends a seed plant's, as start shape `start`.
  void adopt(std::vector<rt::Report> reports, std::vector<rt::PrintLine> prints, uint32_t start);

 private:
  rt::ReportValue value(const ir::Expr& e, const double* a) const;
  uint32_t currentStart() const;

  Derivation& d_;
  std::vector<rt::Report> reports_;
  std::vector<rt::PrintLine> prints_;
};

}  // namespace fgsg::backend
