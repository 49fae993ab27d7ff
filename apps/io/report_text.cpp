// report_text.cpp - the reports' date line and chart links.
#include "report_text.hpp"

#include <ctime>
#include <filesystem>

namespace ggxapp {

std::string utc_now()
{
    std::time_t now = std::time(nullptr);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
    return text;
}

std::string relative_to(const std::string& path, const std::string& markdown)
{
    if (markdown.empty())
        return path;
    std::filesystem::path folder = std::filesystem::absolute(markdown).parent_path();
    return std::filesystem::relative(std::filesystem::absolute(path), folder).string();
}

} // namespace ggxapp
