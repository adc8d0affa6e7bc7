// CityEngine's styles (the `style` keyword): `style Winter` (the same as `style Winter
// extends Default`) or `style Winter extends Other` begins a style; the attrs after it
// redefine those of its base for shapes of that style. A shape's style is chosen with its
// start rule, written as CityEngine's rule packages write it, `Winter$Lot` (fgsg:
// `--start-rule Winter$Lot`); `Lot` alone is `Default$Lot`. The chosen style's attrs
// replace the Default style's values, the nearest style of its chain (itself, its base,
// its base's base ...) winning. Rules, functions and new attrs in a style are not here yet.
#include "frontend/cga/cga_translator.h"

#include "frontend/did_you_mean.h"

namespace fgsg::frontend::cga {

void Translator::styleDecl(P::StyleDeclContext* ctx) {
  const std::string name = ctx->name->getText();
  const SourceRange at = rangeOf(ctx->name);
  if (name == "Default") {
    if (ctx->EXTENDS()) error("E803", rangeOf(ctx), "the Default style extends no other style");
    currentStyle_ = name;
    return;
  }
  if (styles_.count(name)) {
    error("E803", at, "the style '" + name + "' is declared twice");
    currentStyle_ = name;
    return;
  }
  Style s;
  s.range = at;
  s.base = ctx->base ? ctx->base->getText() : "Default";
  if (s.base != "Default" && !styles_.count(s.base)) {
    std::vector<std::string> known{"Default"};
    for (const auto& [n, st] : styles_) known.push_back(n);
    const std::string near = closestName(s.base, known);
    error("E803", rangeOf(ctx->base),
          "the style '" + name + "' extends '" + s.base + "', which is not a style declared before it" +
              (near.empty() ? std::string() : "; did you mean '" + near + "'?"));
    s.base = "Default";
  }
  styles_.emplace(name, std::move(s));
  currentStyle_ = name;
}

// A declaration after `style Name` (not Default): an attr that redefines one of the
// Default style's, kept until the chosen style is known (applyStyle).
void Translator::styleDeclaration(P::AnnotatedContext* ctx) {
  auto* a = ctx->attrDecl();
  if (!a) {
    notSupported(rangeOf(ctx), "a rule, function or const in a style other than Default (a style redefines attrs here)");
    return;
  }
  const std::string name = a->name->getText();
  if (!attrs_.count(name)) {
    notSupported(rangeOf(a->name), "a new attr in a style ('" + name + "' is not an attr of the Default style)");
    return;
  }
  Style& s = styles_[currentStyle_];
  if (s.attrs.count(name)) {
    error("E803", rangeOf(a->name), "the style '" + currentStyle_ + "' declares the attr '" + name + "' twice");
    return;
  }
  currentParams_ = nullptr;
  ExprPtr v = value(a->value(), Env{});  // translated here, so its errors show whichever style runs
  if (v) s.attrs.emplace(name, std::move(v));
}

// `--start-rule Style$Rule`: the style's attrs (and its bases') take the Default style's place.
void Translator::applyStyle() {
  if (chosenStyle_ == "Default") return;
  if (!styles_.count(chosenStyle_)) {
    std::string list = "Default";
    for (const auto& [n, s] : styles_) list += ", " + n;
    error("E803", SourceRange{{1, 1}, {1, 1}},
          "--start-rule " + chosenStyle_ + "$" + startRuleOverride_ + ": this file has no style '" + chosenStyle_ +
              "' (its styles: " + list + ")");
    return;
  }
  std::set<std::string> done;
  for (std::string st = chosenStyle_; st != "Default"; st = styles_[st].base)
    for (auto& [name, expr] : styles_[st].attrs) {
      if (!done.insert(name).second) continue;  // a nearer style redefined it
      for (ValueDecl& v : program_.values)
        if (v.isAttr && v.name == name) v.value = cloneExpr(*expr);
    }
}

}  // namespace fgsg::frontend::cga
