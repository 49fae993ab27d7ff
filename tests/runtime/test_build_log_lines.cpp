// test_build_log_lines.cpp - build logs mapped back to the files of a
// program's #line markers (lib/src/core/build_log_lines.hpp), on the host: the
// location forms of the OpenCL compilers that ignore the markers, the logs
// of those that honour them left as they are, a user sampler's program as
// the library assembles it, and a user sampler's build summary starting
// with the user's file and line.
#include <doctest/doctest.h>

#include <algorithm>

#include <ggxcl/user_sampler.hpp>

#include "build_log_lines.hpp"

namespace {

using ggxcl::detail::map_build_log;
using ggxcl::detail::program_lines;

// A program assembled like the library's: a kernel file including a header, then a user's file.
//   physical line:  1 `#line 1 "main.cl"`, 2-3 main.cl:1-2, 4 `#line 1 "inc.h"`, 5-6 inc.h:1-2,
//   7 `#line 4 "main.cl"`, 8 main.cl:4, 9 `#line 9 "/u/my file.h"`, 10-11 /u/my file.h:9-10
const std::string source = "#line 1 \"main.cl\"\n"
                           "kernel void k()\n"
                           "{\n"
                           "#line 1 \"inc.h\"\n"
                           "float f(float x)\n"
                           "{ return x }\n"
                           "#line 4 \"main.cl\"\n"
                           "}\n"
                           "#line 9 \"/u/my file.h\"\n"
                           "float g()\n"
                           "{ return 1 }\n";

std::string mapped(const std::string& log)
{
    return map_build_log(log, program_lines(source));
}

} // namespace

TEST_CASE("the table: each physical line's file and line, nothing for directives")
{
    const ggxcl::detail::ProgramLines lines = program_lines(source);
    REQUIRE(lines.lines.size() == 12);  // the empty line after the last newline counts
    CHECK(lines.lines[0].file.empty());
    CHECK(lines.lines[1].file == "main.cl");
    CHECK(lines.lines[1].line == 1);
    CHECK(lines.lines[5].file == "inc.h");
    CHECK(lines.lines[5].line == 2);
    CHECK(lines.lines[7].file == "main.cl");
    CHECK(lines.lines[7].line == 4);
    CHECK(lines.lines[8].file.empty());
    CHECK(lines.files == std::set<std::string>{"main.cl", "inc.h", "/u/my file.h"});
}

TEST_CASE("the line right after #line 9 \"f\" is f:9 (not 8, not 10)")
{
    const std::string program = "#line 9 \"f\"\nx\ny\n";
    CHECK(map_build_log("<kernel>:2:1: error: a\n", program_lines(program)) == "f:9:1: error: a\n");
    CHECK(map_build_log("<kernel>:3:1: error: b\n", program_lines(program)) == "f:10:1: error: b\n");
}

TEST_CASE("lines before the first directive and directive lines are left as printed")
{
    const std::string program = "a\n#line 5 \"f\"\nb\n";
    CHECK(map_build_log("<kernel>:1:1: error: x\n", program_lines(program)) == "<kernel>:1:1: error: x\n");
    CHECK(map_build_log("<kernel>:2:1: error: x\n", program_lines(program)) == "<kernel>:2:1: error: x\n");
    CHECK(map_build_log("<kernel>:3:1: error: x\n", program_lines(program)) == "f:5:1: error: x\n");
    CHECK(map_build_log("<kernel>:1:1: error: x\n", program_lines("no markers\n")) == "<kernel>:1:1: error: x\n");
}

TEST_CASE("NVIDIA's <kernel>:L:C, with the source line and caret kept")
{
    const std::string log = "<kernel>:11:11: error: expected ';' after return statement\n"
                            "{ return 1 }\n"
                            "          ^\n"
                            "          ;\n";
    CHECK(mapped(log) == "/u/my file.h:10:11: error: expected ';' after return statement\n"
                         "{ return 1 }\n"
                         "          ^\n"
                         "          ;\n");
}

TEST_CASE("NVIDIA's logs as its driver printed them (580.159.04, H200) give what PoCL prints for the same programs")
{
    const std::string two_files = "#line 1 \"main.cl\"\nkernel void k(global float* x)\n{\n"
                                  "#line 9 \"/u/my file.h\"\n  x[0] = 1\n  x[1] = y;\n}\n";
    const std::string nvidia = "<kernel>:5:11: error: expected ';' after expression\n  x[0] = 1\n          ^\n"
                               "          ;\n<kernel>:6:10: error: use of undeclared identifier 'y'\n"
                               "  x[1] = y;\n         ^\n";
    CHECK(map_build_log(nvidia, program_lines(two_files)) ==
          "/u/my file.h:9:11: error: expected ';' after expression\n  x[0] = 1\n          ^\n"
          "          ;\n/u/my file.h:10:10: error: use of undeclared identifier 'y'\n"
          "  x[1] = y;\n         ^\n");
    const std::string directive_error = "#line 1 \"a.cl\"\n#error \"stop here\"\nkernel void k(){}\n";
    const std::string excerpt = " error: \"stop here\"\n#error \"stop here\"\n ^\n";
    CHECK(map_build_log("<kernel>:2:2:" + excerpt, program_lines(directive_error)) == "a.cl:1:2:" + excerpt);
    const std::string before_markers = "int f(){ return 1 }\n#line 40 \"b.h\"\n"
                                       "kernel void k(global int* x){ x[0] = f() +; }\n";
    CHECK(map_build_log("<kernel>:1:18: error: expected ';'\n<kernel>:3:43: error: expected expression\n",
                        program_lines(before_markers)) ==
          "<kernel>:1:18: error: expected ';'\nb.h:40:43: error: expected expression\n");
}

TEST_CASE("<source>, input.cl and a temporary file's path as the program's name")
{
    CHECK(mapped("<source>:10:1: error: x") == "/u/my file.h:9:1: error: x");
    CHECK(mapped("input.cl:2:8: warning: y\n") == "main.cl:1:8: warning: y\n");
    CHECK(mapped("/tmp/abc.cl:8:1: error: z\n") == "main.cl:4:1: error: z\n");
    CHECK(mapped("/tmp/main.cl:2:1: error: z\n") == "main.cl:1:1: error: z\n");  // not the marker's name
}

TEST_CASE("a location without a column")
{
    CHECK(mapped("<kernel>:6: error: expected ';'\n") == "inc.h:2: error: expected ';'\n");
    CHECK(mapped("input.cl:3: note: here\n") == "main.cl:2: note: here\n");
}

TEST_CASE("a line inside an included file maps to that file, and so does 'In file included from'")
{
    CHECK(mapped("In file included from <kernel>:3:\n<kernel>:6:12: error: expected ';'\n") ==
          "In file included from main.cl:2:\n"
          "inc.h:2:12: error: expected ';'\n");
}

TEST_CASE("several errors in one log, each mapped, the text between them kept")
{
    const std::string log = "<kernel>:6:12: error: expected ';' after return statement\n"
                            "{ return x }\n"
                            "\t<kernel>:11:11: error: expected ';' after return statement\n"
                            "2 errors generated.\n";
    CHECK(mapped(log) == "inc.h:2:12: error: expected ';' after return statement\n"
                         "{ return x }\n"
                         "\t/u/my file.h:10:11: error: expected ';' after return statement\n"
                         "2 errors generated.\n");
}

TEST_CASE("PoCL's 'error: FILE:L:C:' form after whitespace is mapped when FILE is the program's name")
{
    CHECK(mapped("error: <kernel>:11:11: expected ';'\n") == "error: /u/my file.h:10:11: expected ';'\n");
}

TEST_CASE("logs that already name the marker files (clang, PoCL) are left byte for byte")
{
    const std::string clang = "main.cl:2:4: error: unknown type name 'kernal'\n"
                              "In file included from main.cl:3:\n"
                              "inc.h:2:12: error: expected ';' after return statement\r\n"
                              "/u/my file.h:10:11: error: expected ';' after return statement\n"
                              "2 errors generated.\n";
    CHECK(mapped(clang) == clang);
    const std::string pocl = "error: /u/my file.h:9:46: expected ';' after return statement\n"
                             "Device pthread-skylake failed to build the program\n";
    CHECK(mapped(pocl) == pocl);
}

TEST_CASE("line numbers past the end or 0, and text that is no location, are left alone")
{
    CHECK(mapped("<kernel>:13:1: error: x\n") == "<kernel>:13:1: error: x\n");
    CHECK(mapped("<kernel>:0:1: error: x\n") == "<kernel>:0:1: error: x\n");
    CHECK(mapped("<kernel>:99999999999:1: error: x\n") == "<kernel>:99999999999:1: error: x\n");
    CHECK(mapped("a:b: 3:4 :5: http://h:2/ 12:x\n") == "a:b: 3:4 :5: http://h:2/ 12:x\n");
    CHECK(mapped("") == "");
}

TEST_CASE("a user sampler's summary starts with its file and line, from NVIDIA's mapped log and from PoCL's")
{
    const std::string prefix = "the user sampler does not compile: ";
    const std::string nvidia = mapped("<kernel>:11:11: error: expected ';' after return statement\n{ return 1 }\n");
    CHECK(ggxcl::user_build_summary(nvidia) ==
          prefix + "/u/my file.h:10:11: error: expected ';' after return statement");
    const std::string pocl = "error: /u/my file.h:10:11: expected ';'\nDevice x failed to build the program\n";
    CHECK(ggxcl::user_build_summary(pocl) == prefix + "/u/my file.h:10:11: error: expected ';'");
    const std::string warned = "syntax_error.h:3:1: warning: w\nsyntax_error.h:9:4: error: e\n";
    CHECK(ggxcl::user_build_summary(warned) == prefix + "syntax_error.h:9:4: error: e");  // not the warning
    CHECK(ggxcl::user_build_summary("no such line\n") == "the user sampler does not compile");
}

TEST_CASE("the library's own assembly: NVIDIA's physical line of a user sampler's line 9 maps to it")
{
    const std::string path = std::string(GGX_USER_SAMPLERS_DIR) + "/syntax_error.h";
    const auto sampler = ggxcl::UserSampler::load(path);
    const std::string program = ggxcl::program_source("ggx_bulk.cl", ggxcl::user_sampler_options(*sampler));
    const std::string line9 = "    return ggx_sample_caps(i, ax, ay, u1, u2)\n}";
    const std::size_t at = program.find(line9);
    REQUIRE(at != std::string::npos);
    const long physical = 1 + static_cast<long>(std::count(program.begin(), program.begin() + at, '\n'));
    CHECK(physical > 1000);  // after the kernel file and the device headers
    const std::string message = "error: expected ';' after return statement\n";
    const std::string log = "<kernel>:" + std::to_string(physical) + ":46: " + message;
    CHECK(map_build_log(log, program_lines(program)) == path + ":9:46: " + message);
    const std::string in_kernel = "<kernel>:2:1: error: x\n";  // line 1 of ggx_bulk.cl is its #line marker
    CHECK(map_build_log(in_kernel, program_lines(program)) == "ggx_bulk.cl:1:1: error: x\n");
}
