// ggx_furnace.cl - the fused white-furnace estimator: nothing per sample is
// stored.  Each work-item draws GGX_FURNACE_PER_ITEM samples (an unrolled
// straight line, so PoCL still vectorizes across work-items) and writes the
// sum of their estimator weights and the sum of their squares; the host adds
// these partial sums in double and forms the albedo estimate (the mean
// weight) and its variance.  No barriers: a barrier-based reduction in local
// memory costs more than the sampling on PoCL.
//
// Build options: those of ggx_bulk.cl (method, precision, per-sample and
// specialization flags; GGX_WRITE_MASK is ignored).  GGX_FURNACE_PER_ITEM is
// in ggx_contract.h.
// Work-item w of a launch of `count` samples draws samples
// GGX_FURNACE_PER_ITEM * w + k (k < GGX_FURNACE_PER_ITEM) that are < count,
// so the partial sums depend neither on the work-group size nor, for
// launches that start at multiples of GGX_FURNACE_PER_ITEM, on how a range
// is split into launches.  Output (items = global size): sums[w] = sum of
// its weights, sums[items + w] = sum of their squares, and with
// GGX_DIELECTRIC sums[2 items + w] = the sum of the weights of its
// reflected samples (o on the view's side): the reflectance's part.
#ifndef GGX_METHOD
#error "build with -DGGX_METHOD=<method id>"
#endif
#include "ggx_bulk_params.h"

__kernel void ggx_furnace_bulk(ulong seed, ulong first, uint count, uint stride, GGX_PARAM_KERNEL_ARGS,
                               __global float* GGX_RESTRICT sums_out, ulong sums_at)
{
    __global float* GGX_RESTRICT sums = sums_out + sums_at;
    uint item = (uint)get_global_id(0), items = (uint)get_global_size(0);
    float w_total = 0.0f, w2_total = 0.0f, reflected_total = 0.0f;
#pragma unroll
    for (uint k = 0; k < GGX_FURNACE_PER_ITEM; ++k) {
        uint index = item * GGX_FURNACE_PER_ITEM + k;
        uint j = min(index, count - 1u);  // past `count`: recompute the last sample, then count it as 0
        ggx_params p = ggx_load_params(j, stride, GGX_PARAM_VALUES_AT);
        ggx_sample s = ggx_bulk_sample(seed, first, j, p);
        float w = index < count ? s.weight : 0.0f;
        w_total += w;
        w2_total += w * w;
#if GGX_DIELECTRIC
        reflected_total += ggx_bulk_reflected(p, s) ? w : 0.0f;
#endif
    }
    sums[item] = w_total;
    sums[items + item] = w2_total;
#if GGX_DIELECTRIC
    sums[2u * items + item] = reflected_total;
#else
    (void)reflected_total;
#endif
}
