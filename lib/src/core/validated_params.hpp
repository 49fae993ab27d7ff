// validated_params.hpp - a request's SampleParams once validate() has
// passed them, with unit view and normal.  Every public entry point of the
// Sampler (and generate_split) validates once at its start and hands one of
// these to its internal paths (per chunk, per launch), which take
// ValidatedParams and so never validate again.
#pragma once

#include <cstdint>

#include "ggxcl/fields.hpp"
#include "ggxcl/params.hpp"

namespace ggxcl::detail {

class ValidatedParams {
public:
    const SampleParams& operator*() const { return unit_; }

private:
    explicit ValidatedParams(const SampleParams& unit) : unit_(unit) {}
    friend ValidatedParams validated(const SampleParams& params);
    SampleParams unit_;
};

// validate(params) (throws its InvalidArgument), then normalized(params)
// without validating again.
ValidatedParams validated(const SampleParams& params);

// What a request for samples in host memory (Sampler::generate,
// generate_chunks, generate_chunk_views, generate_split) checks once at its
// start: validated(params), validate(range), validate(per_sample, params,
// range.count), and at least one field (InvalidArgument "fields").
// Defined with that front end, in sampler_generate.cpp.
ValidatedParams validated_request(const SampleParams& params, const SampleRange& range, FieldSet fields,
                                  const PerSampleInputs& per_sample);

} // namespace ggxcl::detail
