// CityEngine's styles (the `style` keyword): `style Winter` (the same as `style Winter
// extends Default`) or `style Winter extends Other` begins a style; every declaration after
// it, up to the next `style`, belongs to that style. A style redefines its base's rules,
// attrs, consts and functions and may add its own; what it does not redefine it inherits.
// A shape's style is chosen with its start rule, written as CityEngine's rule packages
// write it, `Winter$Lot` (fgsg: `--start-rule Winter$Lot`); `Lot` alone is `Default$Lot`.
// One run derives in one style, so the choice is made here: of each name, the declarations
// of the nearest style of the chosen style's chain (itself, its base, its base's base ...
// Default) are translated, the others skipped (readStyles, keeps).
#include "frontend/cga/cga_translator.h"

#include "frontend/did_you_mean.h"

#include <algorithm>

namespace fgsg::frontend::cga {

namespace {

// What a declaration defines, for overriding: rules and values (attrs, consts, functions)
// have names of their own. A rule is keyed by its name and number of parameters: its
// overloads are different rules, so a style that redefines Door(h) keeps Default's Door.
std::string styleOverrideKey(P::AnnotatedContext* ctx) {
  if (auto* r = ctx->ruleDecl())
    return "rule " + r->name->getText() + "/" + std::to_string(r->params() ? r->params()->ID().size() : 0);
  if (auto* a = ctx->attrDecl()) return "value " + a->name->getText();
  if (auto* c = ctx->constDecl()) return "value " + c->name->getText();
  return "value " + ctx->functionDecl()->name->getText();
}

}  // namespace

// Every style of the file (a base may be declared after the style that extends it), the
// errors of their declarations, the chosen style's chain and which declaration wins each
// name. Run before collect(): everything after reads only the declarations that are kept.
void Translator::readStyles(P::CgaFileContext* file) {
  std::string current = "Default";
  std::vector<std::string> order;  // the styles but Default, as declared
  for (P::DeclarationContext* d : file->declaration()) {
    if (auto* st = d->styleDecl()) {
      current = st->name->getText();
      const SourceRange at = rangeOf(st->name);
      if (current == "Default") {
        if (st->EXTENDS()) error("E803", rangeOf(st), "the Default style extends no other style");
        continue;
      }
      if (const auto first = styles_.find(current); first != styles_.end()) {
        error("E803", at, "the style '" + current + "' is declared twice");
        diags_->note(first->second.range, "'" + current + "' is first declared here");
        continue;
      }
      Style s;
      s.range = at;
      s.base = st->base ? st->base->getText() : "Default";
      if (st->base) s.baseRange = rangeOf(st->base);
      styles_.emplace(current, std::move(s));
      order.push_back(current);
    } else if (auto* a = d->annotated()) {
      owner_[a] = current;
    }
  }
  std::vector<std::string> known{"Default"};
  known.insert(known.end(), order.begin(), order.end());
  for (const std::string& name : order) {
    Style& s = styles_[name];
    if (s.base == "Default" || styles_.count(s.base)) continue;
    const std::string near = closestName(s.base, known);
    error("E803", s.baseRange,
          "the style '" + name + "' extends '" + s.base + "', which is not a style of this file" +
              (near.empty() ? std::string() : "; did you mean '" + near + "'?"));
    s.base = "Default";
  }
  // A cycle is reported once, at the first of its styles in the file, and broken there.
  for (const std::string& name : order) {
    std::vector<std::string> path{name};
    for (std::string st = styles_[name].base; st != "Default"; st = styles_[st].base) {
      if (st == name) {
        std::string chain;
        for (const std::string& p : path) chain += p + " extends ";
        error("E803", styles_[name].baseRange, "style cycle: " + chain + name + "; a style's bases end at Default");
        styles_[name].base = "Default";
        break;
      }
      if (std::find(path.begin(), path.end(), st) != path.end()) break;  // a cycle not through `name`
      path.push_back(st);
    }
  }

  // The chosen style's chain, nearest first. A style the file lacks may come from an
  // import (checked once the imports are in, frontend/imports.cpp), or this file is an
  // import read in its importer's style: its own declarations are then the Default style's.
  program_.cgaStyle = chosenStyle_ == "Default" ? "" : chosenStyle_;
  program_.cgaStyles = known;
  chain_.clear();
  if (chosenStyle_ != "Default" && !styles_.count(chosenStyle_) && !styleFromImporter_ && !file->declaration().empty()) {
    bool imports = false;
    for (P::DeclarationContext* d : file->declaration()) imports = imports || d->importDecl();
    if (!imports) {
      std::string list;
      for (const std::string& n : known) list += (list.empty() ? "" : ", ") + n;
      const std::string near = closestName(chosenStyle_, known);
      error("E803", SourceRange{{1, 1}, {1, 1}},
            "--start-rule " + chosenStyle_ + "$" + startRuleOverride_ + ": this file has no style '" + chosenStyle_ +
                "' (its styles: " + list + ")" + (near.empty() ? std::string() : "; did you mean '" + near + "'?"));
    }
  }
  if (styles_.count(chosenStyle_))
    for (std::string st = chosenStyle_; st != "Default"; st = styles_[st].base) chain_.push_back(st);
  chain_.push_back("Default");

  // Of each name, the declarations of the nearest style that has one win.
  std::map<std::string, size_t> nearest;  // key -> rank in chain_
  for (const auto& [ctx, style] : owner_) {
    const size_t rank = size_t(std::find(chain_.begin(), chain_.end(), style) - chain_.begin());
    if (rank == chain_.size()) continue;
    const std::string key = styleOverrideKey(ctx);
    if (const auto it = nearest.find(key); it == nearest.end() || rank < it->second) nearest[key] = rank;
  }
  for (const auto& [ctx, style] : owner_) {
    const size_t rank = size_t(std::find(chain_.begin(), chain_.end(), style) - chain_.begin());
    if (rank == chain_.size() || nearest[styleOverrideKey(ctx)] != rank) continue;
    // An attr of the Default style a nearer style redefines keeps its place (and its
    // annotations, --set and lot properties): only its value is the nearer style's.
    if (auto* a = ctx->attrDecl(); a && style != "Default") {
      bool inDefault = false;
      for (const auto& [other, otherStyle] : owner_)
        inDefault = inDefault || (otherStyle == "Default" && other->attrDecl() &&
                                  other->attrDecl()->name->getText() == a->name->getText());
      if (inDefault) {
        attrValueFromStyle_[a->name->getText()] = a;
        continue;
      }
    }
    kept_.insert(ctx);
  }
  // The Default style's attrs stay declared where a nearer style gives their value.
  for (const auto& [ctx, style] : owner_)
    if (style == "Default" && ctx->attrDecl() && attrValueFromStyle_.count(ctx->attrDecl()->name->getText()))
      kept_.insert(ctx);
}

bool Translator::keeps(P::AnnotatedContext* ctx) const { return kept_.count(ctx) != 0; }

// The value an attr of the Default style has in the chosen style (the nearest redefinition).
P::ValueContext* Translator::styledAttrValue(P::AttrDeclContext* ctx) const {
  const auto it = attrValueFromStyle_.find(ctx->name->getText());
  return it == attrValueFromStyle_.end() ? ctx->value() : it->second->value();
}

}  // namespace fgsg::frontend::cga
