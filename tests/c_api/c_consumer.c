/* c_consumer.c - a C99 program against ggxcl's C API (ggxcl/ggxcl.h).
 *   c_consumer bits DUMP USER_DIR   its own context, queue and buffers at
 *       offsets (0, aligned, odd: the kernels take them) get the C++ enqueue's bits of
 *       every case of c_api_cases.h (DUMP, from cpp_dump) and leave the rest
 *       of each buffer untouched; per-sample inputs from buffers at offsets;
 *       the host calls agree, a histogram bins the generated samples; then every status code that one process can
 *       provoke (USER_DIR holds tests/user_samplers).
 *   c_consumer threads DUMP         four threads share one sampler, each with
 *       its own queue, and get the same bits.
 *   c_consumer vulkan DUMP VK_DUMP USER_DIR   a Vulkan sampler (ggxcl_sampler_create_api):
 *       ggxcl_generate, _pdf and _eval of every case (the user sampler in GLSL) give the C++
 *       VulkanSampler's bits (VK_DUMP, from cpp_dump ... vulkan) and agree with OpenCL's (DUMP)
 *       within the shader bounds; the furnace works; the calls on OpenCL objects fail naming
 *       the call; a bad API or language is refused.  Runs without an OpenCL platform.
 *   c_consumer no-device            (no OpenCL platform) GGXCL_DEVICE_ERROR.
 *   c_consumer no-cache             (no writable cache) GGXCL_ERROR.
 *   c_consumer out-of-memory        GGXCL_OUT_OF_HOST_MEMORY.
 * Exits 0 when every check passes, else 1 after naming the failures. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <ggxcl/ggxcl.h>

#include "c_api_cases.h"

static int failures = 0;

#define CHECK(condition, ...)                                        \
    do {                                                             \
        if (!(condition)) {                                          \
            fprintf(stderr, "FAIL %s:%d: ", __FILE__, __LINE__);     \
            fprintf(stderr, __VA_ARGS__);                            \
            fprintf(stderr, "\n");                                   \
            ++failures;                                              \
        }                                                            \
    } while (0)

#define MUST(call)                                                                              \
    do {                                                                                        \
        ggxcl_status must_status = (call);                                                      \
        if (must_status != GGXCL_SUCCESS) {                                                     \
            fprintf(stderr, "FAIL %s:%d: %s: %s\n", __FILE__, __LINE__, ggxcl_status_string(must_status), \
                    ggxcl_last_error());                                                        \
            exit(1);                                                                            \
        }                                                                                       \
    } while (0)

static const float sentinel = -7.0f;
static const float* dump = NULL; /* CASE_FLOATS per method */

static void read_dump(const char* path)
{
    size_t floats = CASE_TOTAL * CASE_FLOATS;
    float* data = malloc(floats * sizeof(float));
    FILE* file = fopen(path, "rb");
    if (!data || !file || fread(data, sizeof(float), floats, file) != floats) {
        fprintf(stderr, "cannot read %zu floats from %s\n", floats, path);
        exit(1);
    }
    fclose(file);
    dump = data;
}

static ggxcl_user_sampler* user_sampler = NULL; /* CASE_USER_FILE */

static void load_user_sampler(const char* user_dir)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", user_dir, CASE_USER_FILE);
    MUST(ggxcl_user_sampler_load(path, NULL, &user_sampler));
}

static ggxcl_params case_params(const struct api_case* c)
{
    ggxcl_params params;
    ggxcl_default_params(&params);
    params.method = (ggxcl_method)c->method;
    params.alpha_x = case_alpha_x(c);
    params.alpha_y = case_alpha_y(c);
    memcpy(params.view, case_view, sizeof case_view);
    params.eta = c->eta;
    params.transport = c->importance ? GGXCL_TRANSPORT_IMPORTANCE : GGXCL_TRANSPORT_RADIANCE;
    params.user_sampler = c->method == GGX_METHOD_USER ? user_sampler : NULL;
    return params;
}

static const char* case_name(const struct api_case* c)
{
    if (c->eta != 0.0f)
        return "caps as a dielectric";
    return c->method == GGX_METHOD_USER ? ggxcl_user_sampler_name(user_sampler) : ggxcl_method_name((ggxcl_method)c->method);
}

/* A buffer of `floats` floats, every one the sentinel. */
static cl_mem sentinel_buffer(cl_context context, cl_command_queue queue, size_t floats)
{
    cl_int error = CL_SUCCESS;
    cl_mem mem = clCreateBuffer(context, CL_MEM_READ_WRITE, floats * sizeof(float), NULL, &error);
    CHECK(error == CL_SUCCESS, "clCreateBuffer: %d", error);
    error = clEnqueueFillBuffer(queue, mem, &sentinel, sizeof sentinel, 0, floats * sizeof(float), 0, NULL, NULL);
    CHECK(error == CL_SUCCESS, "clEnqueueFillBuffer: %d", error);
    return mem;
}

/* Compares `planes` planes at `offset` (CASE_STRIDE apart) of `mem` with
 * the dump's floats at `expected`, and checks every other float of the
 * buffer's `floats` is still the sentinel. */
static void expect_planes(cl_command_queue queue, cl_mem mem, size_t floats, size_t offset, int planes,
                          const float* expected, const char* what, const char* method)
{
    float* host = malloc(floats * sizeof(float));
    size_t i, written = 0, mismatches = 0, touched = 0;
    clEnqueueReadBuffer(queue, mem, CL_TRUE, 0, floats * sizeof(float), host, 0, NULL, NULL);
    for (i = 0; i < floats; ++i) {
        size_t local = i - offset, plane = local / CASE_STRIDE, j = local % CASE_STRIDE;
        if (i >= offset && plane < (size_t)planes && j < CASE_COUNT) {
            ++written;
            if (memcmp(&host[i], &expected[plane * CASE_COUNT + j], sizeof(float)) != 0)
                ++mismatches;
        } else if (host[i] != sentinel) {
            ++touched;
        }
    }
    CHECK(written == (size_t)planes * CASE_COUNT && mismatches == 0,
          "%s %s: %zu of %zu floats differ from the C++ API's", method, what, mismatches, written);
    CHECK(touched == 0, "%s %s: %zu floats outside the planes were written", method, what, touched);
    free(host);
}

/* Offsets in floats: o at the device's base address alignment, pdf_m at 7 and the pdfs at 3
 * (below any alignment), pdf_o and weight in one buffer at 0 and 2000; the kernels take each. */
enum { PDF_M_OFFSET = 7, WEIGHT_OFFSET = 2000, PDF_OFFSET = 3 };
static size_t o_offset = 0;

static void set_aligned_offset(cl_device_id device)
{
    cl_uint align_bits = 0;
    clGetDeviceInfo(device, CL_DEVICE_MEM_BASE_ADDR_ALIGN, sizeof align_bits, &align_bits, NULL);
    o_offset = align_bits / (8 * sizeof(float));
    CHECK(o_offset > PDF_M_OFFSET, "a base address alignment of %u bits", align_bits);
}
struct Device {
    cl_context context;
    cl_device_id device;
};

/* Our own context on the device the library picks by default (GGXCL_DEVICE, else the first). */
static struct Device own_context(void)
{
    ggxcl_sampler* probe = NULL;
    struct Device d;
    cl_int error = CL_SUCCESS;
    MUST(ggxcl_sampler_create("", &probe));
    d.device = ggxcl_sampler_device(probe);
    clRetainDevice(d.device);
    ggxcl_sampler_release(probe);
    d.context = clCreateContext(NULL, 1, &d.device, NULL, NULL, &error);
    set_aligned_offset(d.device);
    CHECK(error == CL_SUCCESS, "clCreateContext: %d", error);
    return d;
}

#define PLANE_FLOATS(planes) ((size_t)(planes) * CASE_STRIDE + 300u)

/* pdf_o at 0 and weight at WEIGHT_OFFSET of one buffer, the floats between untouched. */
static void expect_side_by_side(cl_command_queue queue, cl_mem shared, const float* expected, const char* name)
{
    float host[4000];
    size_t j, differ = 0;
    clEnqueueReadBuffer(queue, shared, CL_TRUE, 0, sizeof host, host, 0, NULL, NULL);
    for (j = 0; j < CASE_COUNT; ++j)
        differ += memcmp(&host[j], &expected[PLANE_PDF_O * CASE_COUNT + j], sizeof(float)) != 0 ||
                  memcmp(&host[WEIGHT_OFFSET + j], &expected[PLANE_WEIGHT * CASE_COUNT + j], sizeof(float)) != 0 ||
                  host[CASE_COUNT + j] != sentinel;
    CHECK(differ == 0, "%s pdf_o and weight in one buffer: %zu samples differ", name, differ);
}

/* One case through ggxcl_enqueue, ggxcl_enqueue_pdf and ggxcl_enqueue_eval on `queue`. */
static void check_case(ggxcl_sampler* sampler, cl_context context, cl_command_queue queue, size_t index)
{
    const struct api_case* c = &api_cases[index];
    const char* name = case_name(c);
    const float* expected = dump + index * CASE_FLOATS;
    const int u_planes = c->eta != 0.0f ? 3 : 2;
    ggxcl_params params = case_params(c);
    ggxcl_range range = {CASE_SEED, CASE_FIRST, CASE_COUNT};
    ggxcl_device_outputs out;
    cl_mem m = sentinel_buffer(context, queue, PLANE_FLOATS(3)), o = sentinel_buffer(context, queue, PLANE_FLOATS(3) + o_offset);
    cl_mem pdf_m = sentinel_buffer(context, queue, PLANE_FLOATS(1)), shared = sentinel_buffer(context, queue, 4000);
    cl_mem u = sentinel_buffer(context, queue, PLANE_FLOATS(3)), pdf = sentinel_buffer(context, queue, PLANE_FLOATS(1));
    cl_mem value = sentinel_buffer(context, queue, PLANE_FLOATS(1));
    cl_event sampled = NULL, evaluated[2] = {NULL, NULL};
    ggxcl_buffer pdfs, values;
    memset(&out, 0, sizeof out);
    out.m.mem = m;
    out.o.mem = o, out.o.offset = o_offset;
    out.pdf_m.mem = pdf_m, out.pdf_m.offset = PDF_M_OFFSET;
    out.pdf_o.mem = shared;
    out.weight.mem = shared, out.weight.offset = WEIGHT_OFFSET;
    out.u.mem = u;
    MUST(ggxcl_enqueue(sampler, queue, &params, &range, &out, CASE_STRIDE, NULL, 0, NULL, &sampled));
    pdfs.mem = pdf, pdfs.offset = PDF_OFFSET;
    values.mem = value, values.offset = 0;
    MUST(ggxcl_enqueue_pdf(sampler, queue, &params, CASE_COUNT, out.o, pdfs, CASE_STRIDE, NULL, 1, &sampled,
                           &evaluated[0]));
    MUST(ggxcl_enqueue_eval(sampler, queue, &params, CASE_COUNT, out.o, values, CASE_STRIDE, NULL, 1, &sampled,
                            &evaluated[1]));
    CHECK(clWaitForEvents(2, evaluated) == CL_SUCCESS, "%s: the events did not complete", name);
    expect_planes(queue, m, PLANE_FLOATS(3), 0, 3, expected + PLANE_M * CASE_COUNT, "m", name);
    expect_planes(queue, o, PLANE_FLOATS(3) + o_offset, o_offset, 3, expected + PLANE_O * CASE_COUNT, "o", name);
    expect_planes(queue, pdf_m, PLANE_FLOATS(1), PDF_M_OFFSET, 1, expected + PLANE_PDF_M * CASE_COUNT, "pdf_m", name);
    expect_planes(queue, u, PLANE_FLOATS(3), 0, u_planes, expected + PLANE_U * CASE_COUNT, "u", name);
    expect_planes(queue, pdf, PLANE_FLOATS(1), PDF_OFFSET, 1, expected + PLANE_PDF * CASE_COUNT, "pdf", name);
    expect_planes(queue, value, PLANE_FLOATS(1), 0, 1, expected + PLANE_EVAL * CASE_COUNT, "eval", name);
    expect_side_by_side(queue, shared, expected, name);
    clReleaseEvent(sampled), clReleaseEvent(evaluated[0]), clReleaseEvent(evaluated[1]);
    clReleaseMemObject(m), clReleaseMemObject(o), clReleaseMemObject(pdf_m), clReleaseMemObject(shared);
    clReleaseMemObject(u), clReleaseMemObject(pdf), clReleaseMemObject(value);
}

/* Per-sample views (at offset 5) and alphas (at the aligned offset),
 * every one the case's own: the samples agree with the uniform request's within float
 * rounding (the host normalizes a uniform view in double; the kernel takes these as they are). */
static void check_per_sample_inputs(ggxcl_sampler* sampler, cl_context context, cl_command_queue queue)
{
    const size_t index = 3; /* caps */
    const float* expected = dump + index * CASE_FLOATS + PLANE_O * CASE_COUNT;
    ggxcl_params params = case_params(&api_cases[index]);
    ggxcl_range range = {CASE_SEED, CASE_FIRST, CASE_COUNT};
    float* views = calloc(5 + 3 * CASE_STRIDE, sizeof(float));
    float* alphas = calloc(o_offset + 2 * CASE_STRIDE, sizeof(float));
    float o_host[3 * CASE_STRIDE];
    size_t j, plane, differ = 0;
    ggxcl_device_inputs in;
    ggxcl_device_outputs out;
    cl_int error = CL_SUCCESS;
    cl_mem view_mem, alpha_mem, o = sentinel_buffer(context, queue, 3 * CASE_STRIDE);
    for (plane = 0; plane < 3; ++plane)
        for (j = 0; j < CASE_STRIDE; ++j)
            views[5 + plane * CASE_STRIDE + j] = case_view[plane];
    for (j = 0; j < CASE_STRIDE; ++j)
        alphas[o_offset + j] = params.alpha_x, alphas[o_offset + CASE_STRIDE + j] = params.alpha_y;
    view_mem = clCreateBuffer(context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, (5 + 3 * CASE_STRIDE) * sizeof(float),
                              views, &error);
    alpha_mem = clCreateBuffer(context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                               (o_offset + 2 * CASE_STRIDE) * sizeof(float), alphas, &error);
    memset(&in, 0, sizeof in);
    memset(&out, 0, sizeof out);
    in.view.mem = view_mem, in.view.offset = 5;
    in.alpha.mem = alpha_mem, in.alpha.offset = o_offset;
    out.o.mem = o;
    MUST(ggxcl_enqueue(sampler, queue, &params, &range, &out, CASE_STRIDE, &in, 0, NULL, NULL));
    clEnqueueReadBuffer(queue, o, CL_TRUE, 0, sizeof o_host, o_host, 0, NULL, NULL);
    for (plane = 0; plane < 3; ++plane)
        for (j = 0; j < CASE_COUNT; ++j) {
            float got = o_host[plane * CASE_STRIDE + j], want = expected[plane * CASE_COUNT + j];
            differ += !(got - want <= 1e-4f && want - got <= 1e-4f);
        }
    CHECK(differ == 0, "per-sample inputs: %zu of %u components differ by more than 1e-4", differ, 3 * CASE_COUNT);
    free(views), free(alphas);
    clReleaseMemObject(view_mem), clReleaseMemObject(alpha_mem), clReleaseMemObject(o);
}

/* The host calls: ggxcl_generate gives the enqueue's bits, the furnace's two forms agree. */
static void check_host_calls(ggxcl_sampler* sampler, cl_command_queue queue)
{
    const size_t index = 5; /* bounded */
    ggxcl_params params = case_params(&api_cases[index]);
    ggxcl_range range = {CASE_SEED, CASE_FIRST, CASE_COUNT};
    const float* expected = dump + index * CASE_FLOATS;
    static float o[3 * CASE_COUNT], weight[CASE_COUNT], pdf[CASE_COUNT];
    ggxcl_host_outputs out;
    ggxcl_furnace_sums sums;
    ggxcl_range furnace_range = {3, 0, 1u << 16};
    size_t items = ggxcl_furnace_items(sampler, furnace_range.count), i;
    cl_mem partial = sentinel_buffer(ggxcl_sampler_context(sampler), queue, 2 * items + 5);
    ggxcl_buffer partial_at = {NULL, 5};
    float* host = malloc((2 * items + 5) * sizeof(float));
    double total = 0.0;
    memset(&out, 0, sizeof out);
    out.o = o, out.weight = weight;
    MUST(ggxcl_generate(sampler, &params, &range, GGXCL_FIELD_BIT(GGXCL_FIELD_O) | GGXCL_FIELD_BIT(GGXCL_FIELD_WEIGHT), &out));
    CHECK(memcmp(o, expected + PLANE_O * CASE_COUNT, sizeof o) == 0, "ggxcl_generate's o differs from enqueue's");
    CHECK(memcmp(weight, expected + PLANE_WEIGHT * CASE_COUNT, sizeof weight) == 0, "ggxcl_generate's weight differs");
    MUST(ggxcl_pdf(sampler, &params, CASE_COUNT, o, pdf));
    {   /* the host pdf takes directions as vectors it normalizes: within float rounding */
        size_t j, differ = 0;
        for (j = 0; j < CASE_COUNT; ++j) {
            float want = expected[PLANE_PDF * CASE_COUNT + j], scale = want > 1.0f ? want : 1.0f;
            differ += !(pdf[j] - want <= 1e-5f * scale && want - pdf[j] <= 1e-5f * scale);
        }
        CHECK(differ == 0, "ggxcl_pdf: %zu of %u differ from enqueue_pdf's by more than 1e-5", differ, CASE_COUNT);
    }

    MUST(ggxcl_furnace(sampler, &params, &furnace_range, &sums));
    partial_at.mem = partial;
    MUST(ggxcl_enqueue_furnace(sampler, queue, &params, &furnace_range, partial_at, NULL, 0, NULL, NULL));
    clEnqueueReadBuffer(queue, partial, CL_TRUE, 0, (2 * items + 5) * sizeof(float), host, 0, NULL, NULL);
    for (i = 0; i < items; ++i)
        total += host[5 + i];
    CHECK(sums.count == furnace_range.count && sums.mean > 0.5 && sums.mean <= 1.0 + 1e-6,
          "furnace: %llu samples, mean %g", (unsigned long long)sums.count, sums.mean);
    CHECK(total / (double)furnace_range.count > sums.mean - 1e-5 && total / (double)furnace_range.count < sums.mean + 1e-5,
          "enqueue_furnace's mean %.8f, furnace's %.8f", total / (double)furnace_range.count, sums.mean);
    CHECK(host[0] == sentinel && host[4] == sentinel, "enqueue_furnace wrote before its offset");
    free(host);
    clReleaseMemObject(partial);
}

/* Expects `status` to be `expected`, with a message containing `needle`. */
static void expect_status(ggxcl_status status, ggxcl_status expected, const char* needle, const char* what)
{
    CHECK(status == expected, "%s: %s, expected %s (%s)", what, ggxcl_status_string(status),
          ggxcl_status_string(expected), ggxcl_last_error());
    CHECK(strstr(ggxcl_last_error(), needle) != NULL, "%s: the message lacks \"%s\": %s", what, needle,
          ggxcl_last_error());
}

/* ggxcl_histogram of bounded's o against the same samples binned here (bins of equal solid angle:
 * z = cos theta in 8 steps from -1, phi in 16 from 0): at most 2 of 1000 in another bin (float
 * rounding at an edge), every sample counted; a bad direction and no counts are refused. */
static void check_histogram(ggxcl_sampler* sampler, const char* name)
{
    enum { NZ = 8, NPHI = 16 };
    const double pi = 3.14159265358979323846;
    ggxcl_params params = case_params(&api_cases[5]);
    ggxcl_range range = {CASE_SEED, CASE_FIRST, CASE_COUNT};
    static float o[3 * CASE_COUNT];
    uint64_t counts[NZ * NPHI], here[NZ * NPHI], non_finite = 1, invalid = 1, total = 0, moved = 0;
    ggxcl_host_outputs out;
    size_t j;
    memset(&out, 0, sizeof out);
    memset(here, 0, sizeof here);
    out.o = o;
    MUST(ggxcl_generate(sampler, &params, &range, GGXCL_FIELD_BIT(GGXCL_FIELD_O), &out));
    MUST(ggxcl_histogram(sampler, &params, &range, NZ, NPHI, GGXCL_FIELD_O, counts, &non_finite, &invalid));
    for (j = 0; j < CASE_COUNT; ++j) {
        double phi = atan2(o[CASE_COUNT + j], o[j]);
        int z = (int)floor((o[2 * CASE_COUNT + j] + 1.0) / 2.0 * NZ), k = (int)floor((phi < 0 ? phi + 2 * pi : phi) / (2 * pi) * NPHI);
        ++here[(z < NZ ? z : NZ - 1) * NPHI + (k < NPHI ? k : NPHI - 1)];
    }
    for (j = 0; j < NZ * NPHI; ++j) {
        total += counts[j];
        moved += counts[j] > here[j] ? counts[j] - here[j] : here[j] - counts[j];
    }
    CHECK(total == CASE_COUNT && non_finite == 0 && invalid == 0, "%s histogram: %llu counted, %llu non-finite, "
          "%llu invalid", name, (unsigned long long)total, (unsigned long long)non_finite, (unsigned long long)invalid);
    CHECK(moved <= 4, "%s histogram: %llu samples in another bin than here", name, (unsigned long long)moved);
    expect_status(ggxcl_histogram(sampler, &params, &range, NZ, NPHI, GGXCL_FIELD_PDF_O, counts, &non_finite, &invalid),
                  GGXCL_INVALID_ARGUMENT, "o or m", "a histogram of pdf_o");
    expect_status(ggxcl_histogram(sampler, &params, &range, NZ, NPHI, GGXCL_FIELD_O, NULL, &non_finite, &invalid),
                  GGXCL_INVALID_ARGUMENT, "counts", "a histogram without counts");
}

/* Every status a process with a device can provoke. */
static void check_errors(ggxcl_sampler* sampler, cl_command_queue queue, const char* user_dir)
{
    const struct api_case caps = {GGX_METHOD_CAPS, 0.0f, 0}, unknown = {63, 0.0f, 0};
    ggxcl_params params = case_params(&caps);
    ggxcl_range range = {1, 0, 100000};
    ggxcl_device_outputs out;
    ggxcl_sampler* other = NULL;
    ggxcl_user_sampler* broken = NULL;
    static float o[3 * 100000];
    ggxcl_host_outputs host;
    char path[4096];
    cl_mem small = sentinel_buffer(ggxcl_sampler_context(sampler), queue, 1000);

    params.alpha_x = 1e-35f;  /* the library's rule in the library's words */
    expect_status(ggxcl_generate(sampler, &params, &range, 0, &(ggxcl_host_outputs){0}), GGXCL_INVALID_ARGUMENT,
                  "invalid alpha_x '1e-35': allowed is a number from 1e-30 to 1e30", "an alpha of 1e-35");
    params.alpha_x = -1.0f;
    expect_status(ggxcl_generate(sampler, &params, &range, 0, &(ggxcl_host_outputs){0}), GGXCL_INVALID_ARGUMENT,
                  "alpha", "a negative alpha");
    CHECK(strstr(ggxcl_last_error_parameter(), "alpha") != NULL, "the parameter of a bad alpha: %s",
          ggxcl_last_error_parameter());
    params = case_params(&unknown);
    expect_status(ggxcl_generate(sampler, &params, &range, 0, &(ggxcl_host_outputs){0}), GGXCL_INVALID_ARGUMENT,
                  "params.method", "method 63");
    params = case_params(&caps);
    memset(&out, 0, sizeof out);
    out.pdf_m.mem = small, out.pdf_m.offset = 10;
    range.count = 995;
    expect_status(ggxcl_enqueue(sampler, queue, &params, &range, &out, 0, NULL, 0, NULL, NULL), GGXCL_INVALID_ARGUMENT,
                  "outputs.pdf_m", "a too-small buffer");
    CHECK(strcmp(ggxcl_last_error_parameter(), "outputs.pdf_m") == 0, "its parameter: %s", ggxcl_last_error_parameter());
    expect_status(ggxcl_enqueue(NULL, queue, &params, &range, &out, 0, NULL, 0, NULL, NULL), GGXCL_INVALID_ARGUMENT,
                  "sampler", "a NULL sampler");
    expect_status(ggxcl_sampler_create("no such device anywhere", &other), GGXCL_NO_MATCHING_DEVICE,
                  "no such device anywhere", "an unknown device");
    CHECK(other == NULL, "a failed create left a sampler");

    snprintf(path, sizeof path, "%s/syntax_error.h", user_dir);
    MUST(ggxcl_user_sampler_load(path, NULL, &broken));
    params.method = GGXCL_METHOD_USER, params.user_sampler = broken;
    range.count = 1000;
    memset(&host, 0, sizeof host);
    host.o = o;
    expect_status(ggxcl_generate(sampler, &params, &range, GGXCL_FIELD_BIT(GGXCL_FIELD_O), &host), GGXCL_BUILD_ERROR,
                  "syntax_error.h:9", "a user sampler that does not compile");
    CHECK(strstr(ggxcl_last_build_log(), "syntax_error.h") != NULL, "the build log: %s", ggxcl_last_build_log());
    ggxcl_user_sampler_release(broken);

    /* Device memory exhausted, then a lost device (injected: docs/RELIABILITY.md). */
    params = case_params(&caps);
    range.count = 100000;
    setenv("GGXCL_INJECT_FAULT", "alloc-above=64", 1);
    expect_status(ggxcl_generate(sampler, &params, &range, GGXCL_FIELD_BIT(GGXCL_FIELD_O), &host), GGXCL_CL_ERROR,
                  "CL_MEM_OBJECT_ALLOCATION_FAILURE", "device memory exhausted");
    CHECK(ggxcl_last_cl_error() == CL_MEM_OBJECT_ALLOCATION_FAILURE, "its CL code: %d", ggxcl_last_cl_error());
    MUST(ggxcl_sampler_create("", &other));
    setenv("GGXCL_INJECT_FAULT", "lost-after=0", 1);
    expect_status(ggxcl_generate(other, &params, &range, GGXCL_FIELD_BIT(GGXCL_FIELD_O), &host), GGXCL_DEVICE_LOST,
                  "CL_DEVICE_NOT_AVAILABLE", "a lost device");
    CHECK(ggxcl_last_cl_error() == CL_DEVICE_NOT_AVAILABLE, "its CL code: %d", ggxcl_last_cl_error());
    unsetenv("GGXCL_INJECT_FAULT");
    ggxcl_sampler_release(other);
    clReleaseMemObject(small);
}

struct ThreadWork {
    ggxcl_sampler* sampler;
    cl_context context;
    size_t case_index;
};

static void* thread_body(void* argument)
{
    struct ThreadWork* work = argument;
    cl_int error = CL_SUCCESS;
    cl_command_queue queue = clCreateCommandQueue(work->context, ggxcl_sampler_device(work->sampler), 0, &error);
    int round;
    for (round = 0; round < 3; ++round)
        check_case(work->sampler, work->context, queue, work->case_index);
    clReleaseCommandQueue(queue);
    return NULL;
}

/* Four threads on one sampler, each with its own queue and its own method. */
static void check_threads(void)
{
    struct Device d = own_context();
    ggxcl_sampler* sampler = NULL;
    pthread_t threads[4];
    struct ThreadWork work[4];
    int t;
    MUST(ggxcl_sampler_create_with_context(d.context, d.device, &sampler));
    for (t = 0; t < 4; ++t) {
        work[t].sampler = sampler, work[t].context = d.context, work[t].case_index = (size_t)t + 3; /* caps, caps-iso, bounded, the dielectric */
        CHECK(pthread_create(&threads[t], NULL, thread_body, &work[t]) == 0, "pthread_create");
    }
    for (t = 0; t < 4; ++t)
        pthread_join(threads[t], NULL);
    ggxcl_sampler_release(sampler);
    clReleaseContext(d.context), clReleaseDevice(d.device);
}

static void check_bits(const char* user_dir)
{
    struct Device d = own_context();
    cl_int error = CL_SUCCESS;
    cl_command_queue queue = clCreateCommandQueue(d.context, d.device, 0, &error);
    ggxcl_sampler* sampler = NULL;
    size_t index;
    int major = -1, minor = -1, patch = -1;
    char options[4096];
    size_t needed = 0;
    const char* include_dir = NULL;
    MUST(ggxcl_sampler_create_with_context(d.context, d.device, &sampler));
    CHECK(ggxcl_sampler_context(sampler) == d.context, "the sampler is not on our context");
    for (index = 0; index < CASE_TOTAL; ++index)
        check_case(sampler, d.context, queue, index);
    check_per_sample_inputs(sampler, d.context, queue);
    check_host_calls(sampler, queue);
    check_histogram(sampler, "OpenCL");
    check_errors(sampler, queue, user_dir);

    ggxcl_version_numbers(&major, &minor, &patch);
    CHECK(major >= 0 && minor >= 0 && patch >= 0 && strchr(ggxcl_version(), '.'), "version %s", ggxcl_version());
    MUST(ggxcl_device_include_dir(&include_dir));
    MUST(ggxcl_build_options(sampler, GGXCL_PRECISION_RELAXED, options, sizeof options, &needed));
    CHECK(strstr(options, include_dir) && strstr(options, "-cl-fast-relaxed-math") && needed == strlen(options) + 1,
          "build options: %s", options);
    printf("c_consumer: %u cases on %s (ggxcl %s), device headers in %s\n", (unsigned)CASE_TOTAL,
           ggxcl_sampler_device_name(sampler), ggxcl_version(), include_dir);
    ggxcl_sampler_release(sampler);
    clReleaseCommandQueue(queue), clReleaseContext(d.context), clReleaseDevice(d.device);
}

/* ---- A Vulkan sampler (c_consumer vulkan) ---- */

static int by_value(const void* a, const void* b)
{
    const double x = *(const double*)a, y = *(const double*)b;
    return x < y ? -1 : x > y;
}

/* The 99th percentile of `n` values (sorted in place). */
static double percentile_99(double* values, size_t n)
{
    qsort(values, n, sizeof *values, by_value);
    return values[(size_t)(0.99 * (double)(n - 1))];
}

/* One case from the host calls, in the dump's layout. */
static void host_case(ggxcl_sampler* sampler, const struct api_case* c, float* floats)
{
    ggxcl_params params = case_params(c);
    ggxcl_range range = {CASE_SEED, CASE_FIRST, CASE_COUNT};
    ggxcl_host_outputs out;
    memset(floats, 0, CASE_FLOATS * sizeof(float));
    memset(&out, 0, sizeof out);
    out.m = floats + PLANE_M * CASE_COUNT, out.o = floats + PLANE_O * CASE_COUNT;
    out.pdf_m = floats + PLANE_PDF_M * CASE_COUNT, out.pdf_o = floats + PLANE_PDF_O * CASE_COUNT;
    out.weight = floats + PLANE_WEIGHT * CASE_COUNT, out.u = floats + PLANE_U * CASE_COUNT;
    MUST(ggxcl_generate(sampler, &params, &range, (1u << GGXCL_FIELD_COUNT) - 1u, &out));
    MUST(ggxcl_pdf(sampler, &params, CASE_COUNT, out.o, floats + PLANE_PDF * CASE_COUNT));
    MUST(ggxcl_eval(sampler, &params, CASE_COUNT, out.o, floats + PLANE_EVAL * CASE_COUNT));
}

/* Vulkan's o and pdf_o against OpenCL's: angle 99% <= 1e-5 rad and max <= 2e-3, pdf_o relative 99% <= 1e-4. */
static void expect_close_to_opencl(const float* vk, const float* cl, const char* name)
{
    static double angle[CASE_COUNT], relative[CASE_COUNT];
    size_t j, kept = 0;
    double worst = 0.0;
    for (j = 0; j < CASE_COUNT; ++j) {
        const float* a = vk + PLANE_O * CASE_COUNT + j;
        const float* b = cl + PLANE_O * CASE_COUNT + j;
        double x = (double)a[CASE_COUNT] * b[2 * CASE_COUNT] - (double)a[2 * CASE_COUNT] * b[CASE_COUNT];
        double y = (double)a[2 * CASE_COUNT] * b[0] - (double)a[0] * b[2 * CASE_COUNT];
        double z = (double)a[0] * b[CASE_COUNT] - (double)a[CASE_COUNT] * b[0];
        double dot = (double)a[0] * b[0] + (double)a[CASE_COUNT] * b[CASE_COUNT] + (double)a[2 * CASE_COUNT] * b[2 * CASE_COUNT];
        angle[j] = atan2(sqrt(x * x + y * y + z * z), dot);
        worst = angle[j] > worst ? angle[j] : worst;
        if (cl[PLANE_PDF_O * CASE_COUNT + j] > 0.0f)
            relative[kept++] = fabs(vk[PLANE_PDF_O * CASE_COUNT + j] / cl[PLANE_PDF_O * CASE_COUNT + j] - 1.0);
    }
    CHECK(percentile_99(angle, CASE_COUNT) <= 1e-5 && worst <= 2e-3, "%s: o's angle to OpenCL's: 99%% %g, max %g",
          name, percentile_99(angle, CASE_COUNT), worst);
    CHECK(kept > 0 && percentile_99(relative, kept) <= 1e-4, "%s: pdf_o against OpenCL's: 99%% %g", name,
          kept ? percentile_99(relative, kept) : -1.0);
    CHECK(memcmp(vk + PLANE_U * CASE_COUNT, cl + PLANE_U * CASE_COUNT, 3 * CASE_COUNT * sizeof(float)) == 0,
          "%s: the uniforms differ from OpenCL's", name);
}

/* The calls on OpenCL objects fail on a Vulkan sampler, naming the call; a bad API or language too. */
static void check_vulkan_refusals(ggxcl_sampler* sampler, const char* user_dir)
{
    ggxcl_params params;
    ggxcl_range range = {1, 0, 100};
    ggxcl_device_outputs out;
    ggxcl_sampler* other = NULL;
    ggxcl_user_sampler* opencl_c = NULL;
    char path[4096], options[16];
    ggxcl_default_params(&params);
    memset(&out, 0, sizeof out);
    CHECK(ggxcl_sampler_api(sampler) == GGXCL_API_VULKAN, "the sampler's API");
    CHECK(ggxcl_sampler_context(sampler) == NULL && strstr(ggxcl_last_error(), "ggxcl_sampler_context"),
          "a Vulkan sampler's context: %s", ggxcl_last_error());
    CHECK(ggxcl_sampler_device(sampler) == NULL && strstr(ggxcl_last_error(), "ggxcl_sampler_device"),
          "a Vulkan sampler's device: %s", ggxcl_last_error());
    CHECK(ggxcl_sampler_queue(sampler) == NULL && strstr(ggxcl_last_error(), "ggxcl_sampler_queue"),
          "a Vulkan sampler's queue: %s", ggxcl_last_error());
    CHECK(ggxcl_furnace_items(sampler, 100) == 0 && strstr(ggxcl_last_error(), "ggxcl_furnace_items"),
          "a Vulkan sampler's furnace items: %s", ggxcl_last_error());
    expect_status(ggxcl_enqueue(sampler, NULL, &params, &range, &out, 0, NULL, 0, NULL, NULL), GGXCL_INVALID_ARGUMENT,
                  "ggxcl_enqueue", "enqueue on Vulkan");
    CHECK(strcmp(ggxcl_last_error_parameter(), "sampler") == 0, "enqueue on Vulkan names %s",
          ggxcl_last_error_parameter());
    expect_status(ggxcl_build_options(sampler, GGXCL_PRECISION_PRECISE, options, sizeof options, NULL),
                  GGXCL_INVALID_ARGUMENT, "ggxcl_build_options", "build options on Vulkan");
    snprintf(path, sizeof path, "%s/%s", user_dir, CASE_USER_FILE);
    MUST(ggxcl_user_sampler_load(path, NULL, &opencl_c));
    params.method = GGXCL_METHOD_USER, params.user_sampler = opencl_c;
    expect_status(ggxcl_furnace(sampler, &params, &range, &(ggxcl_furnace_sums){0}), GGXCL_INVALID_ARGUMENT,
                  CASE_USER_FILE, "an OpenCL C sampler on Vulkan");
    ggxcl_user_sampler_release(opencl_c);
    expect_status(ggxcl_sampler_create_api((ggxcl_api)7, "", GGXCL_SHADER_GLSL, &other), GGXCL_INVALID_ARGUMENT,
                  "GGXCL_API_VULKAN", "an unknown API");
    expect_status(ggxcl_sampler_create_api(GGXCL_API_OPENCL, "", GGXCL_SHADER_HLSL, &other), GGXCL_INVALID_ARGUMENT,
                  "GGXCL_SHADER_HLSL with GGXCL_API_VULKAN", "HLSL on OpenCL");
    CHECK(strcmp(ggxcl_last_error_parameter(), "language") == 0, "HLSL on OpenCL names %s", ggxcl_last_error_parameter());
}

static void check_vulkan(const char* opencl_dump, const char* vulkan_dump, const char* user_dir)
{
    static float floats[CASE_FLOATS];
    const float* opencl;
    ggxcl_sampler* sampler = NULL;
    ggxcl_params params;
    ggxcl_range range = {3, 0, 1u << 16};
    ggxcl_furnace_sums sums;
    char path[4096];
    size_t index;
    read_dump(opencl_dump);
    opencl = dump;
    read_dump(vulkan_dump);
    snprintf(path, sizeof path, "%s/%s", user_dir, CASE_USER_SHADER);
    MUST(ggxcl_user_sampler_load(path, NULL, &user_sampler));
    MUST(ggxcl_sampler_create_api(GGXCL_API_VULKAN, "", GGXCL_SHADER_GLSL, &sampler));
    for (index = 0; index < CASE_TOTAL; ++index) {
        const char* name = case_name(&api_cases[index]);
        host_case(sampler, &api_cases[index], floats);
        CHECK(memcmp(floats, dump + index * CASE_FLOATS, sizeof floats) == 0, "%s: not the C++ VulkanSampler's bits",
              name);
        expect_close_to_opencl(floats, opencl + index * CASE_FLOATS, name);
    }
    ggxcl_default_params(&params);
    MUST(ggxcl_furnace(sampler, &params, &range, &sums));
    CHECK(sums.count == range.count && sums.mean > 0.5 && sums.mean <= 1.0 + 1e-6, "furnace on Vulkan: mean %g",
          sums.mean);
    check_histogram(sampler, "Vulkan");
    check_vulkan_refusals(sampler, user_dir);
    printf("c_consumer: %u cases on %s\n", (unsigned)CASE_TOTAL, ggxcl_sampler_device_name(sampler));
    ggxcl_sampler_release(sampler);
    ggxcl_user_sampler_release(user_sampler);
    free((void*)opencl);
}

int main(int argc, char** argv)
{
    const char* mode = argc > 1 ? argv[1] : "";
    if (strcmp(mode, "bits") == 0 && argc == 4) {
        read_dump(argv[2]);
        load_user_sampler(argv[3]);
        check_bits(argv[3]);
        ggxcl_user_sampler_release(user_sampler);
    } else if (strcmp(mode, "threads") == 0 && argc == 3) {
        read_dump(argv[2]);
        check_threads();
    } else if (strcmp(mode, "vulkan") == 0 && argc == 5) {
        check_vulkan(argv[2], argv[3], argv[4]);
    } else if (strcmp(mode, "no-device") == 0) {
        ggxcl_sampler* sampler = NULL;
        expect_status(ggxcl_sampler_create("", &sampler), GGXCL_DEVICE_ERROR, "OpenCL", "no OpenCL platform");
    } else if (strcmp(mode, "no-cache") == 0) {
        const char* dir = NULL;
        expect_status(ggxcl_device_include_dir(&dir), GGXCL_ERROR, "cannot write the device headers",
                      "no writable cache");
    } else if (strcmp(mode, "out-of-memory") == 0) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
        /* The sanitizers' allocators end the process when operator new fails instead of
         * throwing: this status is provoked by the plain build's run. */
        printf("c_consumer out-of-memory: not under a sanitizer (its new aborts instead of throwing)\n");
        return 0;
#else
        ggxcl_params params;
        ggxcl_sampler* sampler = NULL;
        float one = 0.0f;
        ggxcl_default_params(&params);
        MUST(ggxcl_sampler_create("", &sampler));
        expect_status(ggxcl_pdf(sampler, &params, (size_t)1 << 46, &one, &one), GGXCL_OUT_OF_HOST_MEMORY,
                      "out of host memory", "2^46 directions");
        ggxcl_sampler_release(sampler);
#endif
    } else {
        fprintf(stderr, "usage: c_consumer bits DUMP USER_DIR | threads DUMP | vulkan DUMP VK_DUMP USER_DIR | no-device | "
                        "no-cache | out-of-memory\n");
        return 2;
    }
    if (failures)
        fprintf(stderr, "c_consumer %s: %d check(s) failed\n", mode, failures);
    else
        printf("c_consumer %s: ok\n", mode);
    return failures ? 1 : 0;
}
