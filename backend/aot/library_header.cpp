#include "backend/aot/library_header.h"

#include "backend/aot/fgsg_api_text.h"  // generated in the build tree from fgsg_api.h

#include <filesystem>
#include <stdexcept>

namespace fgsg::backend::aot {

namespace {

// The runtime entry points generated code calls, as C prototypes: runtime/abi.def
// expanded once more (its C++ types are C types here).
#define FGSG_RT_FN(name, ret, ...) #ret " " #name "(" #__VA_ARGS__ ");\n"
constexpr const char kRuntimePrototypes[] =
#include "runtime/abi.def"
    ;

bool isAsciiLetter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool isAsciiDigit(char c) { return c >= '0' && c <= '9'; }

}  // namespace

std::string librarySymbolName(const std::string& outputPath) {
  const std::string file = std::filesystem::path(outputPath).filename().string();
  const std::string shape = " (the library must be named libNAME.so, NAME a C identifier)";
  if (file.size() < 3 || file.compare(file.size() - 3, 3, ".so") != 0)
    throw std::invalid_argument("'" + outputPath + "' does not end in .so" + shape);
  std::string name = file.substr(0, file.size() - 3);
  if (name.rfind("lib", 0) == 0) name = name.substr(3);
  if (name.empty()) throw std::invalid_argument("'" + outputPath + "' names no library" + shape);
  for (char& c : name) {
    if (c == '-' || c == '.') c = '_';
    else if (!isAsciiLetter(c) && !isAsciiDigit(c) && c != '_')
      throw std::invalid_argument("'" + outputPath + "': '" + file +
                                  "' has characters other than letters, digits, '_', '-' and '.'" + shape);
  }
  if (!isAsciiLetter(name[0]))
    throw std::invalid_argument("'" + outputPath + "': NAME '" + name + "' does not start with a letter" + shape);
  return name;
}

std::string libraryHeader(const std::string& name) {
  const std::string guard = "FGSG_LIBRARY_" + name + "_H";  // NAME's case kept: libFoo and libfoo differ
  std::string out;
  out += "/* " + name + ".h: the grammar compiled into lib" + name + ".so by fgsg compile.\n";
  out += " * Link with -l" + name + " -lfgsg. Generated: do not edit. */\n";
  out += "#ifndef " + guard + "\n#define " + guard + "\n\n";
  out += kFgsgApiHeaderText;
  out += "\n#ifdef __cplusplus\nextern \"C\" {\n#endif\n\n";
  out += "struct FgsgProgram;\n";
  out += "/* The compiled grammar, for fgsg_generator_create. */\n";
  out += "extern const struct FgsgProgram fgsg_program_" + name + ";\n\n";
  out += "/* A generator for this grammar (free it with fgsg_generator_free). */\n";
  out += "static inline fgsg_generator* " + name + "_create(void) {\n";
  out += "  return fgsg_generator_create(&fgsg_program_" + name + ");\n}\n\n";
  out += "/* The runtime entry points lib" + name + ".so calls (libfgsg.so exports them; for\n";
  out += " * reference, not for use: their context comes from the engine). runtime/abi.def. */\n";
  out += "typedef struct FgsgContext FgsgContext;\n";
  out += kRuntimePrototypes;
  out += "\n#ifdef __cplusplus\n}\n#endif\n\n#endif /* " + guard + " */\n";
  return out;
}

}  // namespace fgsg::backend::aot
