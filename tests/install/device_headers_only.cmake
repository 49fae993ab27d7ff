# device_headers_only.cmake - the test_device_headers_only CTest script (cmake -P):
# configures the source tree with -DGGXCL_DEVICE_HEADERS_ONLY=ON while CMake is
# told that OpenCL, Boost, CLI11, doctest, nlohmann-json and pybind11 do not
# exist (CMAKE_DISABLE_FIND_PACKAGE_*), so the configure proves it needs none
# of them; installs to a temporary prefix; checks that the device headers,
# ggxcl-device.pc and the CMake package are there and no library or program
# is; `pkg-config --cflags ggxcl-device` reaches ggx_samplers.h and `--libs`
# is empty; examples/glsl and examples/hlsl compile with those flags
# (glslangValidator); examples/cpu_render compiles and runs with them and as a
# CMake project through find_package(ggxcl COMPONENTS device_headers), while
# find_package(ggxcl) asking for the runtime fails with a message naming the
# component.  Inputs: SOURCE_DIR, WORK_DIR, GENERATOR, CXX.
cmake_minimum_required(VERSION 3.20)
set(prefix ${WORK_DIR}/prefix)

include(${CMAKE_CURRENT_LIST_DIR}/script_steps.cmake)

file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
set(absent)
foreach(package OpenCL Boost CLI11 doctest nlohmann_json pybind11 Python3 Threads)
  list(APPEND absent -DCMAKE_DISABLE_FIND_PACKAGE_${package}=ON)
endforeach()
step("configure the device headers alone" ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/build -G ${GENERATOR}
  -DCMAKE_CXX_COMPILER=${CXX} -DGGXCL_DEVICE_HEADERS_ONLY=ON ${absent})
step("install" ${CMAKE_COMMAND} --install ${WORK_DIR}/build --prefix ${prefix})
file(GLOB_RECURSE installed RELATIVE ${prefix} ${prefix}/*)
foreach(path IN LISTS installed)
  if(NOT path MATCHES "^include/ggxcl/cl/ggx_[a-z0-9_]+\\.(h|cl)$" AND
     NOT path MATCHES "^lib[^/]*/(pkgconfig/ggxcl-device\\.pc|cmake/ggxcl/ggxclConfig(Version)?\\.cmake)$")
    fail("installed beyond the device headers: ${path}")
  endif()
endforeach()
foreach(path include/ggxcl/cl/ggx_samplers.h include/ggxcl/cl/ggx_contract.h include/ggxcl/cl/ggx_method_traits.h)
  if(NOT EXISTS ${prefix}/${path})
    fail("missing: ${path}")
  endif()
endforeach()

file(GLOB pc_dirs ${prefix}/lib*/pkgconfig)
set(ENV{PKG_CONFIG_PATH} "${pc_dirs}")
find_program(PKG_CONFIG NAMES pkg-config pkgconf REQUIRED)
step("pkg-config --libs ggxcl-device" ${PKG_CONFIG} --libs ggxcl-device)
string(STRIP "${step_output}" libs)
if(NOT libs STREQUAL "")
  fail("pkg-config --libs ggxcl-device is not empty: ${libs}")
endif()
step("pkg-config --cflags ggxcl-device" ${PKG_CONFIG} --cflags ggxcl-device)
separate_arguments(cflags UNIX_COMMAND "${step_output}")
step("compile cpu_render with pkg-config's flags" ${CXX} -std=c++17 -O2 ${cflags}
  ${SOURCE_DIR}/examples/cpu_render/cpu_render.cpp -o ${WORK_DIR}/cpu-render-pc)
step("run cpu_render (pkg-config)" ${WORK_DIR}/cpu-render-pc 100000)
# The same flags serve the shading languages (docs/SHADERS.md): the examples' compute shaders.
find_program(GLSLANG_VALIDATOR glslangValidator REQUIRED)  # glslang-tools
step("compile examples/glsl with pkg-config's flags" ${GLSLANG_VALIDATOR} --quiet -V ${cflags}
  ${SOURCE_DIR}/examples/glsl/furnace.comp -o ${WORK_DIR}/furnace-glsl.spv)
step("compile examples/hlsl with pkg-config's flags" ${GLSLANG_VALIDATOR} --quiet -V -D -e main -S comp
  --target-env vulkan1.1 -DGGX_HLSL=1 ${cflags} ${SOURCE_DIR}/examples/hlsl/furnace.hlsl -o ${WORK_DIR}/furnace-hlsl.spv)

step("configure examples/cpu_render" ${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/cpu_render
  -B ${WORK_DIR}/cpu-render-build -G ${GENERATOR} -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_PREFIX_PATH=${prefix})
step("build examples/cpu_render" ${CMAKE_COMMAND} --build ${WORK_DIR}/cpu-render-build)
step("run cpu_render (find_package)" ${WORK_DIR}/cpu-render-build/cpu_render 100000)

# The runtime asked of a headers-only install: refused, naming the component to ask for.
file(MAKE_DIRECTORY ${WORK_DIR}/runtime)
file(WRITE ${WORK_DIR}/runtime/CMakeLists.txt
  "cmake_minimum_required(VERSION 3.20)\nproject(asks_runtime LANGUAGES CXX)\nfind_package(ggxcl CONFIG REQUIRED)\n")
execute_process(COMMAND ${CMAKE_COMMAND} -S ${WORK_DIR}/runtime -B ${WORK_DIR}/runtime/build -G ${GENERATOR}
  -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_PREFIX_PATH=${prefix} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(status EQUAL 0 OR NOT "${out}${err}" MATCHES "COMPONENTS[ \n]+device_headers")
  fail("find_package(ggxcl) for the runtime of a headers-only install: status ${status}\n${out}\n${err}")
endif()
message(STATUS "the runtime of a headers-only install is refused, naming the device_headers component: ok")
file(REMOVE_RECURSE ${WORK_DIR})
