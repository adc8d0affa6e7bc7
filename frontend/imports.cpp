#include "frontend/imports.h"

#include "frontend/builtins.h"
#include "frontend/cga/cga_parse.h"
#include "frontend/did_you_mean.h"
#include "frontend/imported_functions.h"
#include "frontend/parse.h"
#include "runtime/io/read_input.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>

namespace fgsg::frontend {

namespace fs = std::filesystem;

namespace {

constexpr size_t kMaxModuleBytes = 16u << 20;  // a grammar module, not a data file
constexpr int kMaxImportDepth = 64;
// Rules and declarations all of a grammar's imports may bring in, copies included: about
// a hundred times the whole standard library. Each alias path is a copy of its own (its
// names and attrs are its own), so a module imported twice by each of 25 others in a
// chain is 2^25 copies; past this the import is an error instead of hours of copying.
constexpr uint64_t kMaxImportedItems = 1u << 16;

uint64_t saturatingAdd(uint64_t a, uint64_t b) { return a > UINT64_MAX - b ? UINT64_MAX : a + b; }

// What a module brings into its importer itself: counted against kMaxImportedItems.
uint64_t ownItems(const Program& m) {
  return m.values.size() + m.fields.size() + m.textures.size() + m.tilesets.size() + m.rules.size();
}

std::string withExtension(const std::string& written) {
  return fs::path(written).has_extension() ? written : written + ".fgsg";
}

// Calls `visit` on every item of `s`, those in bodies and brackets too.
template <class S, class F>
void forEachItem(S& s, const F& visit) {
  for (auto& it : s.items) {
    auto walk = [&](auto& self, auto& item) -> void {
      visit(item);
      for (auto& b : item.body) forEachItem(b, visit);
      for (auto& c : item.children) self(self, c);
    };
    walk(walk, it);
  }
}

// A module's names, renamed `alias.X` where it is imported `as alias`.
class Qualifier {
 public:
  Qualifier(Program& m, const std::string& alias) : m_(m), prefix_(alias + ".") {
    for (const auto& v : m.values) values_.insert(v.name);
    for (const auto& f : m.fields) values_.insert(f.name);
    for (const auto& t : m.textures) values_.insert(t.name), textures_.insert(t.name);
    for (const auto& t : m.tilesets) values_.insert(t.name);
    for (const auto& r : m.rules) {
      symbols_.insert(r.predecessor.name);
      // The shape symbols successors write (ones without rules too: pieces, hooks).
      for (const auto& b : r.branches)
        forEachItem(b.successor, [&](const Item& it) {
          if (it.kind == ItemKind::Call && !findCommand(it.name)) symbols_.insert(it.name);
        });
    }
  }

  void run() {
    for (auto& v : m_.values) {
      expr(v.value, nullptr);
      v.name = prefix_ + v.name;
    }
    for (auto& f : m_.fields) {
      f.name = prefix_ + f.name;
      for (auto& a : f.args) expr(a, nullptr);
      for (auto& item : f.design)
        for (auto& w : item.words) expr(w.value, nullptr);
    }
    for (auto& t : m_.textures) t.name = prefix_ + t.name;
    for (auto& t : m_.tilesets) {
      t.name = prefix_ + t.name;
      for (auto& item : t.items)
        for (auto& v : item.values) expr(v, nullptr);
    }
    for (auto& r : m_.rules) rule(r);
    for (auto& f : m_.functions) expr(f.body, nullptr);  // its parameters are "#k": no clash
  }

 private:
  void rule(Rule& r) {
    std::set<std::string> params;
    auto pattern = [&](ModulePattern& p) {
      for (const auto& d : p.params) params.insert(d.name);
      if (p.name != "[" && p.name != "]" && !findCommand(p.name)) p.name = prefix_ + p.name;
    };
    for (auto& p : r.leftContext) pattern(p);
    pattern(r.predecessor);
    for (auto& p : r.rightContext) pattern(p);
    expr(r.guard, &params);
    for (auto& b : r.branches) {
      expr(b.probability, &params);
      successor(b.successor, params);
    }
  }

  void successor(Successor& s, const std::set<std::string>& params) {
    expr(s.size, &params);
    for (auto& item : s.items) this->item(item, params);
  }

  void item(Item& it, const std::set<std::string>& params) {
    if (it.kind == ItemKind::Call && !findCommand(it.name)) it.name = prefix_ + it.name;
    for (auto& a : it.args) expr(a, &params);
    for (auto& b : it.body) successor(b, params);
    for (auto& c : it.children) item(c, params);
  }

  void expr(ExprPtr& e, const std::set<std::string>* params) {
    if (!e) return;
    const bool shadowed = params && params->count(e->text);
    if (e->kind == ExprKind::Ident && values_.count(e->text) && !shadowed) e->text = prefix_ + e->text;
    if (e->kind == ExprKind::Member) {
      if (values_.count(e->object) && !(params && params->count(e->object))) e->object = prefix_ + e->object;
      if (e->object == "context" && textures_.count(e->text)) e->text = prefix_ + e->text;
      // Feature.label("window"): the label is a piece's symbol, renamed with it.
      if (e->object == "Feature" && e->text == "label" && e->args.size() == 1 && e->args[0] &&
          e->args[0]->kind == ExprKind::String && symbols_.count(e->args[0]->text))
        e->args[0]->text = prefix_ + e->args[0]->text;
    }
    for (auto& a : e->args) expr(a, params);
  }

  Program& m_;
  std::string prefix_;
  std::set<std::string> values_, textures_, symbols_;
};

// A module's asset, image and field files are its own: names found beside the module (or
// in its assets/ folder) become absolute paths, so the importer's folder need not hold them.
class FileAnchor {
 public:
  FileAnchor(const fs::path& moduleFile) : dirs_{moduleFile.parent_path(), moduleFile.parent_path() / "assets"} {}

  void run(Program& m) {
    for (auto& t : m.textures) anchor(t.path);
    for (auto& f : m.fields) anchor(f.path);
    for (auto& r : m.rules)
      for (auto& b : r.branches)
        forEachItem(b.successor, [&](Item& it) {
          const bool namesFile = it.name == "I" || it.name == "IC" || it.name == "IM" || it.name == "Texture" ||
                                 it.name == "Synthesize";
          if (namesFile && !it.args.empty() && it.args[0] && it.args[0]->kind == ExprKind::String)
            anchor(it.args[0]->text);
          // Material("normalmap" or "colormap", "image.png")
          if (it.name == "Material" && it.args.size() == 2 && it.args[1] && it.args[1]->kind == ExprKind::String)
            anchor(it.args[1]->text);
        });
  }

 private:
  void anchor(std::string& name) {
    if (name.empty() || !fs::path(name).has_extension() || fs::path(name).is_absolute()) return;
    std::error_code ec;
    for (const fs::path& dir : dirs_)
      if (fs::is_regular_file(dir / name, ec)) {
        name = fs::absolute(dir / name, ec).lexically_normal().string();
        return;
      }
  }
  std::vector<fs::path> dirs_;
};

// What a program is assembled from, for clash messages: which import brought a name in.
struct Origin {
  std::string what;  // "'std/cga/facade' (imported at line 3)" or "this file"
  SourceRange at;
};

class Importer {
 public:
  Importer(SourceFile& file, Diagnostics& diags, const ImportSearch& search)
      : file_(file), diags_(diags), search_(search) {}

  bool run(Program& program) {
    const int before = diags_.errorCount();
    std::error_code ec;
    stack_.push_back(fs::weakly_canonical(file_.name, ec).string());  // the grammar itself
    sites_.push_back({});
    importAll(program, "", 0);
    checkChosenStyle(program);
    return diags_.errorCount() == before;
  }

 private:
  // Where `written`, imported by the file `importer` ("" the grammar), is: its key.
  std::string locate(const std::string& written, const std::string& importer, std::vector<std::string>& tried) const {
    const std::string name = withExtension(written);
    std::vector<fs::path> candidates;
    if (name.rfind("std/", 0) == 0) {
      if (!search_.stdlib.empty()) candidates.push_back(fs::path(search_.stdlib) / name.substr(4));
    } else if (fs::path(name).is_absolute()) {
      candidates.push_back(name);
    } else {
      const fs::path from = fs::path(importer.empty() ? file_.name : importer).parent_path();
      candidates.push_back(from / name);
      for (const std::string& dir : search_.path) candidates.push_back(fs::path(dir) / name);
      if (!search_.stdlib.empty()) candidates.push_back(fs::path(search_.stdlib) / name);
    }
    std::error_code ec;
    for (const fs::path& c : candidates) {
      tried.push_back(c.string());
      if (fs::is_regular_file(c, ec)) return fs::weakly_canonical(c, ec).string();
    }
    return "";
  }

  // The module an import names, from the grammar's text (a compiled library) or read now.
  // Quietly (`report` false): nullptr for one that cannot be found or read, reported when
  // it is imported.
  const SourceFile::Module* module(const ImportDecl& d, const std::string& importer, bool report = true) {
    for (const auto& m : file_.modules)
      if (m.importer == importer && m.written == d.path) return &m;
    std::vector<std::string> tried;
    const std::string key = locate(d.path, importer, tried);
    if (key.empty() && !report) return nullptr;
    if (key.empty()) {
      std::string list;
      for (const auto& t : tried) list += (list.empty() ? "" : ", ") + t;
      diags_.error("E060", d.pathRange, "cannot find the module '" + d.path + "' (looked for " + list +
                                            "; FGSG_PATH adds folders, \"std/...\" names the standard library)");
      return nullptr;
    }
    std::string text, error;  // a grammar, not a data file: a cap of its own
    if (!rt::io::readInputFile(key, "a grammar module", text, error, kMaxModuleBytes)) {
      if (report) diags_.error("E060", d.pathRange, "cannot read the module '" + d.path + "': " + error);
      return nullptr;
    }
    std::string shown = d.path.rfind("std/", 0) == 0 ? withExtension(d.path) : key;
    file_.addModule({key, shown, importer, d.path, std::move(text), 0});
    return &file_.modules.back();
  }

  // A module with everything it imports, as importing it once would copy it: its rules
  // and declarations, and how many copies of each module that is (itself once).
  struct Extent {
    uint64_t items = 0;
    std::map<std::string, uint64_t> copies;  // module key -> copies
  };

  // Found once per module, before any copy is made: each module is parsed once here, its
  // imports' extents added up (a cycle or a missing module counts nothing: importing it
  // reports it).
  const Extent& extent(const SourceFile::Module& m) {
    if (const auto known = extents_.find(m.key); known != extents_.end()) return known->second;
    Extent e;
    e.copies[m.key] = 1;
    Program mod;
    Diagnostics quiet(&file_);  // its errors are reported when it is imported
    const std::string key = m.key;  // `m` may move as modules are added
    if (parseText(m.name, m.text, mod, quiet)) {
      e.items = ownItems(mod);
      measuring_.insert(key);
      for (const ImportDecl& d : mod.imports) {
        const SourceFile::Module* child = module(d, key, false);
        if (!child || measuring_.count(child->key)) continue;
        const Extent& c = extent(*child);
        e.items = saturatingAdd(e.items, c.items);
        for (const auto& [k, n] : c.copies) e.copies[k] = saturatingAdd(e.copies[k], n);
      }
      measuring_.erase(key);
    }
    return extents_[key] = std::move(e);
  }

  // E065: importing `m` at `d` would copy more than kMaxImportedItems rules and
  // declarations into the grammar; says which module is copied how often.
  void tooLarge(const ImportDecl& d, const Extent& e) {
    auto number = [](uint64_t n) { return n == UINT64_MAX ? std::string("more than 10^19") : std::to_string(n); };
    std::string worst;
    uint64_t most = 1;
    for (const auto& [k, n] : e.copies)
      if (n > most) most = n, worst = fs::path(k).filename().string();
    std::string why = "'" + d.path + "' with all it imports is " + number(e.items) + " rules and declarations";
    if (imported_ > 0) why += ", after " + std::to_string(imported_) + " imported before";
    diags_.error("E065", d.pathRange,
                 "importing " + why + ": more than the " + std::to_string(kMaxImportedItems) +
                     " a grammar may import" +
                     (most > 1 ? "; '" + worst + "' is copied " + number(most) +
                                     " times, once for each chain of imports that reaches it (a module "
                                     "imported under two names is two copies, with all it imports): "
                                     "import it once, and pass what differs as parameters"
                               : std::string()));
  }

  // Merges every module `program` (the file `key`) imports into it.
  void importAll(Program& program, const std::string& key, int depth) {
    std::vector<ImportDecl> imports = std::move(program.imports);
    program.imports.clear();
    std::map<std::string, Origin> declared;  // name -> where it came from, for clashes
    auto own = [&](const std::string& name, SourceRange at) { declared.emplace(name, Origin{"this file", at}); };
    for (const auto& v : program.values) own(v.name, v.range);
    for (const auto& f : program.fields) own(f.name, f.range);
    for (const auto& t : program.textures) own(t.name, t.range);
    for (const auto& t : program.tilesets) own(t.name, t.range);
    std::map<std::string, Origin> ruled;  // symbol -> the file that gives it rules
    for (const auto& r : program.rules) ruled.emplace(r.predecessor.name, Origin{"this file", r.range});

    for (ImportDecl& d : imports) {
      // `Scope.sx` and the other queries must stay queries: `alias.X` would join them.
      static const std::set<std::string> kQueryObjects = {"Scope", "Shape", "Geometry", "Feature", "Lot", "context"};
      if (kQueryObjects.count(d.alias) || declared.count(d.alias)) {
        diags_.error("E062", d.range, "'" + d.alias + "' cannot name a module here: it is " +
                                          (kQueryObjects.count(d.alias) ? "a query (" + d.alias + ".X)" : "declared in this file") +
                                          "; import it `as` another name");
        continue;
      }
      const SourceFile::Module* m = module(d, key);
      if (!m) continue;
      const std::string mKey = m->key;
      if (const auto on = std::find(stack_.begin(), stack_.end(), mKey); on != stack_.end()) {
        std::string chain;
        for (auto k = on; k != stack_.end(); ++k) chain += fs::path(*k).filename().string() + " imports ";
        diags_.error("E061", d.pathRange, "import cycle: " + chain + fs::path(mKey).filename().string() +
                                              " again; a module cannot import itself, even through others");
        const size_t next = size_t(on - stack_.begin()) + 1;  // the import the cycle went out by
        if (next < sites_.size()) diags_.note(sites_[next], "the cycle leaves " + fs::path(mKey).filename().string() + " here");
        continue;
      }
      if (depth >= kMaxImportDepth) {
        diags_.error("E061", d.pathRange, "imports nest deeper than " + std::to_string(kMaxImportDepth));
        continue;
      }
      if (const Extent& e = extent(*m); saturatingAdd(imported_, e.items) > kMaxImportedItems) {
        tooLarge(d, e);
        continue;
      }
      m = module(d, key);  // extent() may have added modules: `m` may have moved
      Program mod;
      // Blank lines before its text put its tokens on its own lines of the whole.
      const std::string text = std::string(size_t(m->firstLine - 1), '\n') + m->text;
      const std::string moduleName = m->name;
      // A `.cga` module is read in the importer's style (CityEngine's styles across imports).
      const std::string style = moduleStyle(d, program.cgaStyle);
      const bool parsed = !style.empty() && isCgaSource(moduleName, text)
                              ? parseCgaText(moduleName, text, mod, diags_, style + "$", true)
                              : parseText(moduleName, text, mod, diags_);
      if (!parsed) continue;
      imported_ += ownItems(mod);
      stack_.push_back(mKey);
      sites_.push_back(d.pathRange);
      importAll(mod, mKey, depth + 1);
      stack_.pop_back();
      sites_.pop_back();
      offerStyles(d, mod, program);
      dropProgramWide(mod);
      FileAnchor(mKey).run(mod);
      if (!d.alias.empty()) Qualifier(mod, d.alias).run();
      inlineImportedFunctions(program, d.alias, mod, d.path, diags_);
      for (auto& r : mod.rules) r.imported = true;
      applySettings(d, mod);
      propagateAttrs(d, mod, program);
      const Origin from{"'" + d.path + "' (imported at line " + std::to_string(file_.locate(d.range.begin.line).second) + ")",
                        d.range};
      merge(mod, program, declared, ruled, from);
    }
    if (!imports.empty()) pickImportedOverloads(program);
  }

  // `F.Door(1, 2, 3)` where F's .cga file has rules `Door` and `Door(w, h, d)`: the importer
  // could not see F's overloads, which are the symbols `F.Door` (the fewest parameters) and
  // `F.Door$/3` (cga::Translator::overloadSymbol). The call takes the one with its number
  // of arguments; a number none has is an error that lists theirs.
  void pickImportedOverloads(Program& program) {
    std::map<std::string, std::set<size_t>> overloads;  // `F.Door` -> 0, 3
    std::map<std::string, size_t> arity;
    for (const auto& r : program.rules) {
      const std::string& name = r.predecessor.name;
      arity.emplace(name, r.predecessor.params.size());
      const size_t mark = name.rfind("$/");
      const bool overload = mark != std::string::npos && mark + 2 < name.size() &&
                            name.find_first_not_of("0123456789", mark + 2) == std::string::npos;
      overloads[overload ? name.substr(0, mark) : name].insert(r.predecessor.params.size());
    }
    for (auto& r : program.rules) {
      if (r.imported) continue;
      for (auto& b : r.branches)
        forEachItem(b.successor, [&](Item& it) {
          if (it.kind != ItemKind::Call || it.name.find('.') == std::string::npos) return;
          const auto own = arity.find(it.name);
          if (own == arity.end() || own->second == it.args.size()) return;
          const auto overload = arity.find(it.name + "$/" + std::to_string(it.args.size()));
          if (overload != arity.end()) {
            it.name = overload->first;
            return;
          }
          const std::set<size_t>& counts = overloads[it.name];
          if (counts.size() < 2) return;  // one rule: sema's count check
          std::string list;
          size_t k = 0;
          for (size_t n : counts) list += (k++ == 0 ? "" : k == counts.size() ? " or " : ", ") + std::to_string(n);
          diags_.error("E019", it.range, "'" + symbolDisplayName(it.name) + "' takes " + list + " parameters, got " +
                                             std::to_string(it.args.size()));
        });
    }
  }

  // The style a `.cga` module is read in ("": Default): the importer's, unless the import's
  // styles list leaves it out; then the list's first (CityEngine: `import m (Wide) : ...`
  // gives this file m's Wide in place of m's Default).
  static std::string moduleStyle(const ImportDecl& d, const std::string& importerStyle) {
    if (d.styles.empty()) return importerStyle;
    const std::string chosen = importerStyle.empty() ? "Default" : importerStyle;
    const std::string style = std::find(d.styles.begin(), d.styles.end(), chosen) != d.styles.end() ? chosen : d.styles[0];
    return style == "Default" ? "" : style;
  }

  // The styles an import brings to its importer: all of the module's, or those its list
  // names, each of which the module must have.
  void offerStyles(const ImportDecl& d, const Program& mod, Program& importer) {
    std::vector<std::string> has = mod.cgaStyles;
    if (has.empty()) has.push_back("Default");  // an fgsg module: its one style
    for (size_t i = 0; i < d.styles.size(); ++i) {
      if (std::find(has.begin(), has.end(), d.styles[i]) != has.end()) continue;
      std::string list;
      for (const std::string& n : has) list += (list.empty() ? "" : ", ") + n;
      const std::string near = closestName(d.styles[i], has);
      diags_.error("E803", d.styleRanges[i],
                   "the module '" + d.path + "' has no style '" + d.styles[i] + "' (its styles: " + list + ")" +
                       (near.empty() ? std::string() : "; did you mean '" + near + "'?"));
    }
    for (const std::string& st : d.styles.empty() ? has : d.styles)
      if (std::find(has.begin(), has.end(), st) != has.end() &&
          std::find(importer.cgaStyles.begin(), importer.cgaStyles.end(), st) == importer.cgaStyles.end())
        importer.cgaStyles.push_back(st);
  }

  // `--start-rule Style$Rule` on a `.cga` grammar whose own styles lack Style: one of its
  // imports must bring it (frontend/cga/cga_styles.cpp leaves that to here).
  void checkChosenStyle(const Program& program) {
    const std::string& style = program.cgaStyle;
    if (style.empty() || std::find(program.cgaStyles.begin(), program.cgaStyles.end(), style) != program.cgaStyles.end())
      return;
    std::string list;
    for (const std::string& n : program.cgaStyles) list += (list.empty() ? "" : ", ") + n;
    const std::string near = closestName(style, program.cgaStyles);
    diags_.error("E803", SourceRange{{1, 1}, {1, 1}},
                 "--start-rule " + style + "$...: neither this file nor its imports have a style '" + style +
                     "' (their styles: " + list + ")" + (near.empty() ? std::string() : "; did you mean '" + near + "'?"));
  }

  // A module's start and what belongs to a whole program are the importer's.
  static void dropProgramWide(Program& m) {
    m.axioms.clear();
    m.derives.clear();
    m.surfaces.clear();
    m.turtles.clear();
    m.ignores.clear();
    m.collisions.clear();
    std::vector<Rule> kept;
    for (auto& r : m.rules)
      if (r.predecessor.name != "Axiom" && r.predecessor.name != "axiom" && r.predecessor.name != "start" &&
          r.predecessor.name != "Start")
        kept.push_back(std::move(r));
    m.rules = std::move(kept);
  }

  // `import "m" as m (floor_height = 3.5)`: the module's attr takes the importer's value.
  void applySettings(ImportDecl& d, Program& mod) {
    for (size_t i = 0; i < d.settings.size(); ++i) {
      const std::string name = (d.alias.empty() ? "" : d.alias + ".") + d.settings[i].first;
      bool found = false;
      for (auto& v : mod.values)
        if (v.name == name && v.isAttr) {
          v.value = std::move(d.settings[i].second);
          v.fromImporter = true;
          found = true;
        }
      if (!found)
        diags_.error("E062", d.settingRanges[i], "the module '" + d.path + "' has no attr '" + d.settings[i].first + "'");
    }
  }

  // CityEngine's import (a `.cga` importer): each of the importer's own attrs gives its
  // value to the module's attr of the same name, unless the import's list keeps that one
  // (`(a, b)`, or `()` all) or the importer sets it (`(a = ...)`, `m.a = ...`).
  void propagateAttrs(const ImportDecl& d, Program& mod, const Program& importer) {
    const std::string prefix = d.alias.empty() ? "" : d.alias + ".";
    std::set<std::string> kept;
    for (size_t i = 0; i < d.protectedAttrs.size(); ++i) {
      bool found = false;
      for (const ValueDecl& v : mod.values) found = found || (v.isAttr && v.name == prefix + d.protectedAttrs[i]);
      if (!found)
        diags_.error("E062", d.protectedRanges[i], "the module '" + d.path + "' has no attr '" + d.protectedAttrs[i] + "'");
      kept.insert(d.protectedAttrs[i]);
    }
    if (!d.propagateAttrs || d.protectAll || d.alias.empty()) return;
    std::set<std::string> own;  // the importer's own attrs (those of its imports have a '.')
    for (const ValueDecl& v : importer.values)
      if (v.isAttr && v.name.find('.') == std::string::npos) own.insert(v.name);
    for (ValueDecl& v : mod.values) {
      if (!v.isAttr || v.fromImporter || v.name.compare(0, prefix.size(), prefix) != 0) continue;
      const std::string name = v.name.substr(prefix.size());
      if (!own.count(name) || kept.count(name)) continue;
      ExprPtr e = std::make_unique<Expr>();
      e->kind = ExprKind::Ident;
      e->range = d.range;
      e->text = name;
      v.value = std::move(e);
      v.fromImporter = true;
    }
  }

  void merge(Program& mod, Program& into, std::map<std::string, Origin>& declared, std::map<std::string, Origin>& ruled,
             const Origin& from) {
    auto claim = [&](const std::string& name, SourceRange) {
      const auto [it, fresh] = declared.emplace(name, Origin{from.what, from.at});
      if (fresh) return true;
      clash(name, it->second, from);
      return false;
    };
    for (auto& v : mod.values)
      if (claim(v.name, v.range)) into.values.push_back(std::move(v));
    for (auto& f : mod.fields)
      if (claim(f.name, f.range)) into.fields.push_back(std::move(f));
    for (auto& t : mod.textures)
      if (claim(t.name, t.range)) into.textures.push_back(std::move(t));
    for (auto& t : mod.tilesets)
      if (claim(t.name, t.range)) into.tilesets.push_back(std::move(t));
    std::set<std::string> mine;
    for (auto& r : mod.rules) {
      const std::string& name = r.predecessor.name;
      if (!mine.count(name)) {
        const auto [it, fresh] = ruled.emplace(name, from);
        if (!fresh) {
          clash(name, it->second, from);
          continue;
        }
        mine.insert(name);
      }
      into.rules.push_back(std::move(r));
    }
  }

  // Both sites: the later import (or declaration) as the error, the first as a note.
  void clash(const std::string& name, const Origin& first, const Origin& second) {
    diags_.error("E063", second.at,
                 "'" + name + "' comes from both " + second.what + " and " + first.what +
                     "; import one of them `as` a name (its names are then written name." + name + ")");
    diags_.note(first.at, "'" + name + "' first comes from here");
  }

  SourceFile& file_;
  Diagnostics& diags_;
  const ImportSearch& search_;
  std::vector<std::string> stack_;  // the modules being imported, outermost first
  std::vector<SourceRange> sites_;  // the import that brought each in (the grammar: none)
  std::map<std::string, Extent> extents_;  // by module key
  std::set<std::string> measuring_;        // modules whose extent is being found (cycles)
  uint64_t imported_ = 0;                  // rules and declarations imported so far
};

}  // namespace

ImportSearch defaultImportSearch() {
  ImportSearch s;
  if (const char* path = std::getenv("FGSG_PATH"); path && *path) {
    std::string dir;
    for (const char* c = path;; ++c) {
      if (*c == ':' || *c == '\0') {
        if (!dir.empty()) s.path.push_back(dir);
        dir.clear();
        if (*c == '\0') break;
      } else {
        dir += *c;
      }
    }
  }
  std::error_code ec;
  // An installed fgsg finds it beside itself, wherever the prefix was moved to.
  const fs::path besideExe = fs::read_symlink("/proc/self/exe", ec).parent_path().parent_path() / "share/fgsg/stdlib";
  if (const char* lib = std::getenv("FGSG_STDLIB"); lib && *lib) s.stdlib = lib;
  else if (!ec && fs::is_directory(besideExe, ec)) s.stdlib = besideExe.string();
#ifdef FGSG_INSTALLED_STDLIB
  else if (fs::is_directory(FGSG_INSTALLED_STDLIB, ec)) s.stdlib = FGSG_INSTALLED_STDLIB;
#endif
#ifdef FGSG_SOURCE_STDLIB
  else if (fs::is_directory(FGSG_SOURCE_STDLIB, ec)) s.stdlib = FGSG_SOURCE_STDLIB;
#endif
  return s;
}

bool resolveImports(SourceFile& file, Program& program, Diagnostics& diags, const ImportSearch& search) {
  if (program.imports.empty()) return true;
  return Importer(file, diags, search).run(program);
}

}  // namespace fgsg::frontend
