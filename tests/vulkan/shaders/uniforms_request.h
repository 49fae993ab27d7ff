// uniforms_request.h - the body of the uniforms shaders, one text for GLSL
// (uniforms.comp) and HLSL (uniforms.hlsl): the uniforms of ggx_philox.h and
// ggx_sobol.h (64-bit integers) for sample first + j of stream seed, stored
// as planes: Philox u1, u2, u3; Sobol u1, u2, u3; Sobol per launch u1, u2,
// u3.  The including shader declares `request` and `values` first.
#include "ggx_sobol.h"

void ggx_test_uniforms(uint j)
{
    uint n = request.count;
    if (j >= n)
        return;
    ggx_ulong seed = (ggx_to_ulong(request.seed_hi) << 32) | ggx_to_ulong(request.seed_lo);
    ggx_ulong first = (ggx_to_ulong(request.first_hi) << 32) | ggx_to_ulong(request.first_lo);
    ggx_uniform_pair philox = ggx_philox_pair(seed, first + j), sobol = ggx_sobol_pair(seed, first + j);
    ggx_uniform_pair launch = ggx_sobol_launch_pair(seed, first, j);
    values[j] = philox.u1;
    values[n + j] = philox.u2;
    values[2 * n + j] = ggx_lobe_uniform(seed, first + j);
    values[3 * n + j] = sobol.u1;
    values[4 * n + j] = sobol.u2;
    values[5 * n + j] = ggx_sobol_lobe_uniform(seed, first + j);
    values[6 * n + j] = launch.u1;
    values[7 * n + j] = launch.u2;
    values[8 * n + j] = ggx_sobol_launch_lobe_uniform(seed, first, j);
}
