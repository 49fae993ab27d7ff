// spill_control.cl - the negative controls of compile_programs.py: each
// kernel must fail the spill check on every GPU target.
//   private_array: a private array indexed at run time cannot live in
//     registers: scratch on AMD, a local-memory depot in PTX;
//   register_spill (AMD): 24 live sums in a kernel allowed 8 vector registers
//     must spill registers to scratch.
__kernel void private_array(__global float* out, __global const int* index)
{
    float table[512];
    for (int k = 0; k < 512; ++k)
        table[k] = out[k] * (float)k;
    size_t j = get_global_id(0);
    out[j] = table[index[j] & 511];
}

#ifdef __AMDGCN__
__kernel __attribute__((amdgpu_num_vgpr(8))) void register_spill(__global float* out)
{
    size_t j = get_global_id(0);
    float s[24];
#pragma unroll
    for (int k = 0; k < 24; ++k)
        s[k] = out[j + (size_t)k * 4096];
#pragma unroll
    for (int r = 0; r < 8; ++r)
#pragma unroll
        for (int k = 0; k < 24; ++k)
            s[k] = s[k] * s[(k + r + 1) % 24] + 1.0f;
    float total = 0.0f;
#pragma unroll
    for (int k = 0; k < 24; ++k)
        total += s[k];
    out[j] = total;
}
#endif
