// Math builtins shared by the interpreter and generated code, so that both call the
// same libm functions with the same degree conversions and get the same bits.
// Declared from runtime/abi.def (FGSG_RT_MATH entries).
#pragma once

#include <cstdint>

extern "C" {
#define FGSG_RT_FN(name, ret, ...)
#define FGSG_RT_MATH(name, ret, ...) ret name(__VA_ARGS__) noexcept;
#include "runtime/abi.def"
#undef FGSG_RT_MATH
}
