// oclgrind_probe.cpp - tiny OpenCL programs for test_oclgrind, each run
// under Oclgrind: deliberately bad kernels (negative controls: the
// detector of test_oclgrind must report each of them), a correct one (it
// must report nothing), and the minimal reproduction of Oclgrind's
// clEnqueueFillBuffer bug.
//
//   oclgrind_probe MODE
//     clean   a correct kernel on written memory: nothing to report
//     oob     a write one element past the end of a buffer
//     uninit  a copy of a buffer never written (uninitialized values written to global memory)
//     race    every work-item writes the same element (write-write data race)
//     api     a local size that does not divide the global size (an API error: --check-api)
//     fill    a buffer zeroed by clEnqueueFillBuffer, then atomic_add to it: Oclgrind 21.10
//             reports "Uninitialized value written to global memory" although fill
//             initialized every byte (its bug; ggxcl zeroes its histogram counts by a write)
//     write   the same kernel on a buffer zeroed by clEnqueueWriteBuffer: nothing to report
//
// Prints "probe MODE: ..." with the buffer's first values on stdout and
// nothing on stderr (the plain OpenCL C API, no exceptions); exit 1 when a
// call other than the deliberately wrong one fails.
#define CL_TARGET_OPENCL_VERSION 120
#include <CL/cl.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

const char* source = R"CL(
__kernel void probe_clean(__global const float* in, __global float* out)
{
    uint j = get_global_id(0);
    out[j] = 2.0f * in[j];
}
__kernel void probe_oob(__global const float* in, __global float* out)
{
    uint j = get_global_id(0);
    out[j + 1u] = 2.0f * in[j];  // the last work-item writes past the end
}
__kernel void probe_race(__global const float* in, __global float* out)
{
    out[0] = in[get_global_id(0)];  // every work-item, the same address
}
__kernel void probe_add(__global uint* counts)
{
    atomic_add(&counts[get_global_id(0) % 4u], 1u);
}
)CL";

constexpr std::size_t n = 64, group = 16;

int fail(const char* what, cl_int error)
{
    std::printf("probe: %s failed with OpenCL error %d\n", what, error);
    return 1;
}

} // namespace

int main(int argc, char** argv)
{
    const std::string mode = argc == 2 ? argv[1] : "";
    const char* modes[] = {"clean", "oob", "uninit", "race", "api", "fill", "write"};
    bool known = false;
    for (const char* m : modes)
        known = known || mode == m;
    if (!known) {
        std::printf("usage: oclgrind_probe clean|oob|uninit|race|api|fill|write\n");
        return 2;
    }
    cl_int error = CL_SUCCESS;
    cl_platform_id platform;
    cl_device_id device;
    if ((error = clGetPlatformIDs(1, &platform, nullptr)) != CL_SUCCESS)
        return fail("clGetPlatformIDs", error);
    if ((error = clGetDeviceIDs(platform, CL_DEVICE_TYPE_ALL, 1, &device, nullptr)) != CL_SUCCESS)
        return fail("clGetDeviceIDs", error);
    cl_context context = clCreateContext(nullptr, 1, &device, nullptr, nullptr, &error);
    if (error != CL_SUCCESS)
        return fail("clCreateContext", error);
    cl_command_queue queue = clCreateCommandQueue(context, device, 0, &error);
    if (error != CL_SUCCESS)
        return fail("clCreateCommandQueue", error);
    cl_program program = clCreateProgramWithSource(context, 1, &source, nullptr, &error);
    if (error != CL_SUCCESS)
        return fail("clCreateProgramWithSource", error);
    if ((error = clBuildProgram(program, 1, &device, "", nullptr, nullptr)) != CL_SUCCESS)
        return fail("clBuildProgram", error);

    cl_mem in = clCreateBuffer(context, CL_MEM_READ_WRITE, n * sizeof(float), nullptr, &error);
    cl_mem out = clCreateBuffer(context, CL_MEM_READ_WRITE, n * sizeof(float), nullptr, &error);
    if (error != CL_SUCCESS)
        return fail("clCreateBuffer", error);
    std::vector<float> values(n);
    for (std::size_t j = 0; j < n; ++j)
        values[j] = float(j);
    if (mode != "uninit" && mode != "fill" && mode != "write")
        if ((error = clEnqueueWriteBuffer(queue, in, CL_TRUE, 0, n * sizeof(float), values.data(), 0, nullptr,
                                          nullptr)) != CL_SUCCESS)
            return fail("clEnqueueWriteBuffer", error);

    const bool add = mode == "fill" || mode == "write";
    const char* name = add ? "probe_add" : mode == "oob" ? "probe_oob" : mode == "race" ? "probe_race" : "probe_clean";
    cl_kernel kernel = clCreateKernel(program, name, &error);
    if (error != CL_SUCCESS)
        return fail("clCreateKernel", error);
    if (add) {
        const cl_uint zeros[4] = {0u, 0u, 0u, 0u};
        const cl_uint zero = 0u;
        error = mode == "fill"
                    ? clEnqueueFillBuffer(queue, out, &zero, sizeof zero, 0, sizeof zeros, 0, nullptr, nullptr)
                    : clEnqueueWriteBuffer(queue, out, CL_TRUE, 0, sizeof zeros, zeros, 0, nullptr, nullptr);
        if (error != CL_SUCCESS)
            return fail(mode == "fill" ? "clEnqueueFillBuffer" : "clEnqueueWriteBuffer", error);
        clSetKernelArg(kernel, 0, sizeof out, &out);
    } else {
        clSetKernelArg(kernel, 0, sizeof in, &in);
        clSetKernelArg(kernel, 1, sizeof out, &out);
    }
    const std::size_t global = n, local = mode == "api" ? 7 : group;
    error = clEnqueueNDRangeKernel(queue, kernel, 1, nullptr, &global, &local, 0, nullptr, nullptr);
    if (mode == "api") {
        std::printf("probe api: clEnqueueNDRangeKernel returned %d (CL_INVALID_WORK_GROUP_SIZE is %d)\n", error,
                    CL_INVALID_WORK_GROUP_SIZE);
        return error == CL_INVALID_WORK_GROUP_SIZE ? 0 : 1;
    }
    if (error != CL_SUCCESS)
        return fail("clEnqueueNDRangeKernel", error);
    std::vector<cl_uint> result(n);
    if ((error = clEnqueueReadBuffer(queue, out, CL_TRUE, 0, (add ? 4 : 1) * sizeof(cl_uint), result.data(), 0,
                                     nullptr, nullptr)) != CL_SUCCESS)
        return fail("clEnqueueReadBuffer", error);
    if (add)
        std::printf("probe %s: counts %u %u %u %u (expected %zu each)\n", mode.c_str(), result[0], result[1],
                    result[2], result[3], n / 4);
    else
        std::printf("probe %s: ran %zu work-items\n", mode.c_str(), n);
    clReleaseKernel(kernel);
    clReleaseMemObject(in);
    clReleaseMemObject(out);
    clReleaseProgram(program);
    clReleaseCommandQueue(queue);
    clReleaseContext(context);
    return add && !(result[0] == n / 4 && result[1] == n / 4 && result[2] == n / 4 && result[3] == n / 4) ? 1 : 0;
}
