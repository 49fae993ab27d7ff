// ggx_methods.cpp - the reference's method names, from the project's one list of methods
// (GGX_METHOD_LIST of kernels/ggx_contract.h: names and ids only, no math).
#include "ggx_reference.hpp"

namespace ggxref {

const char* method_name(Method method)
{
    switch (method) {
#define GGXREF_METHOD_NAME(ID, identifier, name, ...) \
    case Method::identifier:                     \
        return name;
        GGX_METHOD_LIST(GGXREF_METHOD_NAME)
#undef GGXREF_METHOD_NAME
    }
    return "?";
}

}  // namespace ggxref
