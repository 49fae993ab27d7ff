// engine_vndf.hlsl - GGX reflection sampling written as an engine ships it
// in HLSL, with no ggxcl in it: tangent space (the normal is +z), V and L
// unit and pointing away from the surface, alpha = (alpha_x, alpha_y),
// u = two uniforms in [0, 1).  The visible normals are drawn by spherical
// caps (Dupuy & Benyoub 2023); the pdf is the density of L per steradian.
#pragma once

static const float kEnginePi = 3.14159265358979f;

// The GGX distribution of normals D(m) (Walter et al. 2007, eq. 33, in its
// anisotropic form): 1 / (pi ax ay ((mx/ax)^2 + (my/ay)^2 + mz^2)^2).
float EngineGgxD(float3 m, float2 alpha)
{
    if (m.z <= 0.0f)
        return 0.0f;
    float3 stretched = float3(m.x / alpha.x, m.y / alpha.y, m.z);
    float k = dot(stretched, stretched);
    return 1.0f / (kEnginePi * alpha.x * alpha.y * k * k);
}

// Smith's masking of v, G1 = 1 / (1 + Lambda(v)) with GGX's Lambda
// (Heitz 2014, eq. 86): 2 / (1 + sqrt(1 + (ax^2 vx^2 + ay^2 vy^2) / vz^2)).
float EngineSmithG1(float3 v, float2 alpha)
{
    float slope2 = (alpha.x * alpha.x * v.x * v.x + alpha.y * alpha.y * v.y * v.y) / (v.z * v.z);
    return 2.0f / (1.0f + sqrt(1.0f + slope2));
}

// A visible normal for the view V: V stretched to roughness 1, a point
// drawn uniformly on the part of the unit sphere above the plane
// z = -V'.z (its height uniform in [-V'.z, 1], its azimuth uniform), plus
// V', stretched back and normalized (Dupuy & Benyoub 2023, sec. 3).
float3 EngineSampleVisibleNormal(float3 V, float2 alpha, float2 u)
{
    float3 v = normalize(float3(alpha.x * V.x, alpha.y * V.y, V.z));
    float z = 1.0f - u.x * (1.0f + v.z);
    float r = sqrt(saturate(1.0f - z * z));
    float phi = 2.0f * kEnginePi * u.y;
    float3 h = float3(r * cos(phi), r * sin(phi), z) + v;
    return normalize(float3(alpha.x * h.x, alpha.y * h.y, h.z));
}

// The density of the reflection L of V about a visible normal: the visible
// normals' G1(V) max(0, V.m) D(m) / V.z (Heitz 2018, eq. 1) times the
// reflection's Jacobian 1 / (4 V.m) (Walter et al. 2007, eq. 14).
float EngineReflectionPdf(float3 V, float3 L, float2 alpha)
{
    float3 h = V + L;
    if (dot(h, h) <= 0.0f)
        return 0.0f;
    float3 m = normalize(h);
    if (dot(V, m) <= 0.0f)
        return 0.0f;
    return EngineSmithG1(V, alpha) * EngineGgxD(m, alpha) / (4.0f * V.z);
}

// The reflected direction L for the view V, as engines return it: a visible
// normal, V reflected about it (HLSL's reflect(-V, m) = 2 (V.m) m - V), and
// its density in `pdf`.
float3 EngineSampleReflection(float3 V, float2 alpha, float2 u, out float pdf)
{
    float3 m = EngineSampleVisibleNormal(V, alpha, u);
    float3 L = reflect(-V, m);
    pdf = EngineReflectionPdf(V, L, alpha);
    return L;
}
