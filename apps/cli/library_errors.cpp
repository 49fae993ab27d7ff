// library_errors.cpp - the library's InvalidArgument in the CLI's terms.
#include "library_errors.hpp"

namespace ggxapp {

void rethrow_in_option_terms(const ggxcl::InvalidArgument& error, const OptionsOfParameters& options)
{
    std::string parameter = error.parameter();
    if (options.count(parameter) == 0 && (parameter == "alpha_x" || parameter == "alpha_y"))
        parameter = "alpha";  // one option sets both
    const auto found = options.find(parameter);
    if (found == options.end())
        throw error;
    throw UsageError(found->second.flag, found->second.text, error.allowed());
}

} // namespace ggxapp
