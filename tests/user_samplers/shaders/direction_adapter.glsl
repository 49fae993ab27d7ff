// direction_adapter.glsl - an engine-style GLSL sampler that returns the
// outgoing direction and its pdf (Heitz 2018's visible normals, written for
// this test), and the adapter that fills the whole ggx_sample from it, as
// docs/USER-SAMPLERS.md shows.  Must pass every check.
const float kPi = 3.14159265358979;

// A visible normal: V stretched, a point on the projected half disk in its
// frame, lifted to the hemisphere, stretched back (Heitz 2018, listing 1's
// steps in words).
vec3 engineVisibleNormal(vec3 V, vec2 alpha, vec2 u)
{
    vec3 vh = normalize(vec3(alpha.x * V.x, alpha.y * V.y, V.z));
    float len2 = vh.x * vh.x + vh.y * vh.y;
    vec3 t1 = len2 > 0.0 ? vec3(-vh.y, vh.x, 0.0) * inversesqrt(len2) : vec3(1.0, 0.0, 0.0);
    vec3 t2 = cross(vh, t1);
    float r = sqrt(u.x), phi = 2.0 * kPi * u.y;
    float p1 = r * cos(phi), p2 = r * sin(phi);
    float s = 0.5 * (1.0 + vh.z);
    p2 = (1.0 - s) * sqrt(1.0 - p1 * p1) + s * p2;
    vec3 nh = p1 * t1 + p2 * t2 + sqrt(max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
    return normalize(vec3(alpha.x * nh.x, alpha.y * nh.y, max(0.0, nh.z)));
}

float engineReflectionPdf(vec3 V, vec3 L, vec2 alpha)
{
    vec3 m = normalize(V + L);
    float vm = dot(V, m);
    if (vm <= 0.0 || m.z <= 0.0)
        return 0.0;
    vec3 sm = vec3(m.x / alpha.x, m.y / alpha.y, m.z);
    float k = dot(sm, sm);
    float D = 1.0 / (kPi * alpha.x * alpha.y * k * k);
    float lambda = 0.5 * (sqrt(1.0 + (alpha.x * alpha.x * V.x * V.x + alpha.y * alpha.y * V.y * V.y) / (V.z * V.z)) - 1.0);
    return D / ((1.0 + lambda) * 4.0 * V.z);
}

vec3 engineSampleReflection(vec3 V, vec2 alpha, vec2 u, out float pdf)
{
    vec3 L = reflect(-V, engineVisibleNormal(V, alpha, u));
    pdf = engineReflectionPdf(V, L, alpha);
    return L;
}

// The adapter.
#define GGX_USER_DISTRIBUTION GGX_USER_VNDF

ggx_sample ggx_user_sample(vec3 i, float ax, float ay, float u1, float u2)
{
    float pdf;
    vec3 o = engineSampleReflection(i, vec2(ax, ay), vec2(u1, u2), pdf);
    ggx_sample s;
    s.m = normalize(i + o);
    s.o = o;
    s.pdf_o = pdf;
    s.pdf_m = 4.0 * abs(dot(i, s.m)) * pdf;
    s.weight = pdf > 0.0 ? ggx_eval_reflection(i, o, ax, ay) / pdf : 0.0;
    return s;
}

float ggx_user_pdf(vec3 i, vec3 o, float ax, float ay)
{
    return engineReflectionPdf(i, o, vec2(ax, ay));
}
