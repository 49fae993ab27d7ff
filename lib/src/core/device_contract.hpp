// device_contract.hpp - the runtime's side of kernels/ggx_contract.h: its
// field and sequence enums checked against the kernels' ids at compile time
// (a mismatch does not build; the method enum is made from the list), and
// the argument positions of the bulk kernels by name.
#pragma once

#include <cstddef>
#include <cstdint>

#include "ggx_contract.h"
#include "ggxcl/fields.hpp"
#include "ggxcl/method.hpp"
#include "ggxcl/params.hpp"

namespace ggxcl::detail {

// ggxcl::Method and all_methods are made from GGX_METHOD_LIST (method.hpp);
// the ids GGX_METHOD_<ID> are written out for the shading languages, which
// have no enum: each must be its line's place in the list.
constexpr bool method_ids_in_list_order()
{
    for (std::size_t k = 0; k < all_methods.size(); ++k)
        if (static_cast<std::size_t>(all_methods[k]) != k)
            return false;
    return true;
}
static_assert(method_ids_in_list_order(), "ggx_contract.h: a GGX_METHOD_<ID> is not its line's place in the list");

static_assert(static_cast<int>(Field::m) == GGX_FIELD_M);
static_assert(static_cast<int>(Field::o) == GGX_FIELD_O);
static_assert(static_cast<int>(Field::pdf_m) == GGX_FIELD_PDF_M);
static_assert(static_cast<int>(Field::pdf_o) == GGX_FIELD_PDF_O);
static_assert(static_cast<int>(Field::weight) == GGX_FIELD_WEIGHT);
static_assert(static_cast<int>(Field::u) == GGX_FIELD_U);
static_assert(all_fields.size() == GGX_FIELD_COUNT, "every kernel field id has its ggxcl::Field");
static_assert(GGX_PARAM_ARG_COUNT == GGX_PARAM_UNIFORM_COUNT + 2 * GGX_PARAM_BUFFER_COUNT,
              "the uniform floats, then four buffers, then their offsets");

static_assert(static_cast<int>(Sequence::philox) == GGX_SEQUENCE_PHILOX);
static_assert(static_cast<int>(Sequence::sobol) == GGX_SEQUENCE_SOBOL);
static_assert(all_sequences.size() == GGX_SEQUENCE_COUNT, "every kernel sequence id has its ggxcl::Sequence");

static_assert(static_cast<int>(Precision::precise) == GGX_PRECISION_PRECISE);
static_assert(static_cast<int>(Precision::relaxed) == GGX_PRECISION_RELAXED);
static_assert(all_precisions.size() == GGX_PRECISION_COUNT, "every precision id has its ggxcl::Precision");
static_assert(static_cast<int>(Transport::radiance) == GGX_TRANSPORT_RADIANCE);
static_assert(static_cast<int>(Transport::importance) == GGX_TRANSPORT_IMPORTANCE);
static_assert(all_transports.size() == GGX_TRANSPORT_COUNT, "every transport id has its ggxcl::Transport");

// The kernel's id of a method, and the -DGGX_WRITE_MASK bits of a field set
// (FieldSet's bits are 1 << field id, the kernels' mask bits).
constexpr int method_id(Method method) { return static_cast<int>(method); }
constexpr int sequence_id(Sequence sequence) { return static_cast<int>(sequence); }
inline unsigned write_mask(FieldSet fields) { return fields.bits(); }

// Argument positions (ggx_contract.h), as cl_uint is: 32-bit unsigned.
constexpr std::uint32_t arg_seed = GGX_ARG_SEED, arg_first = GGX_ARG_FIRST, arg_count = GGX_ARG_COUNT,
                  arg_stride = GGX_ARG_STRIDE, arg_params = GGX_ARG_PARAMS, arg_outputs = GGX_ARG_OUTPUTS;
constexpr std::uint32_t arg_output(Field field) { return GGX_ARG_OUTPUTS + static_cast<std::uint32_t>(field); }
constexpr std::uint32_t arg_output_offset(Field field) { return GGX_ARG_OUTPUT_OFFSETS + static_cast<std::uint32_t>(field); }
constexpr std::uint32_t arg_sums_offset = GGX_ARG_SUMS_OFFSET;
constexpr std::uint32_t pdf_arg_count = GGX_PDF_ARG_COUNT, pdf_arg_stride = GGX_PDF_ARG_STRIDE,
                  pdf_arg_params = GGX_PDF_ARG_PARAMS, pdf_arg_directions = GGX_PDF_ARG_DIRECTIONS,
                  pdf_arg_pdfs = GGX_PDF_ARG_PDFS, pdf_arg_directions_offset = GGX_PDF_ARG_DIRECTIONS_OFFSET,
                  pdf_arg_pdfs_offset = GGX_PDF_ARG_PDFS_OFFSET;
constexpr std::uint32_t count_arg_bins = GGX_COUNT_ARG_BINS, count_arg_count = GGX_COUNT_ARG_COUNT,
                  count_arg_per_item = GGX_COUNT_ARG_PER_ITEM, count_arg_counts = GGX_COUNT_ARG_COUNTS;

// Samples per work-item of ggx_furnace_bulk.
constexpr std::size_t furnace_per_item = GGX_FURNACE_PER_ITEM;

} // namespace ggxcl::detail
