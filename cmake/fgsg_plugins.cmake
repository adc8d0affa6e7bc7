# Plugins: fgsg's heavy dependencies (LLVM, FCL) in shared libraries that `fgsg` opens on
# first need (runtime/plugins/plugin_library.h), so that they cost no other command's
# start-up (issue #18). Each plugin's code is one object library, compiled once for both
# of its uses: the plugin, and every other executable and libfgsg.so, which link it in.

# lib/lib<output>.so from the object library `objects` and its `dependency`, nothing of
# fgsg's static libraries: what it uses of them comes from the executable that opens it
# (fgsg_export_for_plugins). The version script `map` exports its entry point only.
function(fgsg_add_plugin target output objects dependency map)
  add_library(${target} MODULE $<TARGET_OBJECTS:${objects}>)
  set_target_properties(${target} PROPERTIES
    OUTPUT_NAME ${output}
    LIBRARY_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/lib
    LINK_DEPENDS ${map})
  target_link_libraries(${target} PRIVATE ${dependency})
  target_link_options(${target} PRIVATE -Wl,--version-script=${map})
endfunction()

# An executable that opens the plugins exports what they use of fgsg (the fgsg::
# namespace and the runtime's entry points, backend/native/plugin_exports.list); one that
# loads the JIT cache's libraries needs the runtime's entry points.
function(fgsg_export_for_plugins target)
  set(list ${CMAKE_SOURCE_DIR}/backend/native/plugin_exports.list)
  target_link_options(${target} PRIVATE -Wl,--dynamic-list=${list})
  set_property(TARGET ${target} APPEND PROPERTY LINK_DEPENDS ${list})
  add_dependencies(${target} fgsg_llvm_plugin fgsg_fcl_plugin)
endfunction()

# Every target but fgsg links the collision plugin's code in: it then never opens it.
# (The JIT is linked in as the static fgsg_llvm where it is wanted.)
function(fgsg_link_plugins_in target)
  target_link_libraries(${target} PRIVATE fgsg_fcl_objects)
endfunction()
