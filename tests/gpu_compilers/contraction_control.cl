// contraction_control.cl - the negative control of compile_programs.py's
// contraction check: without ggx_platform.h's FP_CONTRACT OFF, clang fuses
// this a * b + c into llvm.fmuladd, which the check must report.
__kernel void contracted(__global float* x)
{
    x[0] = x[1] * x[2] + x[3];
}
