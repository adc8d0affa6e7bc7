// CGA's comp.sel: the name of the selector that chose a component, as a `.cga` rule
// writes it, from the label of fgsg's Comp part (runtime/cga/components.cpp's
// componentSelectorMask): `worldUp` is "world.up", `objectFront` "object.front",
// `streetSide` "street.side", an index selector `#2` "2"; a merged part's trailing `=`
// is dropped; other labels ("front", "side", "eave" ...) are their own names. Free of the
// geometry headers: the lowering interns these names so that comp.sel is a grammar string.
#pragma once

#include <cctype>
#include <string>

namespace fgsg::rt::cga {

inline std::string compSelectorName(const std::string& label) {
  std::string name = label;
  if (!name.empty() && name.back() == '=') name.pop_back();
  if (name.size() > 1 && name[0] == '#') return name.substr(1);
  for (const char* frame : {"world", "object", "street"}) {
    const std::string prefix = frame;
    if (name.size() > prefix.size() && name.compare(0, prefix.size(), prefix) == 0 &&
        std::isupper(static_cast<unsigned char>(name[prefix.size()])))
      return prefix + "." + char(std::tolower(static_cast<unsigned char>(name[prefix.size()]))) +
             name.substr(prefix.size() + 1);
  }
  return name;
}

// Whether a Comp part's label is merged (`.cga`'s `all = A`, fgsg's `all=: A`): all the
// components it takes become one shape.
inline bool compLabelMerged(const std::string& label) { return !label.empty() && label.back() == '='; }

}  // namespace fgsg::rt::cga
