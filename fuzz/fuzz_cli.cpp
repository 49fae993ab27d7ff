// fuzz_cli.cpp - libFuzzer target: the whole `ggx` command line.  The input
// is split into argv tokens at '\n' and '\0' (fuzz/corpus/cli holds one
// token per line), parsed by the real app (GgxApp, every subcommand) and
// prepared: every option is checked, but the work is never run, so no
// device is opened, no file read or written and no Python started.
// Allowed outcomes: a CLI11 parse error (help included), a UsageError
// naming the flag, ggxcl::InvalidArgument, or exactly one prepared work
// whose batches the library accepts (unit view and normal, alpha within
// what --alpha allows, a range that does not wrap).  Anything else traps.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "cli_values.hpp"
#include "ggx_app.hpp"

namespace {

void check(bool ok)
{
    if (!ok)
        __builtin_trap();
}

// "ggx" followed by the input's tokens (empty ones kept, as a shell's '' would give).
std::vector<std::string> argv_tokens(const std::uint8_t* data, std::size_t size)
{
    std::vector<std::string> tokens{"ggx", ""};
    for (std::size_t k = 0; k < size; ++k)
        if (data[k] == '\n' || data[k] == '\0')
            tokens.emplace_back();
        else
            tokens.back() += char(data[k]);
    if (tokens.back().empty())  // a final newline ends the last token
        tokens.pop_back();
    return tokens;
}

bool unit(const ggxcl::Vec3& v)
{
    return std::fabs(std::sqrt(double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z) - 1.0) < 1e-6;
}

// What prepare promises of every batch: the library would not refuse it
// after a device is opened.
void check_batch(const ggxapp::Batch& batch)
{
    const ggxcl::SampleParams& p = batch.params;
    try {
        ggxcl::validate(p);
        ggxcl::validate(batch.range);
    } catch (const ggxcl::InvalidArgument&) {
        __builtin_trap();
    }
    check(unit(p.view) && unit(p.normal));
    check(p.alpha_x >= ggxcl::min_alpha && p.alpha_x <= ggxcl::max_alpha && p.alpha_y >= ggxcl::min_alpha &&
          p.alpha_y <= ggxcl::max_alpha);
}

void parse_and_prepare(const std::vector<std::string>& tokens)
{
    std::vector<const char*> argv;
    for (const std::string& token : tokens)
        argv.push_back(token.c_str());
    ggxapp::GgxApp app;
    app.cli.parse(int(argv.size()), argv.data());
    std::vector<ggxapp::Work> works = app.prepare();
    check(works.size() == 1 && works[0].run);
    for (const ggxapp::Batch& batch : works[0].batches)
        check_batch(batch);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    try {
        parse_and_prepare(argv_tokens(data, size));
    } catch (const CLI::ParseError&) {
    } catch (const ggxapp::UsageError& e) {
        std::string message = e.what();
        check(message.rfind("-", 0) == 0 || message.rfind("SHARD", 0) == 0);  // names the flag
    } catch (const ggxcl::InvalidArgument&) {
    } catch (...) {
        __builtin_trap();
    }
    return 0;
}
