// report_text.cpp - the reports' date line, chart links and readable numbers.
#include "report_text.hpp"

#include <cmath>
#include <ctime>
#include <filesystem>
#include <iomanip>
#include <sstream>

namespace ggxapp {

std::string utc_now()
{
    std::time_t now = std::time(nullptr);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
    return text;
}

std::string relative_to(const std::string& path, const std::string& page)
{
    if (page.empty())
        return path;
    std::filesystem::path folder = std::filesystem::absolute(page).parent_path();
    return std::filesystem::relative(std::filesystem::absolute(path), folder).string();
}

std::string charts_prefix(const std::string& charts, const std::string& html)
{
    if (!charts.empty() || html.empty())
        return charts;
    return std::filesystem::path(html).replace_extension().string();
}

namespace {

// "1.20e-07" -> "1.2e-7": no trailing zeros in the mantissa, no padding in the exponent.
std::string short_scientific(double value, int significant)
{
    std::ostringstream out;
    out.precision(significant - 1);
    out << std::scientific << value;
    std::string text = out.str();
    const std::size_t e = text.find('e');
    std::string mantissa = text.substr(0, e), exponent = text.substr(e + 1);
    if (mantissa.find('.') != std::string::npos) {
        mantissa.erase(mantissa.find_last_not_of('0') + 1);
        if (mantissa.back() == '.')
            mantissa.pop_back();
    }
    const bool negative = exponent[0] == '-';
    exponent.erase(0, exponent.find_first_not_of("+-0"));
    return mantissa + "e" + (negative ? "-" : "") + (exponent.empty() ? "0" : exponent);
}

} // namespace

std::string fixed(double value, int digits)
{
    std::ostringstream out;
    out << std::fixed << std::setprecision(digits) << value;
    return out.str();
}

std::string readable_number(double value, int significant)
{
    if (value == 0.0 || !std::isfinite(value)) {
        std::ostringstream out;
        out << value;
        return out.str();
    }
    const double size = std::fabs(value);
    if (size < 1e-3 || size >= 1e6)
        return short_scientific(value, significant);
    const int digits_before = int(std::floor(std::log10(size))) + 1;  // 4.29: 1, 0.0123: -1
    std::ostringstream out;
    out.setf(std::ios::fixed);
    out.precision(std::max(0, significant - digits_before));
    out << value;
    return out.str();
}

std::string rate_text(double per_second, const std::string& unit)
{
    static const char* const prefixes[] = {"", " k", " M", " G", " T"};
    int k = 0;
    double value = per_second;
    while (std::fabs(value) >= 1000.0 && k < 4)
        value /= 1000.0, ++k;
    return readable_number(value) + prefixes[k] + " " + unit;
}

std::string duration_text(double ns)
{
    const double size = std::fabs(ns);
    if (size < 1e3)
        return readable_number(ns) + " ns";
    if (size < 1e6)
        return readable_number(ns / 1e3) + " us";
    if (size < 1e9)
        return readable_number(ns / 1e6) + " ms";
    return readable_number(ns / 1e9) + " s";
}

} // namespace ggxapp
