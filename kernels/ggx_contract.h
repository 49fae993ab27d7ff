// ggx_contract.h - what the C++ runtime and the OpenCL C kernels must agree
// on, as plain macros that both languages read: the list of methods, the field
// ids and their write-mask bits, the sequence ids of the uniforms, the
// argument positions of every bulk kernel and the bulk shader's push
// constants, and the samples per work-item of the fused estimator.  The runtime makes its method enum from the list and
// checks its other enums against the ids at compile time
// (lib/src/device_contract.hpp: a mismatch does not build); the kernels
// include it and refuse an unknown method id or write mask.
// Every value is a plain integer, usable in #if.  It compiles as OpenCL C,
// C++, CUDA, GLSL and HLSL.
#ifndef GGX_CONTRACT_H
#define GGX_CONTRACT_H

// The methods and their traits, in id order, one line each:
//   X(ID, identifier, name, paper, how, space, alpha, normals, dielectric, below, limits)
// ID gives the id GGX_METHOD_<ID> (-DGGX_METHOD=<id>, ggx_sample_method),
// identifier the C++ enumerator (ggxcl::Method::<identifier>,
// ggxref::Method::<identifier>), name the name users type, paper the source,
// how what the method does, in a line.
// The traits, each read where a rule depends on it (kernels/ggx_method_traits.h
// on the device, ggxcl::method_traits on the host):
//   space      - TANGENT: i, m, o about +z, the normal unread; WORLD: about
//                the normal the caller gives (GGX_SPACE_*);
//   alpha      - ANISOTROPIC: any (alpha_x, alpha_y); ISOTROPIC: alpha_x == alpha_y only;
//   normals    - the density the sampled normals follow (GGX_NORMALS_*): VNDF
//                the visible normals, NDF the normals D(m) mz, OWN a density of
//                the method's own, given by its pdf alone;
//   dielectric - YES: a rough dielectric sampler (eta != 0); NO: conductors only;
//   below      - YES: correct for views below the horizon; NO: views above it only;
//   limits     - why a NO holds, for messages ("" when none does).
// Every list of methods in the project is made from this one: the C++ enums,
// all_methods and method_table, the name tables, the device dispatchers and
// trait functions, the native baseline's loops, the CUDA test's kernels, the
// Python module's table and `ggx methods`.  A new method needs its line here,
// its header of device functions (included by ggx_samplers.h) and its
// reference (reference/, which keeps its own math).
#define GGX_METHOD_LIST(X)                                                                                   \
    X(NDF, ndf, "ndf", "Walter et al. 2007, Microfacet models for refraction through rough surfaces",        \
      "the normals D(m) mz; cheap, but reflections can land below the horizon and weights vary most",       \
      TANGENT, ANISOTROPIC, NDF, YES, YES, "")                                                               \
    X(HEITZ, heitz, "heitz", "Heitz 2018, Sampling the GGX distribution of visible normals (JCGT 7(4))",     \
      "a warped disk in a basis around the stretched view", TANGENT, ANISOTROPIC, VNDF, YES, YES, "")       \
    X(HEITZ2017, heitz2017, "heitz2017",                                                                     \
      "Heitz 2017, A simpler and exact sampling routine for the GGX VNDF (hal-01509746)",                    \
      "two half disks", TANGENT, ANISOTROPIC, VNDF, YES, NO,                                                 \
      "its two half disks assume a view above the horizon (iz >= 0); heitz (2018) takes any view")         \
    X(CAPS, caps, "caps", "Dupuy & Benyoub 2023, Sampling visible GGX normals with spherical caps",          \
      "no basis: the half vector of the view and a uniform direction in a spherical cap",                   \
      TANGENT, ANISOTROPIC, VNDF, YES, YES, "")                                                              \
    X(CAPS_ISO, caps_iso, "caps-iso",                                                                        \
      "Benyoub 2024, VNDF importance sampling for an isotropic Smith-GGX distribution (blog)",               \
      "caps about the world-space normal, no local basis; singular at n = -z", WORLD, ISOTROPIC, VNDF, YES, \
      YES, "it samples about the world-space normal, which fixes no tangent, so alpha is one value")       \
    X(BOUNDED, bounded, "bounded", "Eto & Tokuyoshi 2023, Bounded VNDF sampling for Smith-GGX reflections",  \
      "a tighter cap: fewer reflections below the horizon, lower variance", TANGENT, ANISOTROPIC, OWN, NO,  \
      YES,                                                                                                   \
      "its cap leaves out microfacet normals that refract, so it cannot sample every transmitted "         \
      "direction; use caps (or heitz) for dielectrics")

// The values of the trait columns, by the names the list uses.
#define GGX_SPACE_TANGENT 0
#define GGX_SPACE_WORLD 1
#define GGX_ALPHA_ANISOTROPIC 0
#define GGX_ALPHA_ISOTROPIC 1
#define GGX_NORMALS_VNDF 0
#define GGX_NORMALS_NDF 1
#define GGX_NORMALS_OWN 2
#define GGX_TRAIT_NO 0
#define GGX_TRAIT_YES 1

// The method ids, the list's order (ggxcl/method.hpp checks it at compile
// time): plain integers, usable in #if and in the shading languages, which
// have no enum.
#define GGX_METHOD_NDF 0
#define GGX_METHOD_HEITZ 1
#define GGX_METHOD_HEITZ2017 2
#define GGX_METHOD_CAPS 3
#define GGX_METHOD_CAPS_ISO 4
#define GGX_METHOD_BOUNDED 5
// The number of methods, (0 +1 +1 ...): usable in #if.  (Macros that the
// shading languages' headers use name every column: glslang has no `...`.)
#define GGX_METHOD_COUNT_ONE(ID, identifier, name, paper, how, space, alpha, normals, dielectric, below, limits) +1
#define GGX_METHOD_COUNT (0 GGX_METHOD_LIST(GGX_METHOD_COUNT_ONE))

// The method id of a user sampler (one file that defines the functions of
// kernels/ggx_user_sampler.h; the runtime builds it with -DGGX_USER_SAMPLER=1):
// outside GGX_METHOD_LIST, so no list of built-in methods holds it.  A plain
// integer, usable in #if.
#define GGX_METHOD_USER 64

// The distribution a user sampler claims its normals follow, which its file
// states as `#define GGX_USER_DISTRIBUTION GGX_USER_<one of these>`: the
// GGX visible normals (as heitz and caps), the GGX normals D(m) mz (as ndf),
// or a density of its own (as bounded), given by its pdf alone.
#define GGX_USER_VNDF GGX_NORMALS_VNDF
#define GGX_USER_NDF GGX_NORMALS_NDF
#define GGX_USER_OWN GGX_NORMALS_OWN

// C++ enums of the methods: `enum class Method { GGX_METHOD_LIST(GGX_METHOD_ENUMERATOR) };`
// and their arrays in id order, `{GGX_METHOD_LIST(GGX_METHOD_ENUMERATOR_OF)}` with
// GGX_METHOD_ENUM defined as the enum's name.
#if defined(__cplusplus)
#define GGX_METHOD_ENUMERATOR(ID, identifier, ...) identifier = GGX_METHOD_##ID,
#define GGX_METHOD_ENUMERATOR_OF(ID, identifier, ...) GGX_METHOD_ENUM::identifier,
#endif

// Field ids, in ggxcl::Field order: the order of the sample kernel's output
// buffers; -DGGX_WRITE_MASK=<mask> has bit (1 << id) set for each field
// computed and stored.
#define GGX_FIELD_M 0
#define GGX_FIELD_O 1
#define GGX_FIELD_PDF_M 2
#define GGX_FIELD_PDF_O 3
#define GGX_FIELD_WEIGHT 4
#define GGX_FIELD_U 5
#define GGX_FIELD_COUNT 6

// Where a sample's two uniforms come from (-DGGX_SEQUENCE=<id>), in
// ggxcl::Sequence order: Philox2x32-10 (ggx_philox.h) or the Owen-scrambled
// Sobol points (ggx_sobol.h).  -DGGX_PER_SAMPLE_UNIFORMS=1 reads the caller's
// uniforms instead.
#define GGX_SEQUENCE_PHILOX 0
#define GGX_SEQUENCE_SOBOL 1
#define GGX_SEQUENCE_COUNT 2

// The precision modes (ggxcl::Precision: which options a program is built
// with) and the transport modes of a rough dielectric's transmission
// (ggxcl::Transport: -DGGX_IMPORTANCE=1 for importance), in the order of the
// C++ enums and of the C API's (ggxcl/ggxcl.h).
#define GGX_PRECISION_PRECISE 0
#define GGX_PRECISION_RELAXED 1
#define GGX_PRECISION_COUNT 2
#define GGX_TRANSPORT_RADIANCE 0
#define GGX_TRANSPORT_IMPORTANCE 1
#define GGX_TRANSPORT_COUNT 2

// Argument positions of the sampling kernels: ggx_sample_bulk(_tail),
// ggx_furnace_bulk, ggx_histogram and ggx_histogram_bins(_tail) begin with
//   seed, first, count, stride (the histogram kernels: samples per work-item),
// then the GGX_PARAM_ARG_COUNT parameter arguments of GGX_PARAM_KERNEL_ARGS
// (ggx_bulk_params.h): view x, y, z, alpha x, y, normal x, y, z, eta, the
// per-sample view, alpha, normal and uniforms buffers, and their offsets.
// Their outputs follow: ggx_sample_bulk's six buffers in field order and
// then their six offsets, the furnace's partial sums and their offset, the
// histogram's counts or the bin indices.  Every caller's buffer comes with
// an offset in floats (a ulong) where its planes begin, as CLBlast's kernels
// take them: the runtime passes the caller's buffer as it is.
#define GGX_ARG_SEED 0
#define GGX_ARG_FIRST 1
#define GGX_ARG_COUNT 2
#define GGX_ARG_STRIDE 3
#define GGX_ARG_PARAMS 4
#define GGX_PARAM_UNIFORM_COUNT 9  // the floats before the buffers
#define GGX_PARAM_BUFFER_COUNT 4   // view, alpha, normal, uniforms; then as many offsets
#define GGX_PARAM_ARG_COUNT (GGX_PARAM_UNIFORM_COUNT + 2 * GGX_PARAM_BUFFER_COUNT)
#define GGX_ARG_OUTPUTS (GGX_ARG_PARAMS + GGX_PARAM_ARG_COUNT)
#define GGX_ARG_OUTPUT_OFFSETS (GGX_ARG_OUTPUTS + GGX_FIELD_COUNT)
#define GGX_ARG_SUMS_OFFSET (GGX_ARG_OUTPUTS + 1)

// ggx_pdf_bulk(_tail): count, stride, the parameter arguments, the
// directions, the pdfs, and the offsets of those two.
#define GGX_PDF_ARG_COUNT 0
#define GGX_PDF_ARG_STRIDE 1
#define GGX_PDF_ARG_PARAMS 2
#define GGX_PDF_ARG_DIRECTIONS (GGX_PDF_ARG_PARAMS + GGX_PARAM_ARG_COUNT)
#define GGX_PDF_ARG_PDFS (GGX_PDF_ARG_DIRECTIONS + 1)
#define GGX_PDF_ARG_DIRECTIONS_OFFSET (GGX_PDF_ARG_DIRECTIONS + 2)
#define GGX_PDF_ARG_PDFS_OFFSET (GGX_PDF_ARG_DIRECTIONS + 3)

// The bulk sampling shader's push constants (kernels/ggx_bulk_shader.h), in
// order, for the shader's block and the runtime's struct alike (`uint` a
// 32-bit unsigned integer): seed and first as low and high words, count,
// plane stride, invocations per row of a 2-D dispatch, the uniform
// parameters, each output field's offset in floats in the output buffer
// (GGX_FIELD_* order) and each per-sample input's in the input buffer.  26
// words, 104 of the 128 bytes every Vulkan device has.
#define GGX_BULK_REQUEST_MEMBERS                                                                   \
    uint seed_lo; uint seed_hi; uint first_lo; uint first_hi;                                       \
    uint count; uint stride; uint row_width;                                                        \
    float view_x; float view_y; float view_z; float alpha_x; float alpha_y;                         \
    float normal_x; float normal_y; float normal_z; float eta;                                      \
    uint m_at; uint o_at; uint pdf_m_at; uint pdf_o_at; uint weight_at; uint u_at;                  \
    uint view_at; uint alpha_at; uint normal_at; uint uniforms_at;
#define GGX_BULK_REQUEST_WORDS 26

// ggx_histogram_count: bin indices, their count, indices per work-item, counts.
#define GGX_COUNT_ARG_BINS 0
#define GGX_COUNT_ARG_COUNT 1
#define GGX_COUNT_ARG_PER_ITEM 2
#define GGX_COUNT_ARG_COUNTS 3

// Samples each work-item of ggx_furnace_bulk draws.
#define GGX_FURNACE_PER_ITEM 8

#endif
