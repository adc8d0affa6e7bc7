# What C and C++ programs need from `cmake --install`: the C API header in include/fgsg/,
# libfgsg.so (installed with the commands, CMakeLists.txt), a CMake package
# (find_package(fgsg) -> fgsg::fgsg) and a pkg-config file. Both find the prefix from
# where they lie, so an installed tree can be moved (tests/cli/c_api_installed.sh).
include(CMakePackageConfigHelpers)

install(FILES ${CMAKE_SOURCE_DIR}/backend/aot/fgsg_api.h DESTINATION include/fgsg)

configure_file(${CMAKE_CURRENT_LIST_DIR}/fgsgConfig.cmake.in ${CMAKE_BINARY_DIR}/cmake/fgsgConfig.cmake @ONLY)
# The C API only grows within a major version (0.x: the same minor).
write_basic_package_version_file(${CMAKE_BINARY_DIR}/cmake/fgsgConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/cmake/fgsgConfig.cmake ${CMAKE_BINARY_DIR}/cmake/fgsgConfigVersion.cmake
        DESTINATION lib/cmake/fgsg)

configure_file(${CMAKE_CURRENT_LIST_DIR}/fgsg.pc.in ${CMAKE_BINARY_DIR}/cmake/fgsg.pc @ONLY)
install(FILES ${CMAKE_BINARY_DIR}/cmake/fgsg.pc DESTINATION lib/pkgconfig)
install(FILES ${CMAKE_SOURCE_DIR}/LICENSE DESTINATION share/doc/fgsg)
