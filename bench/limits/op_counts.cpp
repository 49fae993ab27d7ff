// op_counts.cpp - counting a kernel's operations by class in LLVM IR text:
// one line per instruction, its opcode (or callee) and its lane count.
#include "op_counts.hpp"

#include <cctype>
#include <initializer_list>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace ggxapp {

namespace {

struct Cost {
    OpClass op_class;
    double ops;
};

using Names = std::initializer_list<const char*>;

bool among(Names names, const std::string& name)
{
    for (const char* known : names)
        if (name == known)
            return true;
    return false;
}

// Instructions that move or address data and compute nothing.
bool is_free_opcode(const std::string& opcode)
{
    return among({"load", "store", "getelementptr", "alloca", "br", "switch", "ret", "phi", "bitcast", "trunc", "zext",
                  "sext", "ptrtoint", "inttoptr", "addrspacecast", "extractelement", "insertelement", "shufflevector",
                  "extractvalue", "insertvalue", "freeze", "unreachable", "fence"},
                 opcode);
}

bool is_float_type(const std::string& type)
{
    return type.find("float") != std::string::npos || type.find("double") != std::string::npos ||
           type.find("half") != std::string::npos;
}

// The lanes of the first vector type `<N x T>` in `text`; 1 when there is none.
int lanes_of(const std::string& text)
{
    std::size_t open = text.find('<');
    while (open != std::string::npos) {
        std::size_t digits = open + 1;
        while (digits < text.size() && std::isdigit(static_cast<unsigned char>(text[digits])))
            ++digits;
        if (digits > open + 1 && text.compare(digits, 3, " x ") == 0)
            return std::stoi(text.substr(open + 1, digits - open - 1));
        open = text.find('<', open + 1);
    }
    return 1;
}

// The cost of an instruction by its opcode; `rest` is the text after the opcode.  False: not known.
bool opcode_cost(const std::string& opcode, const std::string& rest, Cost& cost)
{
    if (among({"add", "sub", "and", "or", "xor", "shl", "lshr", "ashr", "icmp"}, opcode))
        return cost = {OpClass::int_op, 1}, true;
    if (among({"fadd", "fsub", "fmul", "fneg", "fcmp", "sitofp", "uitofp", "fptosi", "fptoui", "fpext", "fptrunc"},
              opcode))
        return cost = {OpClass::float_op, 1}, true;
    if (opcode == "mul") {
        const bool wide = rest.find("i64") != std::string::npos || rest.find("i128") != std::string::npos;
        return cost = {wide ? OpClass::int_mul_wide : OpClass::int_mul, 1}, true;
    }
    if (among({"fdiv", "frem", "udiv", "sdiv", "urem", "srem"}, opcode))
        return cost = {OpClass::division, 1}, true;
    if (opcode == "select") {  // select [flags] COND %c, TYPE %a, TYPE %b: the class of the values
        std::size_t comma = rest.find(',');
        const bool floats = comma != std::string::npos && is_float_type(rest.substr(comma, rest.find(',', comma + 1) - comma));
        return cost = {floats ? OpClass::float_op : OpClass::int_op, 1}, true;
    }
    return false;
}

// LLVM intrinsics by name without their type suffix ("llvm.fmuladd").
bool intrinsic_cost(const std::string& name, Cost& cost, bool& free)
{
    auto matches = [&](Names known) {
        for (const std::string k : known)
            if (name == k || name.rfind(k + ".", 0) == 0)
                return true;
        return false;
    };
    if (matches({"llvm.experimental.noalias.scope.decl", "llvm.lifetime.start", "llvm.lifetime.end", "llvm.assume",
                 "llvm.dbg.value", "llvm.dbg.declare"}))
        return free = true, true;
    if (matches({"llvm.fmuladd", "llvm.fma", "llvm.fabs", "llvm.copysign", "llvm.minnum", "llvm.maxnum",
                 "llvm.minimum", "llvm.maximum", "llvm.rint", "llvm.floor", "llvm.ceil", "llvm.trunc", "llvm.round",
                 "llvm.nearbyint", "llvm.roundeven"}))
        return cost = {OpClass::float_op, 1}, true;
    if (matches({"llvm.umin", "llvm.umax", "llvm.smin", "llvm.smax", "llvm.abs", "llvm.bitreverse", "llvm.ctlz",
                 "llvm.cttz", "llvm.ctpop", "llvm.fshl", "llvm.fshr", "llvm.bswap"}))
        return cost = {OpClass::int_op, 1}, true;
    if (matches({"llvm.sqrt"}))
        return cost = {OpClass::sqrt, 1}, true;
    return false;
}

// Whether a mangled parameter list starts with a float type: f, d, h, or a vector of them ("Dv4_f").
bool first_param_is_float(const std::string& params)
{
    std::size_t at = params.rfind("Dv", 0) == 0 ? params.find('_') + 1 : 0;  // no '_': npos + 1 = 0
    return at < params.size() && std::string("fdh").find(params[at]) != std::string::npos;
}

// An OpenCL builtin by its Itanium-mangled name: "_Z4sqrtf" is sqrt of a float.
bool builtin_cost(const std::string& mangled, Cost& cost, bool& free)
{
    if (mangled.rfind("_Z", 0) != 0)
        return false;
    std::size_t at = 2, digits = 2;
    while (digits < mangled.size() && std::isdigit(static_cast<unsigned char>(mangled[digits])))
        ++digits;
    if (digits == at)
        return false;
    const std::size_t length = std::stoul(mangled.substr(at, digits - at));
    if (digits + length > mangled.size())
        return false;
    const std::string name = mangled.substr(digits, length), params = mangled.substr(digits + length);
    const bool floats = first_param_is_float(params);
    if (among({"get_global_id", "get_global_size", "get_local_id", "get_local_size", "get_group_id", "get_num_groups",
               "get_global_offset", "get_work_dim", "barrier"},
              name))
        return free = true, true;
    const OpClass typed = floats ? OpClass::float_op : OpClass::int_op;
    if (name == "clamp")
        return cost = {typed, 2}, true;
    if (!floats && (name == "mul24" || name == "mul_hi"))
        return cost = {name == "mul24" ? OpClass::int_mul : OpClass::int_mul_wide, 1}, true;
    const Names float_builtins = {"fma",  "mad",   "fabs", "fmin",   "fmax",  "min",   "max",      "copysign", "rint",
                                  "floor", "ceil", "trunc", "round", "step", "select", "isnan", "isinf", "isfinite",
                                  "signbit"};
    if (among(floats ? float_builtins : Names{"min", "max", "abs", "rotate", "clz", "popcount", "select"}, name))
        return cost = {typed, 1}, true;
    if (among({"sqrt", "rsqrt", "half_sqrt", "half_rsqrt", "native_sqrt", "native_rsqrt"}, name))
        return cost = {OpClass::sqrt, 1}, true;
    if (among({"native_divide", "half_divide", "native_recip", "half_recip"}, name))
        return cost = {OpClass::division, 1}, true;
    return false;
}

// The callee of a call instruction ("llvm.fmuladd.f32", "_Z4sqrtf"); empty for an indirect call.
std::string callee_of(const std::string& rest)
{
    std::size_t at = rest.find('@');
    if (at == std::string::npos)
        return "";
    std::size_t end = rest.find('(', at);
    return rest.substr(at + 1, end == std::string::npos ? std::string::npos : end - at - 1);
}

// One instruction line into `counts`.
void count_instruction(const std::string& line, OpCounts& counts)
{
    std::istringstream words(line);
    std::string word;
    words >> word;
    if (!word.empty() && word[0] == '%') {
        std::string equals;
        words >> equals >> word;  // "%x = opcode"
    }
    while (word == "tail" || word == "musttail" || word == "notail")
        words >> word;
    std::string rest;
    std::getline(words, rest);
    const std::string& opcode = word;
    if (is_free_opcode(opcode))
        return;
    Cost cost{};
    if (opcode == "call") {
        const std::string callee = callee_of(rest);
        bool free = false;
        if (intrinsic_cost(callee, cost, free) || builtin_cost(callee, cost, free)) {
            if (!free)
                counts[cost.op_class] += cost.ops * lanes_of(rest.substr(0, rest.find('@')));
            return;
        }
        ++counts.other["call " + (callee.empty() ? std::string("(indirect)") : callee)];
        return;
    }
    if (opcode_cost(opcode, rest, cost)) {
        counts[cost.op_class] += cost.ops * lanes_of(rest);
        return;
    }
    ++counts.other[opcode];
}

// Instructions are indented; block labels ("12:", "entry:") and the function's lines are not.
bool is_instruction(const std::string& line)
{
    std::size_t first = line.find_first_not_of(" \t");
    return first != 0 && first != std::string::npos && line[first] != ';';
}

} // namespace

const char* op_class_name(OpClass op_class)
{
    switch (op_class) {
    case OpClass::float_op: return "float";
    case OpClass::int_op: return "int";
    case OpClass::int_mul: return "int mul";
    case OpClass::int_mul_wide: return "int mul64";
    case OpClass::sqrt: return "sqrt";
    case OpClass::division: return "div";
    }
    return "?";
}

double OpCounts::total() const
{
    double sum = 0;
    for (double count : of)
        sum += count;
    return sum;
}

OpCounts OpCounts::per(double samples) const
{
    OpCounts out = *this;
    for (double& count : out.of)
        count /= samples;
    return out;
}

std::string OpCounts::other_text() const
{
    std::string text;
    for (const auto& [name, count] : other)
        text += (text.empty() ? "" : ", ") + name + " x " + std::to_string(count);
    return text;
}

OpCounts count_kernel_ops(const std::string& ll_text, const std::string& kernel)
{
    std::istringstream lines(ll_text);
    std::string line;
    const std::string signature = "@" + kernel + "(";
    bool inside = false, found = false;
    OpCounts counts;
    while (std::getline(lines, line)) {
        if (!inside) {
            inside = line.rfind("define ", 0) == 0 && line.find(signature) != std::string::npos;
            found = found || inside;
            continue;
        }
        if (line.rfind("}", 0) == 0)
            break;
        if (is_instruction(line))
            count_instruction(line, counts);
    }
    if (!found)
        throw std::runtime_error("no function @" + kernel + " in the LLVM IR");
    return counts;
}

OpCounts count_kernel_ops_strict(const std::string& ll_text, const std::string& kernel)
{
    OpCounts counts = count_kernel_ops(ll_text, kernel);
    if (!counts.other.empty())
        throw std::runtime_error("@" + kernel + " has operations of no known class: " + counts.other_text());
    return counts;
}

} // namespace ggxapp
