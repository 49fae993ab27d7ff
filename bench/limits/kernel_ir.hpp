// kernel_ir.hpp - the LLVM IR of OpenCL C programs, by clang run at run time
// as the project's offline compiler (clang-15 -x cl -cl-std=CL1.2 -target
// spir64 -O3 -emit-llvm -S): how `ggx bench` sees the operations of the very
// source and options the Sampler builds.  The compiler is $GGXCL_CLANG when
// set, else clang-15 on PATH; where there is none, the reason is returned,
// never thrown, so that the bench carries on without it.
#pragma once

#include <string>
#include <vector>

namespace ggxapp {

struct ClangTool {
    std::string path;         // empty: not available
    std::string unavailable;  // why, when path is empty
};
ClangTool find_clang();

struct IrRequest {
    std::string source;   // OpenCL C, self-contained (includes expanded)
    std::string options;  // build options as a driver takes them, split at spaces
};

// The .ll text of every request, in order: each distinct (source, options) compiled once, up to
// `parallel` compilers at a time, in a temporary directory removed before returning.  Throws
// std::runtime_error with the command and clang's messages when a compile fails.
std::vector<std::string> compile_to_ir(const ClangTool& clang, const std::vector<IrRequest>& requests, int parallel);

} // namespace ggxapp
