/* c_api_cases.h - the requests test_c_api makes through the C++ API
 * (cpp_dump.cpp) and through the C API (c_consumer.c), which must give the
 * same bits: every method, a rough dielectric and a user sampler, one view
 * and roughness each (caps-iso isotropic), samples CASE_FIRST .. of stream
 * CASE_SEED, planes CASE_STRIDE floats apart.  Plain C: both include it. */
#ifndef GGX_C_API_CASES_H
#define GGX_C_API_CASES_H

#define CASE_COUNT 1000u
#define CASE_STRIDE 1003u
#define CASE_SEED 11u
#define CASE_FIRST 5u

struct api_case {
    int method;        /* GGX_METHOD_* (GGX_METHOD_USER: the user sampler below) */
    float eta;         /* 0: a conductor */
    int importance;    /* a dielectric's transport: importance (1) or radiance (0) */
};
#define CASE_USER_FILE "caps_copy.h" /* in tests/user_samplers */
#define CASE_USER_SHADER "shaders/caps_copy.glsl" /* the same sampler for Vulkan */

/* Every built-in method, caps as a dielectric in importance transport, and a user sampler. */
static const struct api_case api_cases[] = {
    {GGX_METHOD_NDF, 0.0f, 0},  {GGX_METHOD_HEITZ, 0.0f, 0}, {GGX_METHOD_HEITZ2017, 0.0f, 0},
    {GGX_METHOD_CAPS, 0.0f, 0}, {GGX_METHOD_CAPS_ISO, 0.0f, 0}, {GGX_METHOD_BOUNDED, 0.0f, 0},
    {GGX_METHOD_CAPS, 1.5f, 1}, {GGX_METHOD_USER, 0.0f, 0}};
#define CASE_TOTAL (sizeof api_cases / sizeof api_cases[0])

/* The view (60 degrees from the normal, azimuth 30) and roughness of a case. */
static const float case_view[3] = {0.75f, 0.4330127f, 0.5f};
static float case_alpha_x(const struct api_case* c) { return c->method == GGX_METHOD_CAPS_ISO ? 0.3f : 0.2f; }
static float case_alpha_y(const struct api_case* c) { return c->method == GGX_METHOD_CAPS_ISO ? 0.3f : 0.45f; }

/* Floats of one case in the dump, planes CASE_COUNT apart: m (planes 0-2),
 * o (3-5), pdf_m (6), pdf_o (7), weight (8), u (9-11: u3 only for a
 * dielectric, else zeros), then the pdf (12) and the BSDF value (13) of the
 * sampled o. */
#define CASE_PLANES 14u
#define CASE_FLOATS (CASE_PLANES * CASE_COUNT)
enum { PLANE_M = 0, PLANE_O = 3, PLANE_PDF_M = 6, PLANE_PDF_O = 7, PLANE_WEIGHT = 8, PLANE_U = 9, PLANE_PDF = 12,
       PLANE_EVAL = 13 };

#endif
