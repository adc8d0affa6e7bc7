// fgsg compile's library names and generated header (backend/aot/library_header.h).
#include "backend/aot/library_header.h"

#include <catch2/catch.hpp>

#include <stdexcept>
#include <string>

using fgsg::backend::aot::libraryHeader;
using fgsg::backend::aot::librarySymbolName;

TEST_CASE("libNAME.so gives NAME: folder, lib prefix and .so removed, '-' and '.' made '_'", "[aot]") {
  CHECK(librarySymbolName("libstem_leaf.so") == "stem_leaf");
  CHECK(librarySymbolName("out/dir/libstem_leaf.so") == "stem_leaf");
  CHECK(librarySymbolName("/abs/libtree-2.so") == "tree_2");
  CHECK(librarySymbolName("libfig.v2.so") == "fig_v2");
  CHECK(librarySymbolName("plants.so") == "plants");  // without the lib prefix
  CHECK(librarySymbolName("libA_b9.so") == "A_b9");
}

TEST_CASE("names that cannot become a C identifier are refused with a reason", "[aot]") {
  auto message = [](const std::string& path) {
    try {
      librarySymbolName(path);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  CHECK_THAT(message("libstem.dylib"), Catch::Contains("does not end in .so"));
  CHECK_THAT(message("libstem"), Catch::Contains("does not end in .so"));
  CHECK_THAT(message("lib.so"), Catch::Contains("names no library"));
  CHECK_THAT(message(".so"), Catch::Contains("names no library"));
  CHECK_THAT(message("dir/"), Catch::Contains("does not end in .so"));
  CHECK_THAT(message("lib3d.so"), Catch::Contains("does not start with a letter"));
  CHECK_THAT(message("lib_x.so"), Catch::Contains("does not start with a letter"));
  CHECK_THAT(message("libst em.so"), Catch::Contains("characters other than"));
  CHECK_THAT(message("lib\xc3\xa9t\xc3\xa9.so"), Catch::Contains("characters other than"));
  CHECK_THAT(message("libx.so"), Catch::Equals("(accepted)"));
}

TEST_CASE("NAME.h holds the C API, the program's declaration and NAME_create", "[aot]") {
  const std::string h = libraryHeader("stem_leaf");
  CHECK(h.find("#ifndef FGSG_LIBRARY_stem_leaf_H") != std::string::npos);
  // The whole of fgsg_api.h, embedded at build time.
  CHECK(h.find("#ifndef FGSG_API_H") != std::string::npos);
  CHECK(h.find("#endif /* FGSG_API_H */") != std::string::npos);
  for (const char* fn : {"fgsg_generator_create", "fgsg_generator_free", "fgsg_last_error", "fgsg_set_seed",
                         "fgsg_set_attribute", "fgsg_set_surface", "fgsg_set_option", "fgsg_generate",
                         "fgsg_vertex_count", "fgsg_positions", "fgsg_normals", "fgsg_colors",
                         "fgsg_index_count", "fgsg_indices", "fgsg_instance_count",
                         "fgsg_instance_transforms", "fgsg_instance_assets", "fgsg_asset_name", "fgsg_write"})
    CHECK(h.find(std::string(fn) + "(") != std::string::npos);
  CHECK(h.find("extern const struct FgsgProgram fgsg_program_stem_leaf;") != std::string::npos);
  CHECK(h.find("static inline fgsg_generator* stem_leaf_create(void) {\n"
               "  return fgsg_generator_create(&fgsg_program_stem_leaf);\n}") != std::string::npos);
  CHECK(h.find("extern \"C\"") != std::string::npos);
  // runtime/abi.def expanded once more: every entry point compiled code calls.
  CHECK(h.find("void fgsg_rt_emit(FgsgContext*, uint32_t, const double*);\n") != std::string::npos);
  CHECK(h.find("uint64_t fgsg_rt_child_key(uint64_t, uint64_t);\n") != std::string::npos);
  const std::string end = "#endif /* FGSG_LIBRARY_stem_leaf_H */\n";
  CHECK(h.compare(h.size() - end.size(), end.size(), end) == 0);
}
