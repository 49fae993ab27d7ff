/* c_api_cases.h - the requests test_c_api makes through the C++ API
 * (cpp_dump.cpp) and through the C API (c_consumer.c), which must give the
 * same bits: every method, one view and roughness each (caps-iso and world
 * space isotropic), samples `first` .. of stream `seed`, planes `stride`
 * floats apart. */
#ifndef GGX_C_API_CASES_H
#define GGX_C_API_CASES_H

#define CASE_COUNT 1000u
#define CASE_STRIDE 1003u
#define CASE_SEED 11u
#define CASE_FIRST 5u

/* The view (60 degrees from the normal, azimuth 30) and roughness of a method id. */
static const float case_view[3] = {0.75f, 0.4330127f, 0.5f};
static float case_alpha_x(int method) { return method == GGX_METHOD_CAPS_ISO ? 0.3f : 0.2f; }
static float case_alpha_y(int method) { return method == GGX_METHOD_CAPS_ISO ? 0.3f : 0.45f; }

/* Floats of one method in the dump, planes CASE_COUNT apart: m (planes 0-2),
 * o (3-5), pdf_m (6), pdf_o (7), weight (8), u (9-10), then the pdf (11) and
 * the BSDF value (12) of the sampled o. */
#define CASE_FLOATS (13u * CASE_COUNT)

#endif
