# GgxclDeviceHeaders.cmake - the device headers' install, alone
# (-DGGXCL_DEVICE_HEADERS_ONLY=ON) or as part of the whole install
# (GgxclInstall.cmake): kernels/*.h and the bulk kernels into
# GGXCL_INSTALL_DEVICE_DIR, and ggxcl-device.pc, whose --cflags reach
# `#include "ggx_samplers.h"` and whose --libs are empty.  Alone, it also
# installs the CMake package with the device_headers component only
# (find_package(ggxcl CONFIG COMPONENTS device_headers) -> ggxcl::device_headers).
include(CMakePackageConfigHelpers)
set(GGXCL_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/ggxcl)

# Every header (user kernels include them) and the bulk kernels built from
# them, for reading or building offline; not the stress harness.
file(GLOB GGXCL_DEVICE_HEADERS ${PROJECT_SOURCE_DIR}/kernels/*.h)
install(FILES ${GGXCL_DEVICE_HEADERS} ${PROJECT_SOURCE_DIR}/kernels/ggx_bulk.cl
  ${PROJECT_SOURCE_DIR}/kernels/ggx_furnace.cl ${PROJECT_SOURCE_DIR}/kernels/ggx_histogram.cl
  DESTINATION ${GGXCL_INSTALL_DEVICE_DIR})

# The pkg-config files' prefix, found from their own place (${pcfiledir}) so
# the installed tree can move, and their directories (ggxcl.pc's too).
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}" OR IS_ABSOLUTE "${CMAKE_INSTALL_INCLUDEDIR}")
  set(GGXCL_PC_PREFIX "${CMAKE_INSTALL_PREFIX}")
  set(GGXCL_PC_LIBDIR "${CMAKE_INSTALL_FULL_LIBDIR}")
  set(GGXCL_PC_INCLUDEDIR "${CMAKE_INSTALL_FULL_INCLUDEDIR}")
else()
  file(RELATIVE_PATH GGXCL_PC_UP /${CMAKE_INSTALL_LIBDIR}/pkgconfig /)
  string(REGEX REPLACE "/$" "" GGXCL_PC_UP "${GGXCL_PC_UP}")
  set(GGXCL_PC_PREFIX "\${pcfiledir}/${GGXCL_PC_UP}")
  set(GGXCL_PC_LIBDIR "\${prefix}/${CMAKE_INSTALL_LIBDIR}")
  set(GGXCL_PC_INCLUDEDIR "\${prefix}/${CMAKE_INSTALL_INCLUDEDIR}")
endif()
configure_file(${CMAKE_CURRENT_LIST_DIR}/ggxcl-device.pc.in ${PROJECT_BINARY_DIR}/package/ggxcl-device.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/package/ggxcl-device.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

# The CMake package's config and version files, installed; has_runtime: whether
# the library is installed too (its targets file is installed beside them).
function(ggxcl_install_package_config has_runtime)
  set(GGXCL_CONFIG_DEVICE_DIR ${GGXCL_INSTALL_DEVICE_DIR})
  set(GGXCL_CONFIG_HAS_RUNTIME ${has_runtime})
  configure_package_config_file(${CMAKE_CURRENT_FUNCTION_LIST_DIR}/ggxclConfig.cmake.in
    ${PROJECT_BINARY_DIR}/package/ggxclConfig.cmake
    INSTALL_DESTINATION ${GGXCL_CMAKE_DIR} PATH_VARS GGXCL_CONFIG_DEVICE_DIR)
  write_basic_package_version_file(${PROJECT_BINARY_DIR}/ggxclConfigVersion.cmake
    VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
  install(FILES ${PROJECT_BINARY_DIR}/package/ggxclConfig.cmake ${PROJECT_BINARY_DIR}/ggxclConfigVersion.cmake
    DESTINATION ${GGXCL_CMAKE_DIR})
endfunction()

if(GGXCL_DEVICE_HEADERS_ONLY)
  ggxcl_install_package_config(FALSE)
endif()
