// fault_injection.cpp - GGXCL_INJECT_FAULT parsed and counted (see
// fault_injection.hpp).
#include "fault_injection.hpp"

#include <atomic>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <string>

#include "ggxcl/error.hpp"

namespace ggxcl::detail {

namespace {

std::uint64_t parse_amount(const std::string& spec, const std::string& text)
{
    std::size_t used = 0;
    unsigned long long value = 0;
    try {
        value = std::stoull(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used == 0 || used != text.size() || text[0] == '-')
        throw InvalidArgument("GGXCL_INJECT_FAULT", spec, "alloc-above=BYTES or lost-after=LAUNCHES (whole numbers)");
    return value;
}

InjectedFault parse_fault(const std::string& spec)
{
    InjectedFault fault;
    const std::string alloc = "alloc-above=", lost = "lost-after=";
    if (spec.rfind(alloc, 0) == 0) {
        fault.alloc_above = parse_amount(spec, spec.substr(alloc.size()));
    } else if (spec.rfind(lost, 0) == 0) {
        fault.lost_after = parse_amount(spec, spec.substr(lost.size()));
        fault.lost = true;
    } else if (!spec.empty()) {
        parse_amount(spec, "");  // throws, naming the forms allowed
    }
    return fault;
}

} // namespace

InjectedFault injected_fault(bool count_launch, std::uint64_t& launches_before)
{
    static std::mutex mutex;
    static std::atomic<bool> ever_set{false};
    static std::string last_spec;
    static std::exception_ptr refused;  // the InvalidArgument of a malformed value
    static InjectedFault fault;
    static std::uint64_t launches = 0;
    const char* env = std::getenv("GGXCL_INJECT_FAULT");
    if (env == nullptr && !ever_set.load(std::memory_order_acquire)) {
        launches_before = 0;
        return {};
    }
    ever_set.store(true, std::memory_order_release);
    std::string spec = env ? env : "";
    std::lock_guard<std::mutex> lock(mutex);
    if (spec != last_spec) {
        last_spec = spec;
        launches = 0;
        fault = {};
        refused = nullptr;
        try {
            fault = parse_fault(spec);
        } catch (const InvalidArgument&) {
            refused = std::current_exception();
        }
    }
    if (refused)
        std::rethrow_exception(refused);
    launches_before = launches;
    launches += count_launch ? 1 : 0;
    return fault;
}

} // namespace ggxcl::detail
