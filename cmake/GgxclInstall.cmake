# GgxclInstall.cmake - what `cmake --install` puts where (GNUInstallDirs):
# libggxcl, its C++ headers, the OpenCL C device headers for user kernels
# (GGXCL_INSTALL_DEVICE_DIR) and the `ggx` tool with its native baseline
# ggx-native (libexec/ggxcl); the CMake package
# (find_package(ggxcl CONFIG) -> ggxcl::ggxcl, with a version file), the
# pkg-config file ggxcl.pc, and the same package for the build tree.
include(CMakePackageConfigHelpers)
set(GGXCL_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/ggxcl)

install(TARGETS ggxcl EXPORT ggxclTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/lib/include/ggxcl DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
  FILES_MATCHING PATTERN "*.hpp" PATTERN "*.h")
# The device headers and ggxcl-device.pc.
include(${CMAKE_CURRENT_LIST_DIR}/GgxclDeviceHeaders.cmake)
if(TARGET ggx)
  install(TARGETS ggx RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  # The -march=native baseline `ggx bench` runs as a child process; ggx looks in ../libexec/ggxcl.
  install(TARGETS ggx-native RUNTIME DESTINATION ${CMAKE_INSTALL_LIBEXECDIR}/ggxcl)
endif()

# The CMake package, installed: GGXCL_DEVICE_INCLUDE_DIR relative to the prefix.
ggxcl_install_package_config(TRUE)
install(EXPORT ggxclTargets NAMESPACE ggxcl:: DESTINATION ${GGXCL_CMAKE_DIR})

# The same package in the build tree (ggxcl_DIR=<build dir>): the device
# headers are the source tree's kernels/.
set(GGXCL_CONFIG_DEVICE_DIR ${PROJECT_SOURCE_DIR}/kernels)
set(GGXCL_CONFIG_HAS_RUNTIME TRUE)
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/ggxclConfig.cmake.in
  ${PROJECT_BINARY_DIR}/ggxclConfig.cmake
  INSTALL_DESTINATION ${PROJECT_BINARY_DIR} INSTALL_PREFIX ${PROJECT_BINARY_DIR}
  PATH_VARS GGXCL_CONFIG_DEVICE_DIR)
export(EXPORT ggxclTargets NAMESPACE ggxcl:: FILE ${PROJECT_BINARY_DIR}/ggxclTargets.cmake)

include(${CMAKE_CURRENT_LIST_DIR}/GgxclPkgConfig.cmake)
