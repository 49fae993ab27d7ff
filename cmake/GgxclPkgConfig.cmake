# GgxclPkgConfig.cmake - ggxcl.pc for `pkg-config --cflags --libs ggxcl`:
# the include directory and ggxcl's public compile definitions, the library
# with OpenCL (and, for a static libggxcl, the thread library, and the C++
# runtime as Libs.private for C programs), and for a shared libggxcl its run
# path, so that a program linked with --libs runs as it is.  The prefix
# is found from the file's own place (${pcfiledir}), so the installed tree
# can move; `pkg-config --variable=devicedir ggxcl` names the device headers.
# The prefix and directories: GgxclDeviceHeaders.cmake (GGXCL_PC_PREFIX, _LIBDIR, _INCLUDEDIR).
# -D flags of the definitions that travel with ggxcl::ggxcl.
get_target_property(GGXCL_PC_DEFINITIONS ggxcl INTERFACE_COMPILE_DEFINITIONS)
list(TRANSFORM GGXCL_PC_DEFINITIONS PREPEND -D)
list(JOIN GGXCL_PC_DEFINITIONS " " GGXCL_PC_CFLAGS)

# OpenCL: its include and library directories unless the compiler searches them anyway.
set(GGXCL_PC_LIBS "-lOpenCL")
get_filename_component(GGXCL_OPENCL_LIBDIR "${OpenCL_LIBRARY}" DIRECTORY)
if(GGXCL_OPENCL_LIBDIR AND NOT GGXCL_OPENCL_LIBDIR IN_LIST CMAKE_CXX_IMPLICIT_LINK_DIRECTORIES)
  string(PREPEND GGXCL_PC_LIBS "-L${GGXCL_OPENCL_LIBDIR} ")
endif()
foreach(dir IN LISTS OpenCL_INCLUDE_DIRS)
  if(NOT dir IN_LIST CMAKE_CXX_IMPLICIT_INCLUDE_DIRECTORIES)
    string(APPEND GGXCL_PC_CFLAGS " -I${dir}")
  endif()
endforeach()
get_target_property(GGXCL_TYPE ggxcl TYPE)
if(GGXCL_TYPE STREQUAL "STATIC_LIBRARY" AND CMAKE_THREAD_LIBS_INIT)
  string(APPEND GGXCL_PC_LIBS " ${CMAKE_THREAD_LIBS_INIT}")
endif()
# A shared libggxcl: programs linked with --libs find it where it is installed (its run path).
set(GGXCL_PC_RPATH "")
if(GGXCL_TYPE STREQUAL "SHARED_LIBRARY")
  set(GGXCL_PC_RPATH "-Wl,-rpath,\${libdir}")
endif()
# A static libggxcl is C++: a C program links it with `pkg-config --static`, which adds these.
set(GGXCL_PC_LIBS_PRIVATE "")
if(GGXCL_TYPE STREQUAL "STATIC_LIBRARY")
  set(GGXCL_PC_LIBS_PRIVATE "-lstdc++ -lm")
endif()

configure_file(${CMAKE_CURRENT_LIST_DIR}/ggxcl.pc.in ${PROJECT_BINARY_DIR}/package/ggxcl.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/package/ggxcl.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
