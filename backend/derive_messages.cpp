#include "backend/derive_messages.h"

namespace fgsg::backend {

void addDeriveMessages(const rt::DeriveResult& result, frontend::Diagnostics& diags) {
  for (const auto& m : result.messages) {
    const frontend::SourceRange at{{m.line, m.col}, {m.line, m.col}};
    if (m.isError)
      diags.error(m.code, at, m.message);
    else
      diags.warning(m.code, at, m.message);
  }
}

}  // namespace fgsg::backend
