/* ggxcl.h - the C API of ggxcl (C99; compiles as C++ too, extern "C"):
 * opaque handles over the same library as the C++ API, status codes instead
 * of exceptions (the last error's message kept per thread), and the
 * caller's OpenCL objects (cl_context, cl_command_queue, cl_mem, cl_event)
 * in and out.  Every enum is made from, or checked against, the device
 * contract <ggxcl/cl/ggx_contract.h> that the kernels and the C++ API use.
 * A sampler runs on OpenCL or, made by ggxcl_sampler_create_api, on Vulkan
 * (docs/VULKAN.md), where every call that works on OpenCL objects is refused.
 *
 *   ggxcl_sampler* sampler;
 *   if (ggxcl_sampler_create("", &sampler) != GGXCL_SUCCESS)
 *       fprintf(stderr, "%s\n", ggxcl_last_error());
 *   ggxcl_params params;
 *   ggxcl_default_params(&params);               caps, alpha 0.3, view +z
 *   ggxcl_device_outputs out = {0};
 *   out.o.mem = my_buffer;                        3 planes of `count` floats
 *   ggxcl_range range = {seed, first, count};
 *   ggxcl_enqueue(sampler, queue, &params, &range, &out, 0, NULL, 0, NULL, &event);
 *
 * Handles may be shared by threads: every call on a sampler may run in
 * several threads at once (give each thread its own queue for parallel
 * launches).  A call that fails returns a status below zero and
 * ggxcl_last_error() says why; what it had written by then (whole chunks of
 * ggxcl_generate before a device failed) stays.  docs/PIPELINES.md. */
#ifndef GGXCL_H
#define GGXCL_H

#include <stddef.h>
#include <stdint.h>

#ifndef CL_TARGET_OPENCL_VERSION
#define CL_TARGET_OPENCL_VERSION 120
#endif
#include <CL/cl.h>

#include "ggxcl/cl/ggx_contract.h"

#ifdef __cplusplus
extern "C" {
#endif

/* What a call returns: GGXCL_SUCCESS or one error kind (the C++ API's
 * exception of the same name in ggxcl/error.hpp). */
typedef enum ggxcl_status {
    GGXCL_SUCCESS = 0,
    GGXCL_INVALID_ARGUMENT = -1,   /* a value outside what is allowed: ggxcl_last_error_parameter() names it */
    GGXCL_DEVICE_ERROR = -2,       /* no platform or device of the API at all, or a Vulkan call failed */
    GGXCL_NO_MATCHING_DEVICE = -3, /* devices exist, none matches the selector (the message lists them) */
    GGXCL_CL_ERROR = -4,           /* an OpenCL call failed: ggxcl_last_cl_error() is its code */
    GGXCL_DEVICE_LOST = -5,        /* the device stopped working: make a new sampler once it is back */
    GGXCL_BUILD_ERROR = -6,        /* a program did not build: ggxcl_last_build_log() */
    GGXCL_OUT_OF_HOST_MEMORY = -7, /* the library could not allocate host memory */
    GGXCL_ERROR = -8               /* any other failure (a file that cannot be written, ...) */
} ggxcl_status;

/* The methods, from the project's one list (GGX_METHOD_LIST), with the
 * kernels' ids: GGXCL_METHOD_NDF, _HEITZ, _HEITZ2017, _CAPS, _CAPS_ISO,
 * _BOUNDED; GGXCL_METHOD_USER with ggxcl_params.user_sampler. */
#define GGXCL_METHOD_ENUMERATOR(ID, identifier, name, ...) GGXCL_METHOD_##ID = GGX_METHOD_##ID,
typedef enum ggxcl_method {
    GGX_METHOD_LIST(GGXCL_METHOD_ENUMERATOR)
    GGXCL_METHOD_USER = GGX_METHOD_USER
} ggxcl_method;
#undef GGXCL_METHOD_ENUMERATOR
#define GGXCL_METHOD_COUNT GGX_METHOD_COUNT /* built-in methods, ids 0 .. count-1 */

/* The per-sample outputs; a set of them is a mask of GGXCL_FIELD_BIT(field). */
typedef enum ggxcl_field {
    GGXCL_FIELD_M = GGX_FIELD_M,           /* microfacet normal, 3 planes */
    GGXCL_FIELD_O = GGX_FIELD_O,           /* sampled direction, 3 planes */
    GGXCL_FIELD_PDF_M = GGX_FIELD_PDF_M,   /* density of m per steradian */
    GGXCL_FIELD_PDF_O = GGX_FIELD_PDF_O,   /* density of o per steradian */
    GGXCL_FIELD_WEIGHT = GGX_FIELD_WEIGHT, /* f |cos o| / pdf_o */
    GGXCL_FIELD_U = GGX_FIELD_U            /* the uniforms: 2 planes (3 for a dielectric) */
} ggxcl_field;
#define GGXCL_FIELD_COUNT GGX_FIELD_COUNT
#define GGXCL_FIELD_BIT(field) (1u << (unsigned)(field))

typedef enum ggxcl_precision {
    GGXCL_PRECISION_PRECISE = GGX_PRECISION_PRECISE, /* no fast math; vectorizes on CPUs */
    GGXCL_PRECISION_RELAXED = GGX_PRECISION_RELAXED  /* built with -cl-fast-relaxed-math */
} ggxcl_precision;

typedef enum ggxcl_sequence {
    GGXCL_SEQUENCE_PHILOX = GGX_SEQUENCE_PHILOX, /* Philox2x32-10: independent uniforms */
    GGXCL_SEQUENCE_SOBOL = GGX_SEQUENCE_SOBOL    /* Owen-scrambled Sobol points */
} ggxcl_sequence;

typedef enum ggxcl_transport {
    GGXCL_TRANSPORT_RADIANCE = GGX_TRANSPORT_RADIANCE,    /* a path tracer's: transmission / eta'^2 */
    GGXCL_TRANSPORT_IMPORTANCE = GGX_TRANSPORT_IMPORTANCE /* the adjoint (light tracing) */
} ggxcl_transport;

typedef struct ggxcl_sampler ggxcl_sampler;           /* a device, its context, programs and queue */
typedef struct ggxcl_user_sampler ggxcl_user_sampler; /* a sampler of the user's own (one file) */

/* What every sample of a batch shares (ggxcl::SampleParams, ggxcl/params.hpp). */
typedef struct ggxcl_params {
    ggxcl_method method;
    float alpha_x, alpha_y;   /* > 0; caps-iso and world space need alpha_x == alpha_y */
    float view[3];            /* pointing away from the surface, tangent space (world for caps-iso) */
    float normal[3];          /* caps-iso and world space: the surface normal */
    ggxcl_precision precision;
    ggxcl_sequence sequence;
    int world_space;          /* nonzero: view, normal, m and o are world-space vectors */
    float eta;                /* 0: a conductor; else a dielectric's index below over above, != 1 */
    ggxcl_transport transport;
    const ggxcl_user_sampler* user_sampler; /* with GGXCL_METHOD_USER, else NULL */
} ggxcl_params;

/* caps, alpha 0.3, view and normal +z, precise, philox, tangent space, eta 0, radiance. */
void ggxcl_default_params(ggxcl_params* params);

/* Samples first .. first + count - 1 of stream `seed` (0 .. 2^32 - 1); sample
 * k depends on (seed, k) alone, so any split gives the same bits. */
typedef struct ggxcl_range {
    uint64_t seed, first, count;
} ggxcl_range;

/* A caller's buffer of floats and the offset, in floats, where the call's
 * planes begin: plane c of a field holds sample j at offset + c * stride + j.
 * mem NULL: not used. */
typedef struct ggxcl_buffer {
    cl_mem mem;
    size_t offset;
} ggxcl_buffer;

/* The outputs of ggxcl_enqueue: only the fields whose buffer is set are computed. */
typedef struct ggxcl_device_outputs {
    ggxcl_buffer m, o, pdf_m, pdf_o, weight, u;
} ggxcl_device_outputs;

/* Per-sample inputs in the caller's buffers, planar with the call's stride:
 * view and normal 3 planes (unit vectors), alpha 2, uniforms 2 (3 with eta).
 * An unset buffer means the value of ggxcl_params (uniforms: its sequence).
 * The two flags are promises that select a cheaper program; 0 when unsure. */
typedef struct ggxcl_device_inputs {
    ggxcl_buffer view, alpha, normal, uniforms;
    int views_above_horizon; /* every view has i.n >= 0 */
    int isotropic;           /* every alpha pair has alpha_x == alpha_y */
} ggxcl_device_inputs;

/* Host arrays for ggxcl_generate, planar with stride range.count (m: x of
 * every sample, then y, then z); NULL: not wanted. */
typedef struct ggxcl_host_outputs {
    float *m, *o, *pdf_m, *pdf_o, *weight, *u;
} ggxcl_host_outputs;

/* The fused white-furnace estimator's sums and what they estimate. */
typedef struct ggxcl_furnace_sums {
    uint64_t count;
    double sum, sum_of_squares;
    double reflected_sum;          /* dielectrics: the reflected samples' weights */
    double mean, variance;         /* the albedo estimate, the per-sample variance */
    double reflectance, transmittance;
} ggxcl_furnace_sums;

/* Versions: "0.2.0"; the numbers of the library running. */
const char* ggxcl_version(void);
void ggxcl_version_numbers(int* major, int* minor, int* patch);

/* Errors.  The strings stay valid until this thread's next failing ggxcl call. */
const char* ggxcl_status_string(ggxcl_status status); /* "GGXCL_INVALID_ARGUMENT", ... */
const char* ggxcl_last_error(void);           /* this thread's last failure's message, "" if none */
const char* ggxcl_last_error_parameter(void); /* GGXCL_INVALID_ARGUMENT: the parameter, e.g. "alpha" */
cl_int ggxcl_last_cl_error(void);             /* GGXCL_CL_ERROR, _DEVICE_LOST, _BUILD_ERROR: the CL code */
const char* ggxcl_last_build_log(void);       /* GGXCL_BUILD_ERROR: the device's build log */

/* Names: "caps-iso" for GGXCL_METHOD_CAPS_ISO (NULL for an unknown id), and back. */
const char* ggxcl_method_name(ggxcl_method method);
ggxcl_status ggxcl_parse_method(const char* name, ggxcl_method* method);

/* A sampler with its own context and queue on the device `selector` names
 * (an index or part of "platform / device"; "" or NULL: GGXCL_DEVICE, else
 * the first device), or on the caller's context and device (retained). */
ggxcl_status ggxcl_sampler_create(const char* selector, ggxcl_sampler** sampler);
ggxcl_status ggxcl_sampler_create_with_context(cl_context context, cl_device_id device, ggxcl_sampler** sampler);

/* A sampler on `api`'s device that `selector` names ("" or NULL: GGXCL_DEVICE
 * or GGXCL_VULKAN_DEVICE, else the first); `language`: the Vulkan shaders'
 * (GGXCL_SHADER_GLSL with OpenCL).  ggxcl_sampler_create(s, p) is
 * ggxcl_sampler_create_api(GGXCL_API_OPENCL, s, GGXCL_SHADER_GLSL, p).  On a
 * Vulkan sampler ggxcl_generate, _pdf, _eval, _furnace, _histogram,
 * _sampler_device_name and user samplers of GLSL or HLSL files work; the calls on OpenCL objects
 * (_sampler_context, _device, _queue, _furnace_items, the _enqueue calls,
 * _build_options) fail with GGXCL_INVALID_ARGUMENT, parameter "sampler", the
 * message naming the call (those returning a handle or a size return NULL
 * or 0 and set the last error).  A Vulkan failure is GGXCL_DEVICE_ERROR (no
 * driver: the message says what to install; a failed or lost device: the
 * message names it; ggxcl_last_cl_error() is CL_SUCCESS),
 * GGXCL_BUILD_ERROR (a shader that does not compile: the code is
 * CL_BUILD_PROGRAM_FAILURE, ggxcl_last_build_log() shaderc's log), or
 * GGXCL_INVALID_ARGUMENT. */
typedef enum ggxcl_api { GGXCL_API_OPENCL = 0, GGXCL_API_VULKAN = 1 } ggxcl_api;
typedef enum ggxcl_shader_language { GGXCL_SHADER_GLSL = 0, GGXCL_SHADER_HLSL = 1 } ggxcl_shader_language;
ggxcl_status ggxcl_sampler_create_api(ggxcl_api api, const char* selector, ggxcl_shader_language language,
                                      ggxcl_sampler** sampler);
ggxcl_api ggxcl_sampler_api(const ggxcl_sampler* sampler);

void ggxcl_sampler_release(ggxcl_sampler* sampler); /* NULL is ignored */
/* The sampler's context, device and own queue (not retained for the caller), its device's name. */
cl_context ggxcl_sampler_context(const ggxcl_sampler* sampler);
cl_device_id ggxcl_sampler_device(const ggxcl_sampler* sampler);
cl_command_queue ggxcl_sampler_queue(const ggxcl_sampler* sampler);
const char* ggxcl_sampler_device_name(const ggxcl_sampler* sampler);

/* A user sampler's file (docs/USER-SAMPLERS.md); name NULL or "": the file's stem. */
ggxcl_status ggxcl_user_sampler_load(const char* path, const char* name, ggxcl_user_sampler** sampler);
void ggxcl_user_sampler_release(ggxcl_user_sampler* sampler);
const char* ggxcl_user_sampler_name(const ggxcl_user_sampler* sampler);

/* Enqueues the samples of `range` (count < 2^32) into the caller's buffers
 * on `queue` (of the sampler's context), after the events of `wait`;
 * `stride` is the plane stride in floats (0: count); `inputs` may be NULL.
 * *event (when event is not NULL) completes when every output is written;
 * the caller releases it. */
ggxcl_status ggxcl_enqueue(ggxcl_sampler* sampler, cl_command_queue queue, const ggxcl_params* params,
                           const ggxcl_range* range, const ggxcl_device_outputs* outputs, uint32_t stride,
                           const ggxcl_device_inputs* inputs, cl_uint wait_count, const cl_event* wait,
                           cl_event* event);

/* The pdf (per steradian) of `count` directions (3 planes) for the params'
 * sampler, and the BSDF value f |cos o| for multiple importance sampling. */
ggxcl_status ggxcl_enqueue_pdf(ggxcl_sampler* sampler, cl_command_queue queue, const ggxcl_params* params,
                               uint32_t count, ggxcl_buffer directions, ggxcl_buffer pdfs, uint32_t stride,
                               const ggxcl_device_inputs* inputs, cl_uint wait_count, const cl_event* wait,
                               cl_event* event);
ggxcl_status ggxcl_enqueue_eval(ggxcl_sampler* sampler, cl_command_queue queue, const ggxcl_params* params,
                                uint32_t count, ggxcl_buffer directions, ggxcl_buffer values, uint32_t stride,
                                const ggxcl_device_inputs* inputs, cl_uint wait_count, const cl_event* wait,
                                cl_event* event);

/* The furnace's partial sums of one range (count <= 2^31) into `sums`:
 * ggxcl_furnace_items(count) weight sums, as many sums of squares, and for
 * a dielectric as many sums of reflected weights. */
ggxcl_status ggxcl_enqueue_furnace(ggxcl_sampler* sampler, cl_command_queue queue, const ggxcl_params* params,
                                   const ggxcl_range* range, ggxcl_buffer sums, const ggxcl_device_inputs* inputs,
                                   cl_uint wait_count, const cl_event* wait, cl_event* event);
size_t ggxcl_furnace_items(const ggxcl_sampler* sampler, uint64_t count);

/* Host memory, for convenience: the samples of `range` (fields: a mask of
 * GGXCL_FIELD_BIT; each wanted field's array set), the pdfs and BSDF values
 * of `count` directions (3 planes of count floats), the furnace's sums. */
ggxcl_status ggxcl_generate(ggxcl_sampler* sampler, const ggxcl_params* params, const ggxcl_range* range,
                            unsigned fields, const ggxcl_host_outputs* outputs);
ggxcl_status ggxcl_pdf(ggxcl_sampler* sampler, const ggxcl_params* params, size_t count, const float* directions,
                       float* pdfs);
ggxcl_status ggxcl_eval(ggxcl_sampler* sampler, const ggxcl_params* params, size_t count, const float* directions,
                        float* values);
ggxcl_status ggxcl_furnace(ggxcl_sampler* sampler, const ggxcl_params* params, const ggxcl_range* range,
                           ggxcl_furnace_sums* sums);

/* Bins the directions (GGXCL_FIELD_O or GGXCL_FIELD_M) of `range` on the
 * device, on OpenCL and Vulkan: `counts` receives bins_z * bins_phi counts,
 * bin (z, phi) at z * bins_phi + phi, z = cos theta in bins_z equal steps
 * from -1 and phi in bins_phi from 0 (bins of equal solid angle;
 * kernels/ggx_histogram_bin.h); *non_finite and *invalid the samples
 * counted apart (ggxcl::Histogram). */
ggxcl_status ggxcl_histogram(ggxcl_sampler* sampler, const ggxcl_params* params, const ggxcl_range* range,
                             int bins_z, int bins_phi, ggxcl_field direction, uint64_t* counts,
                             uint64_t* non_finite, uint64_t* invalid);

/* For the caller's own kernels: a directory of the device headers (for -I;
 * valid for the process), and the options the library builds `precision`
 * with on the sampler's device (-I included): copied into `options` of
 * `size` bytes; *needed (when not NULL) receives the length + 1. */
ggxcl_status ggxcl_device_include_dir(const char** directory);
ggxcl_status ggxcl_build_options(const ggxcl_sampler* sampler, ggxcl_precision precision, char* options,
                                 size_t size, size_t* needed);

#ifdef __cplusplus
}
#endif

#endif
