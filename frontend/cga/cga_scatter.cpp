// The `.cga` dialect's scatter (op_scatter, issue #44):
//
//   scatter(surface|volume|scope, n, uniform|gaussian) { operations }
//                        Scatter("surface", n, "uniform"){ operations }
//   scatter(domain, n, gaussian, center|front|back|left|right|top|bottom, stddev) { ... }
//                        Scatter(domain, n, "gaussian", "left", stddev, "absolute"), a
//                        relative `'0.1` as Scatter(..., 0.1, "relative")
//
// The operations run on each point, a shape of its own (runtime/cga/scatter.h); one that
// creates no shape leaves the point as a leaf of the rule, as a split's part does.
#include "frontend/cga/cga_translator.h"

namespace fgsg::frontend::cga {

namespace {

ExprPtr scatterWordArg(const std::string& word, const SourceRange& at) {
  ExprPtr e = makeExpr(ExprKind::String, at);
  e->text = word;
  return e;
}

}  // namespace

std::optional<Item> Translator::scatter(P::CallOperationContext* op, const Env& env) {
  const auto argCtx = op->expr();
  const SourceRange at = rangeOf(op);
  if (!op->operationBlock()) {
    error("E018", at, "scatter needs the operations its points run: scatter(surface, 20, uniform) { Tree }");
    return std::nullopt;
  }
  if (argCtx.size() != 3 && argCtx.size() != 5) {
    error("E016", rangeOf(op->name),
          "'scatter' takes 3 arguments (domain, nPoints, distribution) or 5 (domain, nPoints, gaussian, mean, "
          "stddev), got " + std::to_string(argCtx.size()));
    return std::nullopt;
  }
  // A selector argument among `words`, or a located E028.
  auto word = [&](size_t k, std::initializer_list<const char*> words, const char* what) -> ExprPtr {
    const std::string w = selectorWord(argCtx[k]);
    std::string list;
    for (const char* allowed : words) {
      if (w == allowed) return scatterWordArg(w, rangeOf(argCtx[k]));
      list += (list.empty() ? "" : ", ") + std::string(allowed);
    }
    error("E028", rangeOf(argCtx[k]),
          std::string("scatter's ") + what + " is " + list + ", not '" + argCtx[k]->getText() + "'");
    return nullptr;
  };
  Item item = command("Scatter", at);
  ExprPtr domain = word(0, {"surface", "volume", "scope"}, "domain");
  ExprPtr count = expr(argCtx[1], env);
  ExprPtr distribution = word(2, {"uniform", "gaussian"}, "distribution");
  if (!domain || !count || !distribution) return std::nullopt;
  const bool gaussian = distribution->text == "gaussian";
  item.args.push_back(std::move(domain));
  item.args.push_back(std::move(count));
  item.args.push_back(std::move(distribution));
  if (argCtx.size() == 5) {
    if (!gaussian) {
      error("E028", rangeOf(argCtx[2]), "scatter's 5-argument form (a mean and a deviation) is gaussian's, not uniform's");
      return std::nullopt;
    }
    ExprPtr mean = word(3, {"center", "front", "back", "left", "right", "top", "bottom"}, "mean");
    if (!mean) return std::nullopt;
    // `'0.1`: times the scope's size along each axis; a plain number: metres.
    P::RelativePrimaryContext* relative = nullptr;
    if (auto* p = dynamic_cast<P::PrimaryExprContext*>(argCtx[4]))
      relative = dynamic_cast<P::RelativePrimaryContext*>(p->primary());
    ExprPtr stddev = relative ? primary(relative->primary(), env) : expr(argCtx[4], env);
    if (!stddev) return std::nullopt;
    item.args.push_back(std::move(mean));
    item.args.push_back(std::move(stddev));
    item.args.push_back(scatterWordArg(relative ? "relative" : "absolute", rangeOf(argCtx[4])));
  }
  Successor part;
  part.range = rangeOf(op->operationBlock());
  operations(op->operationBlock()->operation(), 0, part, env, true);
  item.hasBody = true;
  item.body.push_back(std::move(part));
  return item;
}

}  // namespace fgsg::frontend::cga
