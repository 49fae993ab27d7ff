/* sample_into_buffers.c - GGX samples from C into buffers of your own: a
 * context and queue on the device ggxcl picks, two cl_mem buffers, one
 * ggxcl_enqueue of `n` caps samples (o and its weight) and a read back,
 * then the white-furnace estimate from the weights.
 *   sample_into_buffers [N]      (default 1048576) */
#include <stdio.h>
#include <stdlib.h>

#include <ggxcl/ggxcl.h>

static int fail(const char* what, ggxcl_status status)
{
    fprintf(stderr, "%s: %s: %s\n", what, ggxcl_status_string(status), ggxcl_last_error());
    return 1;
}

int main(int argc, char** argv)
{
    uint32_t n = argc > 1 ? (uint32_t)strtoul(argv[1], NULL, 10) : 1u << 20;
    ggxcl_sampler* sampler = NULL;
    ggxcl_status status = ggxcl_sampler_create(NULL, &sampler); /* GGXCL_DEVICE, else the first device */
    cl_device_id device;
    cl_context context;
    cl_command_queue queue;
    cl_mem o, weight;
    cl_event done;
    cl_int error;
    ggxcl_params params;
    ggxcl_range range = {1, 0, 0};
    ggxcl_device_outputs outputs = {{0}};
    float* host;
    double sum = 0.0;
    uint32_t j;
    if (status != GGXCL_SUCCESS)
        return fail("ggxcl_sampler_create", status);
    if (n == 0)
        return fprintf(stderr, "N must be 1 .. 4294967295\n"), 2;

    /* Our own context, queue and buffers; a sampler on them. */
    device = ggxcl_sampler_device(sampler);
    context = clCreateContext(NULL, 1, &device, NULL, NULL, &error);
    queue = clCreateCommandQueue(context, device, 0, &error);
    ggxcl_sampler_release(sampler);
    if ((status = ggxcl_sampler_create_with_context(context, device, &sampler)) != GGXCL_SUCCESS)
        return fail("ggxcl_sampler_create_with_context", status);
    o = clCreateBuffer(context, CL_MEM_READ_WRITE, 3 * sizeof(float) * n, NULL, &error);
    weight = clCreateBuffer(context, CL_MEM_READ_WRITE, sizeof(float) * n, NULL, &error);

    /* caps at 60 degrees from the normal, alpha 0.3: o (3 planes of n) and the weight. */
    ggxcl_default_params(&params);
    params.view[0] = 0.8660254f, params.view[1] = 0.0f, params.view[2] = 0.5f;
    range.count = n;
    outputs.o.mem = o;
    outputs.weight.mem = weight;
    status = ggxcl_enqueue(sampler, queue, &params, &range, &outputs, 0, NULL, 0, NULL, &done);
    if (status != GGXCL_SUCCESS)
        return fail("ggxcl_enqueue", status);

    host = malloc(sizeof(float) * n);
    clEnqueueReadBuffer(queue, weight, CL_TRUE, 0, sizeof(float) * n, host, 1, &done, NULL);
    for (j = 0; j < n; ++j)
        sum += host[j];
    printf("%u samples of %s on %s (ggxcl %s): directional albedo %.5f\n", n, ggxcl_method_name(params.method),
           ggxcl_sampler_device_name(sampler), ggxcl_version(), sum / n);

    free(host);
    clReleaseEvent(done);
    clReleaseMemObject(o), clReleaseMemObject(weight);
    clReleaseCommandQueue(queue), clReleaseContext(context);
    ggxcl_sampler_release(sampler);
    return 0;
}
