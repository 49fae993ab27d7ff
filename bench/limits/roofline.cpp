// roofline.cpp - the limits of a kernel from its op counts, the device's
// peaks and the store-only kernel's speed.
#include "roofline.hpp"

#include <stdexcept>
#include <string>

#include <ggxcl/cl/ggx_contract.h>

namespace ggxapp {

ComputeLimit compute_limit(const OpCounts& per_sample, const PeakRates& peaks)
{
    ComputeLimit limit;
    for (OpClass c : all_op_classes) {
        if (per_sample[c] == 0)
            continue;
        if (!(peaks[c] > 0))
            throw std::invalid_argument(std::string("peak of ") + op_class_name(c) + ": " + std::to_string(peaks[c]) +
                                        " ops/s; needs a positive rate");
        const double ns = per_sample[c] / peaks[c] * 1e9;
        limit.sum_ns += ns;
        if (ns > limit.ns)
            limit.ns = ns, limit.binding = c;
    }
    return limit;
}

double stored_bytes_per_sample(BenchJob job)
{
    switch (job) {
    case BenchJob::write: return 4 * sizeof(float);  // m (3 planes) and pdf_m
    case BenchJob::write_o: return 4 * sizeof(float);  // o (3 planes) and pdf_o
    case BenchJob::furnace: return 2.0 * sizeof(float) / GGX_FURNACE_PER_ITEM;
    case BenchJob::store: return 4 * sizeof(float);  // bench_speed.cpp's store_only: 4 floats per work-item
    case BenchJob::world:
    case BenchJob::per_sample: break;
    }
    throw std::invalid_argument("job " + job_name(job) + ": no bandwidth limit (it reads per sample); write, furnace or store");
}

double bandwidth_limit_ns(double bytes_per_sample, double store_ns_per_sample)
{
    return bytes_per_sample / stored_bytes_per_sample(BenchJob::store) * store_ns_per_sample;
}

double percent_of_limit(double limit_ns, double measured_ns)
{
    if (!(measured_ns > 0))
        throw std::invalid_argument("measured time " + std::to_string(measured_ns) + " ns; needs > 0");
    return 100.0 * limit_ns / measured_ns;
}

} // namespace ggxapp
