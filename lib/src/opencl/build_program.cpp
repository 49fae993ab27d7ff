// build_program.cpp - building a program from source or from a cached
// binary, with the library's errors (the build log travels in BuildError,
// its locations mapped back to the source's files).
#include "build_program.hpp"

#include "binary_cache.hpp"
#include "build_log_lines.hpp"
#include "device_quirks.hpp"
#include "ggxcl/error.hpp"

namespace ggxcl::detail {

namespace {

std::string build_log(const cl::Program& program, const cl::Device& device)
{
    try {
        return program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(device);
    } catch (const cl::Error&) {
        return "(no build log available)";
    }
}

// The build log with the file and line of `source`'s #line markers wherever the compiler printed
// a physical line of the program (build_log_lines.hpp).
std::string mapped_build_log(const cl::Program& program, const cl::Device& device, const std::string& source)
{
    return map_build_log(build_log(program, device), program_lines(source));
}

cl::Program build_from_source(const cl::Context& context, const cl::Device& device, const std::string& source,
                              const std::string& options)
{
    cl::Program program;
    try {
        program = cl::Program(context, source);
    } catch (const cl::Error& e) {
        throw ClError("clCreateProgramWithSource", e.err());
    }
    try {
        program.build({device}, options.c_str());
    } catch (const cl::Error& e) {
        throw BuildError(e.err(), device.getInfo<CL_DEVICE_NAME>(), options,
                         mapped_build_log(program, device, source));
    }
    return program;
}

// The program from a stored binary; a null program when there is none or
// the driver does not take it.
cl::Program build_from_binary(const cl::Context& context, const cl::Device& device, const std::string& key,
                              const std::string& options)
{
    std::vector<unsigned char> binary;
    if (!load_program_binary(key, binary))
        return cl::Program();
    try {
        cl::Program program(context, {device}, cl::Program::Binaries{binary});
        program.build({device}, options.c_str());
        return program;
    } catch (const cl::Error&) {
        return cl::Program();
    }
}

void keep_program_binary(const cl::Program& program, const std::string& key)
{
    try {
        std::vector<std::vector<unsigned char>> binaries = program.getInfo<CL_PROGRAM_BINARIES>();
        if (binaries.size() == 1)
            store_program_binary(key, binaries.front());
    } catch (const cl::Error&) {
        // a driver without binaries: every process builds from source
    }
}

} // namespace

cl::Program build_program(const cl::Context& context, const cl::Device& device, const std::string& source,
                          const std::string& options, bool keep_binary, bool* from_binary)
{
    if (from_binary)
        *from_binary = false;
    const std::string all_options = options + device_quirk_options(device);
    if (!keep_binary || !binary_cache_applies(device))
        return build_from_source(context, device, source, all_options);
    const std::string key = binary_cache_key(device, source, all_options);
    cl::Program program = build_from_binary(context, device, key, all_options);
    if (program() != nullptr) {
        if (from_binary)
            *from_binary = true;
        return program;
    }
    program = build_from_source(context, device, source, all_options);
    keep_program_binary(program, key);
    return program;
}

} // namespace ggxcl::detail
