// stress_request.cpp - the checks of a stress request, shared by the back ends.
#include "stress_request.hpp"

#include <string>

#include "ggxcl/error.hpp"
#include "ggxcl/method.hpp"

namespace ggxcl::detail {

StressPlanes checked_stress(const StressRequest& request, const std::vector<float>& in, std::uint32_t count)
{
    const UserSampler* user = request.user;
    if ((request.method == Method::user) != (user != nullptr))
        throw InvalidArgument("stress user sampler", user ? user->name() : "none",
                              "a user sampler exactly when the method is user");
    if (user && request.dielectric)
        throw InvalidArgument("stress dielectric", "true", std::string("false for a user sampler (") + user->name() +
                                                               "): " + std::string(method_traits(Method::user).limits));
    const StressPlanes planes{request.dielectric ? 12u : 10u, request.dielectric ? 11u : 10u};
    if (in.size() != planes.in * count)
        throw InvalidArgument("stress inputs", std::to_string(in.size()) + " floats",
                              std::to_string(planes.in * count) + " (" + std::to_string(planes.in) + " planes of " +
                                  std::to_string(count) + " cases)");
    return planes;
}

std::string stress_defines(const StressRequest& request)
{
    return "-DGGX_METHOD=" + std::to_string(static_cast<int>(request.method)) +
           " -DGGX_GUARDS=" + (request.guards ? "1" : "0") +
           (request.user ? user_sampler_options(*request.user) : std::string()) +
           (request.dielectric ? " -DGGX_DIELECTRIC=1" : "");
}

} // namespace ggxcl::detail
