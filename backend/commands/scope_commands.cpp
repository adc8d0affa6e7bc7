#include "backend/commands/scope_commands.h"

#include "frontend/color_literal.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace fgsg::backend {

std::vector<ir::OpKind> ScopeCommands::kinds() const {
  using K = ir::OpKind;
  return {K::Translate, K::Rotate, K::RotateNormal, K::Scale, K::Push, K::Pop, K::Center, K::Color};
}

void ScopeCommands::command(State& st, const ir::Op& op, const double* a) {
  switch (op.kind) {
    case ir::OpKind::Translate: translate(st.scope, a[0], a[1], a[2]); break;
    case ir::OpKind::Rotate:
      if (op.index < 3) {
        turn(st.scope, static_cast<int>(op.index), a[0]);
      } else {
        turn(st.scope, 0, a[0]);
        turn(st.scope, 1, a[1]);
        turn(st.scope, 2, a[2]);
      }
      break;
    case ir::OpKind::RotateNormal:
      if (surface_)
        surface_->rotateAboutNormal(st.scope, a[0]);
      else
        rt::rotateAboutNormal(st.scope, kPlaneNormal, a[0]);
      break;
    case ir::OpKind::Scale:
      for (int k = 0; k < 3; ++k)
        st.scope.S[k] = op.sizes[k].kind == ir::Size::Relative ? a[k] * st.scope.S[k] : a[k];
      break;
    case ir::OpKind::Push: push(st); break;
    case ir::OpKind::Pop:
      if (stack_.size() <= st.stackBase)
        throw DeriveError{op.loc, "R007", "']' without a matching '[' in this string"};
      if (string_) string_->addClose(stack_.back().bracket);
      st.scope = stack_.back().scope;
      st.geom = stack_.back().geom;
      st.width = stack_.back().width;
      st.tropism = stack_.back().tropism;
      st.cylinder = stack_.back().cylinder;
      st.line = stack_.back().line;
      stack_.pop_back();
      break;
    case ir::OpKind::Center: center(st, op); break;
    case ir::OpKind::Color:
      if (op.args.size() == 1 && op.args[0].type == ir::Type::Str) {  // color(s): "#rrggbb" or "#rgb"
        const double id = a[0];
        if (!strings_.holds(id))
          throw DeriveError{op.loc, "R027",
                            "Color: the colour string is not one this grammar holds (a value given by --set or a "
                            "lot property that the grammar does not write): write it as \"#rrggbb\" in the grammar"};
        std::string text = strings_.text(id);
        if (text.size() == 4 && text[0] == '#') text = std::string("#") + text[1] + text[1] + text[2] + text[2] + text[3] + text[3];
        std::array<double, 3> rgb{};
        if (!frontend::parseHexColor(text, rgb))
          throw DeriveError{op.loc, "R027", "Color: \"" + strings_.text(id) +
                                                "\" is no colour (a colour string is \"#rrggbb\", six hex digits)"};
        for (int k = 0; k < 3; ++k) st.scope.color[size_t(k)] = float(rgb[size_t(k)]);
        st.scope.colored = true;
        break;
      }
      for (int k = 0; k < 3; ++k) {
        if (!std::isfinite(a[k]))
          throw DeriveError{op.loc, "R027", "Color: the colour's " + std::string(1, "rgb"[k]) +
                                                " is not a number (a parameter became NaN or infinite)"};
        st.scope.color[size_t(k)] = float(std::clamp(a[k], 0.0, 1.0));  // CGA clamps too
      }
      st.scope.colored = true;
      break;
    default: break;
  }
}

// CGA's center(axes): moves the scope, along each selected axis of its own, so that its
// centre lines up with the centre of the scope the successor (or split body) started
// with. Sizes and orientation stay.
void ScopeCommands::center(State& st, const ir::Op& op) {
  if (surface_)
    throw DeriveError{op.loc, "R009",
                      "Center moves the scope through space, but on a surface the scope stands on a "
                      "surface point: move it along the surface with T"};
  if (!st.origin) throw DeriveError{op.loc, "R900", "internal: Center without the successor's first scope"};
  const rt::Scope& origin = *st.origin;
  const rt::Vec3 from = st.scope.P + st.scope.axes * (0.5 * st.scope.S);
  const rt::Vec3 to = origin.P + origin.axes * (0.5 * origin.S);
  const rt::Vec3 shift = to - from;
  for (int k = 0; k < 3; ++k)
    if (op.index & (1u << k)) st.scope.P += shift.dot(st.scope.axes.col(k)) * st.scope.axes.col(k);
}

}  // namespace fgsg::backend
