// peak_probe.cl - the compute peak probe of `ggx bench` (bench_peak.cpp): one
// kernel per op class, each work-item running 8 chains of 32 dependent steps.
// One macro per class: a step of one chain, which reads the chain's value once (a step that read it
// twice, x = x * x, makes an expression whose paths double with every step: NVIDIA's compiler took
// minutes on it).  The int step is two ops (xor, add: alternating, so that no compiler folds the
// chain); the multiply's xor keeps compilers from folding the chain of multiplies into a power of a,
// and is not counted (it issues beside the multiply on GPUs; on a CPU the rate is a lower bound).
#define R2(S) S S
#define STEPS(S) R2(R2(R2(R2(R2(S)))))
#define EACH_CHAIN(OP) OP(x0) OP(x1) OP(x2) OP(x3) OP(x4) OP(x5) OP(x6) OP(x7)
#define PEAK_KERNEL(name, T, OP)                                                        \
    __kernel void name(__global T* restrict out, T a, T b)                              \
    {                                                                                   \
        uint j = (uint)get_global_id(0);                                                \
        T x0 = a + (T)(j & 255u) * b, x1 = x0 + b, x2 = x1 + b, x3 = x2 + b;            \
        T x4 = x3 + b, x5 = x4 + b, x6 = x5 + b, x7 = x6 + b;                           \
        STEPS(EACH_CHAIN(OP))                                                           \
        out[j] = ((x0 + x1) + (x2 + x3)) + ((x4 + x5) + (x6 + x7));                      \
    }
#define FMA_STEP(x) x = x * a + b;
#define INT_STEP(x) x = (x ^ a) + b;
#define MUL_STEP(x) x = (x * a) ^ b;
#define MUL64_STEP(x) x = (uint)(((ulong)x * 0xD256D193ul) >> 32);
#define SQRT_STEP(x) x = sqrt(x);
#define DIV_STEP(x) x = a / x;
PEAK_KERNEL(peak_float, float, FMA_STEP)
PEAK_KERNEL(peak_int, uint, INT_STEP)
PEAK_KERNEL(peak_int_mul, uint, MUL_STEP)
PEAK_KERNEL(peak_int_mul64, uint, MUL64_STEP)
PEAK_KERNEL(peak_sqrt, float, SQRT_STEP)
PEAK_KERNEL(peak_division, float, DIV_STEP)
