#!/usr/bin/env bash
# Regenerates the ANTLR4 C++ parsers (grammar/generated/) from grammar/Fgsg.g4 (the .fgsg
# dialect) and grammar/Cga.g4 (CityEngine's CGA, the .cga dialect).
# The generated sources are checked in, so only grammar changes need this script.
# Needs the `antlr4` tool (Debian package antlr4, 4.7.2; its output builds against the
# 4.9 C++ runtime).
set -euo pipefail
cd "$(dirname "$0")/.."

rm -rf grammar/generated
for g in Fgsg Cga; do
  antlr4 -Dlanguage=Cpp -visitor -no-listener -package fgsg_grammar \
         -o grammar/generated -Xexact-output-dir grammar/$g.g4
done
# Interpreter data files are not needed to build.
rm -f grammar/generated/*.interp grammar/generated/*.tokens
# Tool 4.7.2 writes u8"..." literals, which are char8_t in C++20 and no longer convert
# to std::string; plain literals are UTF-8 with g++ and clang++ alike.
sed -i 's/\bu8"/"/g' grammar/generated/*.cpp grammar/generated/*.h
# The lexers' and parsers' ATNs are deserialised on first use, not by a static
# initialiser at program start: every fgsg command would pay for it, even --version
# (a quarter of its start-up, issue #18). The first constructor runs the Initializer,
# once and thread-safely (a function-local static).
for g in Fgsg Cga; do
  for f in Lexer Parser; do
    sed -i -e "s|^$g$f::Initializer $g$f::_init;\$|// $g$f::Initializer runs in the constructor, on first use (scripts/regen-grammar.sh).|" \
           -e "/^$g$f::$g$f(.*) : .*(input) {\$/a\\  static Initializer once;" grammar/generated/$g$f.cpp
    python3 scripts/atn_descending_sets.py grammar/generated/$g$f.cpp
  done
done
echo "regenerated grammar/generated/ from grammar/Fgsg.g4 and grammar/Cga.g4"
