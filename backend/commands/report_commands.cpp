#include "backend/commands/report_commands.h"

#include "backend/engine/derivation.h"

namespace fgsg::backend {

// An evaluated argument as its IR type says: a number, a truth value, a string id.
rt::ReportValue ReportCommands::value(const ir::Expr& e, const double* a) const {
  rt::ReportValue v;
  switch (e.type) {
    case ir::Type::Bool:
      v.kind = rt::ReportValue::Kind::Boolean;
      v.number = *a != 0 ? 1 : 0;
      break;
    case ir::Type::Str:  // the module's or a joined one ("roof.area." + kind)
      v.kind = rt::ReportValue::Kind::String;
      v.text = d_.stringText(*a);
      break;
    default: v.number = *a; break;
  }
  return v;
}

// Lots and seeds derived apart open their start shape as they begin; otherwise there is one.
uint32_t ReportCommands::currentStart() const {
  const auto& bounds = d_.output().startBounds;
  return bounds.empty() ? 0 : uint32_t(bounds.size() - 1);
}

void ReportCommands::adopt(std::vector<rt::Report> reports, std::vector<rt::PrintLine> prints, uint32_t start) {
  for (rt::Report& r : reports) reports_.push_back(std::move(r)), reports_.back().start = start;
  for (rt::PrintLine& p : prints) prints_.push_back(std::move(p)), prints_.back().start = start;
}

void ReportCommands::apply(const ir::Op& op, const double* a, uint32_t n, State&, Exec&, Frame&) {
  if (op.kind == ir::OpKind::Report) {
    if (n < 2) return;
    rt::Report r;
    r.start = currentStart();
    r.key = value(op.args[0], a).text;
    r.value = value(op.args[1], a + 1);
    reports_.push_back(std::move(r));
    return;
  }
  rt::PrintLine line;
  line.start = currentStart();
  line.line = op.loc.line;
  line.col = op.loc.col;
  if (n == 3) {  // a vector's components
    line.text = "(";
    for (uint32_t k = 0; k < 3; ++k) line.text += (k ? ", " : "") + rt::reportValueText(value(op.args[k], a + k));
    line.text += ")";
  } else if (n == 1) {
    line.text = rt::reportValueText(value(op.args[0], a));
  }
  prints_.push_back(std::move(line));
}

}  // namespace fgsg::backend
