# install_consumer.cmake - the test_install_consumer CTest script (cmake -P):
# installs the build tree to a temporary prefix, checks what is there and
# that every installed C++ header compiles on its own, builds
# examples/albedo_table against the installed package (CMAKE_PREFIX_PATH),
# runs it and checks its .npy and .png files, compiles tests/install/consumer with
# `pkg-config --cflags --libs ggxcl` and against the build tree's export
# (ggxcl_DIR = the build tree), runs both, builds examples/cpu_render (the
# device headers as plain C++, no OpenCL) with a bare -I and through
# find_package's device_headers component, runs it; then C: ggxcl.h compiles
# as C99 (-pedantic) and as C++, examples/c builds as a C-only CMake project
# with find_package and runs, tests/c_api/c_consumer.c builds as C99 with
# `pkg-config` and as a C-only CMake project with find_package, and gets the
# C++ API's bits (CPP_DUMP writes them) both ways;
# and removes the prefix.
# Inputs: BUILD_DIR, SOURCE_DIR, WORK_DIR, LIBDIR, INCLUDEDIR, BINDIR,
# GENERATOR, CXX, CXX_FLAGS, CC, C_FLAGS, LINKER_FLAGS, CPP_DUMP, SAMPLES,
# HAS_GGX, and PYTHON with PYTHON_DIR (the package's folder under the prefix)
# when the module is built.
cmake_minimum_required(VERSION 3.20)
set(prefix ${WORK_DIR}/prefix)
separate_arguments(cxx_flags UNIX_COMMAND "${CXX_FLAGS}")
separate_arguments(c_flags UNIX_COMMAND "${C_FLAGS}")
separate_arguments(linker_flags UNIX_COMMAND "${LINKER_FLAGS}")
# Programs built by hand find the installed shared libggxcl.
list(APPEND linker_flags -Wl,-rpath,${prefix}/${LIBDIR})
set(forward_flags -G ${GENERATOR} -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CXX}
    "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}" -DCMAKE_C_COMPILER=${CC} "-DCMAKE_C_FLAGS=${C_FLAGS}"
    "-DCMAKE_EXE_LINKER_FLAGS=${LINKER_FLAGS}")

include(${CMAKE_CURRENT_LIST_DIR}/script_steps.cmake)

function(expect_files)
  foreach(path IN LISTS ARGN)
    if(NOT EXISTS ${path})
      fail("missing: ${path}")
    endif()
  endforeach()
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

# 1. Install, and what it put where.
step("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
if(HAS_GGX)
  expect_files(${prefix}/${BINDIR}/ggx)
endif()
expect_files(${prefix}/${INCLUDEDIR}/ggxcl/ggxcl.hpp
  ${prefix}/${INCLUDEDIR}/ggxcl/cl/ggx_samplers.h ${prefix}/${INCLUDEDIR}/ggxcl/cl/ggx_math.h
  ${prefix}/${LIBDIR}/cmake/ggxcl/ggxclConfig.cmake ${prefix}/${LIBDIR}/cmake/ggxcl/ggxclConfigVersion.cmake
  ${prefix}/${LIBDIR}/cmake/ggxcl/ggxclTargets.cmake ${prefix}/${LIBDIR}/pkgconfig/ggxcl.pc)

# 2. Each installed C++ header compiles on its own (with only ggxcl.pc's flags).
set(ENV{PKG_CONFIG_PATH} ${prefix}/${LIBDIR}/pkgconfig)
find_program(PKG_CONFIG NAMES pkg-config pkgconf)
if(NOT PKG_CONFIG)
  fail("pkg-config not found (Debian: apt-get install pkgconf)")
endif()
step("pkg-config --cflags --libs ggxcl" ${PKG_CONFIG} --cflags --libs ggxcl)
separate_arguments(pc_flags UNIX_COMMAND "${step_output}")
step("pkg-config --variable=devicedir ggxcl" ${PKG_CONFIG} --variable=devicedir ggxcl)
string(STRIP "${step_output}" pc_devicedir)
expect_files(${pc_devicedir}/ggx_samplers.h)
file(GLOB headers RELATIVE ${prefix}/${INCLUDEDIR} ${prefix}/${INCLUDEDIR}/ggxcl/*.hpp)
set(units)
foreach(header IN LISTS headers)
  string(MAKE_C_IDENTIFIER ${header} unit)
  file(WRITE ${WORK_DIR}/headers/${unit}.cpp "#include <${header}>\n")
  list(APPEND units ${WORK_DIR}/headers/${unit}.cpp)
endforeach()
step("installed headers standalone" ${CXX} -std=c++17 -fsyntax-only ${pc_flags} ${units})

# 2b. Including the bindings without exceptions before ggxcl is refused, by name.
file(WRITE ${WORK_DIR}/headers/bindings_first.cpp "#include <CL/opencl.hpp>\n#include <ggxcl/ggxcl.hpp>\n")
execute_process(COMMAND ${CXX} -std=c++17 -fsyntax-only ${pc_flags} ${WORK_DIR}/headers/bindings_first.cpp
  RESULT_VARIABLE status ERROR_VARIABLE err OUTPUT_QUIET)
if(status EQUAL 0 OR NOT err MATCHES "CL_HPP_ENABLE_EXCEPTIONS")
  fail("<CL/opencl.hpp> without exceptions before <ggxcl/ggxcl.hpp>: status ${status}, expected the #error\n${err}")
endif()
message(STATUS "bindings without exceptions first: refused")

# 3. The example against the installed package.
step("configure examples/albedo_table" ${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/albedo_table
  -B ${WORK_DIR}/albedo-build -DCMAKE_PREFIX_PATH=${prefix} ${forward_flags})
step("build examples/albedo_table" ${CMAKE_COMMAND} --build ${WORK_DIR}/albedo-build -j2)
step("run albedo_table" ${WORK_DIR}/albedo-build/albedo_table --out ${WORK_DIR}/tables --samples ${SAMPLES})
message(STATUS "${step_output}")
foreach(method ndf heitz heitz2017 caps caps-iso bounded quadrature)
  expect_files(${WORK_DIR}/tables/albedo_${method}.npy ${WORK_DIR}/tables/albedo_${method}.png)
  file(SIZE ${WORK_DIR}/tables/albedo_${method}.npy npy_size)
  file(READ ${WORK_DIR}/tables/albedo_${method}.png png_magic LIMIT 8 HEX)
  if(NOT npy_size EQUAL 4224 OR NOT png_magic STREQUAL "89504e470d0a1a0a")
    fail("albedo_${method}: .npy of ${npy_size} bytes (expected 128 + 32 x 32 x 4), PNG magic ${png_magic}")
  endif()
endforeach()

# 4. A one-file consumer through pkg-config.
step("compile consumer with pkg-config" ${CXX} -std=c++17 -O2 ${cxx_flags} ${SOURCE_DIR}/tests/install/consumer/consumer.cpp
  ${pc_flags} ${linker_flags} -o ${WORK_DIR}/consumer-pkg-config)
step("run consumer (pkg-config)" ${WORK_DIR}/consumer-pkg-config)
message(STATUS "${step_output}")

# 5. The same consumer against the build tree's export.
step("configure consumer against the build tree" ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/install/consumer
  -B ${WORK_DIR}/consumer-build -Dggxcl_DIR=${BUILD_DIR} ${forward_flags})
step("build consumer against the build tree" ${CMAKE_COMMAND} --build ${WORK_DIR}/consumer-build -j2)
step("run consumer (build tree)" ${WORK_DIR}/consumer-build/consumer)
message(STATUS "${step_output}")

# 6. A C++ program with no OpenCL at all, calling the device headers directly
# (examples/cpu_render): with a bare -I, and through find_package(ggxcl
# COMPONENTS device_headers) with OpenCL hidden from CMake.
step("compile cpu_render with a bare -I" ${CXX} -std=c++17 -O2 ${cxx_flags} -I${prefix}/${INCLUDEDIR}/ggxcl/cl
  ${SOURCE_DIR}/examples/cpu_render/cpu_render.cpp ${linker_flags} -o ${WORK_DIR}/cpu-render-bare)
step("run cpu_render (bare -I)" ${WORK_DIR}/cpu-render-bare 200000)
message(STATUS "${step_output}")
step("configure examples/cpu_render" ${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/cpu_render
  -B ${WORK_DIR}/cpu-render-build -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_DISABLE_FIND_PACKAGE_OpenCL=TRUE
  ${forward_flags})
step("build examples/cpu_render" ${CMAKE_COMMAND} --build ${WORK_DIR}/cpu-render-build)
step("run cpu_render (find_package)" ${WORK_DIR}/cpu-render-build/cpu_render 200000)

# 7. C: the header as C99 and as C++, examples/c (a C-only project) through find_package, and the
# C API's test program through pkg-config, against the C++ API's bits.
file(WRITE ${WORK_DIR}/headers/c_header.c "#include <ggxcl/ggxcl.h>\n")
file(WRITE ${WORK_DIR}/headers/c_header.cpp "#include <ggxcl/ggxcl.h>\n#include <ggxcl/ggxcl.hpp>\n")
step("ggxcl.h as C99" ${CC} -std=c99 -Wall -Wextra -pedantic -Werror -fsyntax-only ${pc_flags}
  ${WORK_DIR}/headers/c_header.c)
step("ggxcl.h as C++" ${CXX} -std=c++17 -Wall -Wextra -pedantic -Werror -fsyntax-only ${pc_flags}
  ${WORK_DIR}/headers/c_header.cpp)
step("configure examples/c" ${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/c -B ${WORK_DIR}/c-build
  -DCMAKE_PREFIX_PATH=${prefix} ${forward_flags})
step("build examples/c" ${CMAKE_COMMAND} --build ${WORK_DIR}/c-build)
step("run sample_into_buffers" ${WORK_DIR}/c-build/sample_into_buffers 65536)
message(STATUS "${step_output}")
if(NOT step_output MATCHES "directional albedo 0\\.82")
  fail("sample_into_buffers: not the furnace albedo of caps at 60 degrees, alpha 0.3 (0.822) in ${step_output}")
endif()
step("compile c_consumer.c with pkg-config" ${CC} -std=c99 -Wall -Wextra -pedantic -Werror -O2 ${c_flags}
  -I${SOURCE_DIR}/tests/c_api ${SOURCE_DIR}/tests/c_api/c_consumer.c ${pc_flags} ${linker_flags} -lm
  -o ${WORK_DIR}/c-consumer)
step("C++ API's bits" ${CPP_DUMP} ${WORK_DIR}/cpp-dump.f32 ${SOURCE_DIR}/tests/user_samplers)
step("run c_consumer (pkg-config)" ${WORK_DIR}/c-consumer bits ${WORK_DIR}/cpp-dump.f32
  ${SOURCE_DIR}/tests/user_samplers)
message(STATUS "${step_output}")
step("configure c_consumer (C-only, find_package)" ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/c_api/installed
  -B ${WORK_DIR}/c-consumer-build -DCMAKE_PREFIX_PATH=${prefix} ${forward_flags})
step("build c_consumer (find_package)" ${CMAKE_COMMAND} --build ${WORK_DIR}/c-consumer-build)
step("run c_consumer (find_package)" ${WORK_DIR}/c-consumer-build/c_consumer bits ${WORK_DIR}/cpp-dump.f32
  ${SOURCE_DIR}/tests/user_samplers)

# 8. The installed Python package imports from under the prefix and samples
# (no semicolons in the code: step() would split it as a CMake list).
if(PYTHON)
  step("import the installed Python package" ${CMAKE_COMMAND} -E env PYTHONPATH=${prefix}/${PYTHON_DIR} ${PYTHON} -c
    "import ggxcl\nd = ggxcl.Sampler().sample('caps', 1000, fields=('o',))\nassert d['o'].shape == (1000, 3)\nprint(ggxcl.__file__)")
  if(NOT step_output MATCHES "^${prefix}/${PYTHON_DIR}/ggxcl/__init__.py")
    fail("the Python package came from ${step_output}, not from ${prefix}/${PYTHON_DIR}")
  endif()
  message(STATUS "Python package: ${step_output}")
endif()

file(REMOVE_RECURSE ${WORK_DIR})
