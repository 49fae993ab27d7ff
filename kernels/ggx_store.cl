// ggx_store.cl - the ceiling of the bench's write job
// (ggxcl::benchmark::Job::store): the bytes the write job stores, three
// planes of m and one of pdf_m, from values that cost nothing to compute.
__kernel void store_only(__global float* restrict m, __global float* restrict pdf_m, uint count, float seed)
{
    uint j = get_global_id(0);
    float x = (float)j * 1e-7f + seed;
    m[j] = x;
    m[j + count] = x + 1.0f;
    m[j + 2 * count] = x + 2.0f;
    pdf_m[j] = x + 3.0f;
}
