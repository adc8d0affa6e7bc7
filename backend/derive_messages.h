// A derivation's messages (R… errors, R004 warnings) as diagnostics of the grammar's
// source, so that every engine's problems print like compile diagnostics: location,
// source line, caret. (Its own file: libfgsg.so uses it without the JIT.)
#pragma once

#include "frontend/diagnostics.h"
#include "runtime/derivation.h"

namespace fgsg::backend {

void addDeriveMessages(const rt::DeriveResult& result, frontend::Diagnostics& diags);

}  // namespace fgsg::backend
