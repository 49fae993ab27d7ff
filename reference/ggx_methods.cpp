// ggx_methods.cpp - the reference's methods by name and id: taken from the project's one list
// of methods (GGX_METHOD_LIST of kernels/ggx_contract.h, names and ids only, no math), with
// ggxref::Method and all_methods checked against it at compile time.
#include "ggx_contract.h"
#include "ggx_reference.hpp"

namespace ggxref {

#define GGX_CHECKED_ENUM Method
#define GGX_CHECKED_ALL all_methods
GGX_METHOD_LIST(GGX_CHECK_METHOD_ENUM)
#undef GGX_CHECKED_ENUM
#undef GGX_CHECKED_ALL
static_assert(all_methods.size() == GGX_METHOD_COUNT, "every method of the list has its ggxref::Method");

const char* method_name(Method method)
{
    switch (method) {
#define GGXREF_METHOD_NAME(ID, identifier, name) \
    case Method::identifier:                     \
        return name;
        GGX_METHOD_LIST(GGXREF_METHOD_NAME)
#undef GGXREF_METHOD_NAME
    }
    return "?";
}

}  // namespace ggxref
