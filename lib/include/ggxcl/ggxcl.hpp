// ggxcl.hpp - the whole public API of ggxcl.
#pragma once

#include "ggxcl/backend.hpp"
#include "ggxcl/device.hpp"
#include "ggxcl/error.hpp"
#include "ggxcl/fields.hpp"
#include "ggxcl/kernel_sources.hpp"
#include "ggxcl/method.hpp"
#include "ggxcl/multi_device.hpp"
#include "ggxcl/params.hpp"
#include "ggxcl/results.hpp"
#include "ggxcl/sampler.hpp"
#include "ggxcl/user_kernels.hpp"
#include "ggxcl/user_sampler.hpp"
#include "ggxcl/version.hpp"
#include "ggxcl/vulkan.hpp"
