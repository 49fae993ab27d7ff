// device_albedo.cpp - one row of cells at a time: our kernel writes the
// per-sample inputs, the runtime's sampler writes the weights into our
// buffer, our kernels sum them and draw the same sums themselves.
#include "device_albedo.hpp"

#include <cstring>
#include <string>

#include "albedo_kernels.hpp"

namespace albedo {

namespace {

cl::Buffer float_buffer(const cl::Context& context, std::size_t floats)
{
    return cl::Buffer(context, CL_MEM_READ_WRITE, floats * sizeof(float));
}

// The build options that make our in-kernel sampler the runtime's program
// for these inputs: the method, precise mode's options on this device
// (build_user_program adds the device's own), and for caps-iso the form for
// the normal +z (the general form samples the same distribution, rounded
// differently).
std::string options_for(ggxcl::Method method, const cl::Device& device)
{
    std::string options = "-DALBEDO_METHOD=" + std::to_string(static_cast<int>(method)) +
                          ggxcl::precision_options(device, ggxcl::Precision::precise);
    if (method == ggxcl::Method::caps_iso)
        options += " -DGGX_NORMAL_IS_Z=1";
    return options;
}

std::vector<float> read(cl::CommandQueue& queue, const cl::Buffer& buffer, std::size_t floats)
{
    std::vector<float> host(floats);
    queue.enqueueReadBuffer(buffer, CL_TRUE, 0, floats * sizeof(float), host.data());
    return host;
}

} // namespace

DeviceAlbedo::DeviceAlbedo(const cl::Context& context, const cl::Device& device, std::uint32_t samples_per_cell)
    : context_(context), device_(device), queue_(context, device), sampler_(context, device),
      per_cell_(samples_per_cell), row_samples_(table_size * samples_per_cell)
{
    std::vector<float> packed;
    for (const Cell& cell : table_cells())
        packed.insert(packed.end(), {cell.view_x, cell.view_z, cell.alpha});
    cells_ = cl::Buffer(context_, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, packed.size() * sizeof(float),
                        packed.data());
    const std::size_t blocks = row_samples_ / block;
    row_ = {float_buffer(context_, 3 * row_samples_), float_buffer(context_, 2 * row_samples_),
            float_buffer(context_, row_samples_),     float_buffer(context_, blocks),
            float_buffer(context_, blocks),           float_buffer(context_, blocks),
            float_buffer(context_, blocks)};
}

MethodSums DeviceAlbedo::run(ggxcl::Method method, std::uint64_t seed)
{
    const cl::Program program =
        ggxcl::build_user_program(context_, device_, albedo_kernels_source, options_for(method, device_));
    MethodSums out;
    for (CellSums* sums : {&out.runtime, &out.in_kernel}) {
        sums->sum.assign(cell_count, 0.0);
        sums->sum_of_squares.assign(cell_count, 0.0);
    }
    for (std::uint32_t row = 0; row < table_size; ++row) {
        enqueue_row(program, method, seed, row);
        add_row(row, out);
    }
    return out;
}

void DeviceAlbedo::enqueue_row(const cl::Program& program, ggxcl::Method method, std::uint64_t seed,
                               std::uint32_t row)
{
    const std::uint32_t first_cell = row * table_size, blocks = row_samples_ / block;
    // 1. Our kernel: the per-sample view and roughness of each sample of the row.
    cl::KernelFunctor<cl_uint, cl_uint, cl_uint, cl::Buffer, cl::Buffer, cl::Buffer> inputs(program, "cell_inputs");
    inputs(cl::EnqueueArgs(queue_, cl::NDRange(row_samples_)), first_cell, per_cell_, row_samples_, cells_,
           row_.views, row_.alphas);
    // 2. The runtime's sampler reads them and writes the weights into our buffer, on our queue.
    ggxcl::SampleParams params;
    params.method = method;
    params.precision = ggxcl::Precision::precise;
    ggxcl::DeviceInputs per_sample{row_.views, row_.alphas, cl::Buffer(), true, true};
    ggxcl::DeviceOutputs outputs;
    outputs.weight = row_.weights;
    sampler_.enqueue(queue_, params, {seed, std::uint64_t(first_cell) * per_cell_, row_samples_}, outputs,
                     row_samples_, per_sample);
    // 3. Our kernels: block sums of those weights, and the same sums with the sampler called in-kernel.
    cl::KernelFunctor<cl_uint, cl::Buffer, cl::Buffer, cl::Buffer> sums(program, "block_sums");
    sums(cl::EnqueueArgs(queue_, cl::NDRange(blocks)), block, row_.weights, row_.sums, row_.squares);
    cl::KernelFunctor<cl_ulong, cl_uint, cl_uint, cl_uint, cl::Buffer, cl::Buffer, cl::Buffer> drawn(
        program, "block_sums_inline");
    drawn(cl::EnqueueArgs(queue_, cl::NDRange(blocks)), seed, first_cell, per_cell_, block, cells_,
          row_.inline_sums, row_.inline_squares);
}

void DeviceAlbedo::add_row(std::uint32_t row, MethodSums& out)
{
    const std::uint32_t blocks = row_samples_ / block, blocks_per_cell = per_cell_ / block;
    const std::vector<float> parts[4] = {read(queue_, row_.sums, blocks), read(queue_, row_.squares, blocks),
                                         read(queue_, row_.inline_sums, blocks),
                                         read(queue_, row_.inline_squares, blocks)};
    for (std::uint32_t b = 0; b < blocks; ++b) {
        const std::uint32_t cell = row * table_size + b / blocks_per_cell;
        out.runtime.sum[cell] += parts[0][b];
        out.runtime.sum_of_squares[cell] += parts[1][b];
        out.in_kernel.sum[cell] += parts[2][b];
        out.in_kernel.sum_of_squares[cell] += parts[3][b];
        out.same_bits = out.same_bits && std::memcmp(&parts[0][b], &parts[2][b], sizeof(float)) == 0 &&
                        std::memcmp(&parts[1][b], &parts[3][b], sizeof(float)) == 0;
    }
}

} // namespace albedo
