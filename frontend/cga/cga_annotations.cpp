// The `.cga` dialect's annotations: `@StartRule` marks the start rule; the others
// (`@Range(min, max[, step])`, `@Enum(...)`, `@Hidden`, `@Group`, `@Order`, `@Description`,
// `@File`, `@Directory`, `@Color`, `@Angle`, `@Distance`, `@Percent`, `@Handle`) are kept as
// the attr's metadata (ir::Attr::annotations), which inspectors list: `fgsg view`, Python's
// Grammar.attrs, `fgsg ir`. They do not change what is derived.
#include "frontend/cga/cga_translator.h"

namespace fgsg::frontend::cga {

namespace {

const char* const kAnnotations[] = {"Range",   "Enum",  "Hidden", "Group",    "Order",   "Description",
                                    "File",    "Directory", "Color", "Angle", "Distance", "Percent",
                                    "Handle",  "InRange", "Label", "Dual", "Infer", "Location", "Transient"};

// An argument as inspectors read it: a string without its quotes, anything else as written.
std::string argumentText(P::ExprContext* e) {
  if (auto* p = dynamic_cast<P::PrimaryExprContext*>(e))
    if (auto* s = dynamic_cast<P::StringPrimaryContext*>(p->primary())) return stringValue(s->getText());
  return e->getText();
}

}  // namespace

std::vector<AttrAnnotation> Translator::annotations(const std::vector<P::AnnotationContext*>& list, bool& startRule,
                                                    const std::string& declName) {
  std::vector<AttrAnnotation> out;
  for (P::AnnotationContext* a : list) {
    const std::string name = a->name->getText();
    if (name == "StartRule") {
      startRule = true;
      continue;
    }
    bool known = false;
    for (const char* k : kAnnotations) known |= name == k;
    if (!known)
      warning("W802", rangeOf(a), "unknown annotation '@" + name + "' on '" + declName + "' (kept as metadata)");
    AttrAnnotation note;
    note.name = name;
    for (P::AnnotationArgContext* arg : a->annotationArg())
      note.args.push_back({arg->key ? arg->key->getText() : "", argumentText(arg->expr())});
    out.push_back(std::move(note));
  }
  return out;
}

}  // namespace fgsg::frontend::cga
