#!/usr/bin/env bash
# Regenerates the ANTLR4 C++ parser (grammar/generated/) from grammar/Fgsg.g4.
# The generated sources are checked in, so only grammar changes need this script.
# Needs the `antlr4` tool (Debian package antlr4, 4.7.2; its output builds against the
# 4.9 C++ runtime).
set -euo pipefail
cd "$(dirname "$0")/.."

rm -rf grammar/generated
antlr4 -Dlanguage=Cpp -visitor -no-listener -package fgsg_grammar \
       -o grammar/generated -Xexact-output-dir grammar/Fgsg.g4
# Interpreter data files are not needed to build.
rm -f grammar/generated/*.interp grammar/generated/*.tokens
# Tool 4.7.2 writes u8"..." literals, which are char8_t in C++20 and no longer convert
# to std::string; plain literals are UTF-8 with g++ and clang++ alike.
sed -i 's/\bu8"/"/g' grammar/generated/*.cpp grammar/generated/*.h
echo "regenerated grammar/generated/ from grammar/Fgsg.g4"
