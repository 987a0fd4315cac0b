// GLSL sources of the viewer. Every function names the CPU code it mirrors; keep them in step.
#include "shaders.h"

#include <string>

namespace ivis::app::shaders {
namespace {

const char* const kVersion = "#version 430 core\n";

// Shared by both fragment shaders: the volume textures, the mesh buffers, colours and shading.
const char* const kCommon = R"GLSL(
// ---- volume (dense_slices.h): the CPU's dense far copy, the fine band and closest triangles, all
// R32F / R32I 3D textures fetched texel by texel (no filtering: the trilinear cells are the CPU's)
layout(binding = 1) uniform sampler3D uFar;
layout(binding = 2) uniform isampler3D uTriangles;
layout(binding = 3) uniform sampler2D uColormap;  // 256 x 1, linear RGB of core::colormap(name).at(i / 255)
layout(binding = 4) uniform sampler3D uBand;
uniform bool uVolumeReady;
uniform ivec3 uFarDims;
uniform vec3 uFarOrigin;        // world centre of far voxel (0,0,0)
uniform float uFarInvVoxel;
uniform float uOutside;         // phi outside the far box (the field's clamp value)
uniform bool uHasFineBand;      // the band refines the far copy near the surface
uniform float uTrustBelow;      // far values above this never use the band
uniform ivec3 uBandDims;
uniform vec3 uBandOrigin;       // world centre of band voxel (0,0,0)
uniform ivec3 uTriangleDims;
uniform vec3 uTriangleOrigin;   // world centre of triangle voxel (0,0,0)
uniform float uVoxel;           // voxel size of band and triangles (the fine voxel unless resampled)
uniform float uInvVoxel;
uniform bool uUnsigned;         // phi is an unsigned distance (open mesh)

// ---- mesh: the vertex buffers, read again as storage buffers
layout(std430, binding = 0) readonly buffer VertexPositions { vec4 vertexPosition[]; };  // xyz, w = scalar (NaN -> 0)
layout(std430, binding = 1) readonly buffer VertexNormals { vec4 vertexNormal[]; };      // xyz, w = 1 where NaN
layout(std430, binding = 2) readonly buffer TriangleIndices { uint triangleIndex[]; };

// ---- look (render::ShadingOptions)
uniform bool uHasScalar;
uniform int uDataTriangles;     // triangles at or above this index are hole caps
uniform vec2 uRange;            // scalar range lo, hi
uniform vec3 uNanColour;
uniform vec3 uNoDataColour;

// render::detail::trilinear: corners c[dx | dy << 1 | dz << 2], gradient in index units.
float trilinear(float c[8], vec3 t, out vec3 gradient)
{
    float x00 = c[0] + t.x * (c[1] - c[0]);
    float x10 = c[2] + t.x * (c[3] - c[2]);
    float x01 = c[4] + t.x * (c[5] - c[4]);
    float x11 = c[6] + t.x * (c[7] - c[6]);
    float y0 = x00 + t.y * (x10 - x00);
    float y1 = x01 + t.y * (x11 - x01);
    float dx0 = (c[1] - c[0]) + t.y * ((c[3] - c[2]) - (c[1] - c[0]));
    float dx1 = (c[5] - c[4]) + t.y * ((c[7] - c[6]) - (c[5] - c[4]));
    gradient = vec3(dx0 + t.z * (dx1 - dx0), (x10 - x00) + t.z * ((x11 - x01) - (x10 - x00)), y1 - y0);
    return y0 + t.z * (y1 - y0);
}

// render::DenseGrid::valueAndGradient on the far copy (gradient in world units).
float farValueAndGradient(vec3 p, out vec3 gradient)
{
    gradient = vec3(0.0);
    vec3 q = (p - uFarOrigin) * uFarInvVoxel;
    vec3 f = floor(q);
    if (!(all(greaterThanEqual(f, vec3(0.0))) && all(lessThan(f, vec3(uFarDims - 1))))) return uOutside;
    ivec3 b = ivec3(f);
    float c[8];
    for (int i = 0; i < 8; ++i) c[i] = texelFetch(uFar, b + ivec3(i & 1, (i >> 1) & 1, (i >> 2) & 1), 0).r;
    float value = trilinear(c, q - f, gradient);
    gradient *= uFarInvVoxel;
    return value;
}

// render::DistanceField::Sampler::fineCell: the 8 band values of p's cell, false unless all are in the band.
bool bandCell(vec3 p, out float c[8], out vec3 t)
{
    vec3 q = (p - uBandOrigin) * uInvVoxel;
    vec3 f = floor(q);
    t = q - f;
    if (!(all(greaterThanEqual(f, vec3(0.0))) && all(lessThan(f, vec3(uBandDims - 1))))) return false;
    ivec3 b = ivec3(f);
    for (int i = 0; i < 8; ++i) {
        c[i] = texelFetch(uBand, b + ivec3(i & 1, (i >> 1) & 1, (i >> 2) & 1), 0).r;
        if (c[i] > 1e29) return false;  // kInactiveBandValue
    }
    return true;
}

// render::DistanceField::Sampler::phiAndGradient: the far copy, refined by the fine band where
// all eight corners of the fine cell are in the band.
float phiAndGradient(vec3 p, out vec3 gradient)
{
    float far = farValueAndGradient(p, gradient);
    if (!uHasFineBand || far > uTrustBelow) return far;
    float c[8];
    vec3 t, bandGradient;
    if (!bandCell(p, c, t)) return far;
    float value = trilinear(c, t, bandGradient);
    gradient = bandGradient * uInvVoxel;
    return value;
}

// render::DistanceField::Sampler::phi
float phiAt(vec3 p)
{
    vec3 gradient;
    return phiAndGradient(p, gradient);
}

uvec3 triangleVertices(int triangle)
{
    uint i = 3u * uint(triangle);
    return uvec3(triangleIndex[i], triangleIndex[i + 1u], triangleIndex[i + 2u]);
}

// render::triangleNormal
vec3 triangleNormal(int triangle)
{
    uvec3 v = triangleVertices(triangle);
    vec3 a = vertexPosition[v.x].xyz, b = vertexPosition[v.y].xyz, c = vertexPosition[v.z].xyz;
    vec3 n = cross(b - a, c - a);
    float len = length(n);
    return len > 0.0 ? n / len : vec3(0.0, 0.0, 1.0);
}

// render::shadingNormal: barycentric blend of the vertex normals.
vec3 shadingNormal(int triangle, vec3 barycentric)
{
    uvec3 v = triangleVertices(triangle);
    vec3 n = barycentric.x * vertexNormal[v.x].xyz + barycentric.y * vertexNormal[v.y].xyz +
             barycentric.z * vertexNormal[v.z].xyz;
    float len = length(n);
    return len > 1e-3 ? n / len : triangleNormal(triangle);
}

// core::ScalarRange::normalized
float normalizedScalar(float value)
{
    if (uRange.x == uRange.y) return 0.5;
    return clamp((value - uRange.x) / (uRange.y - uRange.x), 0.0, 1.0);
}

// core::Colormap::at, tabulated at 256 points and interpolated linearly.
vec3 colormap(float t)
{
    return texture(uColormap, vec2((clamp(t, 0.0, 1.0) * 255.0 + 0.5) / 256.0, 0.5)).rgb;
}

// render::Shader::albedo for a point of @a triangle whose interpolated scalar is @a value.
vec3 albedo(int triangle, float value)
{
    if (!uHasScalar || triangle >= uDataTriangles) return uNoDataColour;
    uvec3 v = triangleVertices(triangle);
    if (vertexNormal[v.x].w + vertexNormal[v.y].w + vertexNormal[v.z].w > 0.0) return uNanColour;
    return colormap(normalizedScalar(value));
}

// core::srgbFromLinear: the colour attachment holds sRGB-encoded 8-bit values, as the PNGs do.
vec3 srgbFromLinear(vec3 c)
{
    c = clamp(c, 0.0, 1.0);
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, greaterThan(c, vec3(0.0031308)));
}
)GLSL";

const char* const kMeshVertex = R"GLSL(
layout(location = 0) in vec4 aPositionScalar;
layout(location = 1) in vec4 aNormalNan;
uniform mat4 uClipFromWorld;
out vec3 vPosition;
out vec3 vNormal;
out float vScalar;
void main()
{
    vPosition = aPositionScalar.xyz;
    vNormal = aNormalNan.xyz;
    vScalar = aPositionScalar.w;
    gl_Position = uClipFromWorld * vec4(aPositionScalar.xyz, 1.0);
}
)GLSL";

const char* const kMeshFragment = R"GLSL(
in vec3 vPosition;
in vec3 vNormal;
in float vScalar;
uniform vec3 uEye;
uniform vec3 uForward;
uniform bool uOrtho;
uniform vec3 uToLight;
uniform float uAmbient;
uniform bool uShadows;
layout(location = 0) out vec4 oColour;
layout(location = 1) out uint oRegion;

// render::shadowFactor: soft shadow toward the key light, sphere-traced through phi; on an unsigned
// field a wall thinner than a step shows up as phi falling then rising within two voxels.
float shadowFactor(vec3 point, vec3 normal, vec3 toLight)
{
    const float kSoftness = 8.0;
    float hitDistance = 0.5 * uVoxel;
    vec3 start = point + 2.0 * uVoxel * normal;
    float lit = 1.0;
    float t = uVoxel;
    float previousSlope = 0.0;
    for (int step = 0; step < 512 && t < 6.0; ++step) {
        vec3 gradient;
        float phi = phiAndGradient(start + t * toLight, gradient);
        if (phi < hitDistance) return 0.0;
        float slope = dot(gradient, toLight);
        if (phi < 2.0 * uVoxel && previousSlope < 0.0 && slope > 0.0 && uUnsigned) return 0.0;
        previousSlope = slope;
        lit = min(lit, kSoftness * phi / t);
        t += max(phi, 0.5 * uVoxel);
    }
    return clamp(lit, 0.0, 1.0);
}

// render::Shader::shade for a direct pixel (the rasteriser's barycentrics = the ray hit's).
void main()
{
    int triangle = gl_PrimitiveID;
    vec3 arrival = uOrtho ? uForward : normalize(vPosition - uEye);
    float len = length(vNormal);
    vec3 normal = len > 1e-3 ? vNormal / len : triangleNormal(triangle);
    if (dot(normal, arrival) > 0.0) normal = -normal;  // the side the point is seen from
    vec3 base = albedo(triangle, vScalar);
    float diffuse = max(0.0, dot(normal, uToLight));
    if (diffuse > 0.0 && uShadows && uVolumeReady) diffuse *= shadowFactor(vPosition, normal, uToLight);
    oColour = vec4(srgbFromLinear(base * (uAmbient + (1.0 - uAmbient) * diffuse)), 1.0);
    oRegion = 1u;
}
)GLSL";

const char* const kFullScreenVertex = R"GLSL(
void main()
{
    const vec2 corners[3] = vec2[](vec2(-1.0, -1.0), vec2(3.0, -1.0), vec2(-1.0, 3.0));
    gl_Position = vec4(corners[gl_VertexID], 1.0, 1.0);  // depth 1: passes only where no mesh was drawn
}
)GLSL";

const char* const kIndirectFragment = R"GLSL(
// ---- camera (core::CameraFrame)
uniform vec2 uViewport;         // width, height in pixels
uniform float uHalfHeight;      // tan(fov / 2), or the orthographic half height
uniform float uAspect;
uniform vec3 uEye;
uniform vec3 uRight;
uniform vec3 uUp;
uniform vec3 uForward;
uniform bool uOrtho;
uniform int uMethod;            // 2 neugebauer, 3 mirror, 4 inversevis, 5 inversevis-adaptive (render::Method)
uniform float uIndirectBrightness;
uniform float uEpsilon;         // landing threshold: phi < this
// ---- InverseVis (render::CurvedRayParams)
uniform float uAlpha;
uniform vec3 uAlphaProfile;     // inversevis-adaptive: a0, a1, a2 (render::AlphaProfile)
uniform float uMaxAlpha;        // inversevis-adaptive: the profile's clamp
uniform int uRetries;           // inversevis-adaptive: relaunches at half alpha of a ray that does not land
uniform float uStepSize;
uniform float uHullOffset;
uniform float uEscape;          // 0.999 * reach
uniform int uMaxSteps;
uniform int uMaxHullSteps;      // cap of the backward hull search (the CPU has none)
uniform vec3 uHullLo;
uniform vec3 uHullHi;
// ---- quadratic mirror (render::MirrorParams)
uniform float uMirrorW[5];
uniform float uMirrorZm;        // apex height in eye space
uniform int uMirrorMaxSteps;
// ---- ring map (render::RingLayout, pixels)
uniform vec2 uRingCentre;
uniform float uRingInner;
uniform float uRingOuter;
uniform vec2 uBackCentre;
uniform float uBackRadius;
uniform vec3 uRingOrigin;       // the centre c the ring rays start from
uniform int uRingMaxSteps;
uniform float uInteriorStep;    // largest trusted step where phi < 0 (inside a closed mesh)
uniform float uBoxHalf;         // 2.5: the volume's box

layout(location = 0) out vec4 oColour;
layout(location = 1) out uint oRegion;

const float kPi = 3.14159265358979;

// core::CameraFrame::ray for this fragment (pixel (0,0) is the top-left corner on the CPU).
void cameraRay(out vec3 origin, out vec3 direction)
{
    float x = gl_FragCoord.x, y = uViewport.y - gl_FragCoord.y;
    float sx = (2.0 * x / uViewport.x - 1.0) * uHalfHeight * uAspect;
    float sy = (1.0 - 2.0 * y / uViewport.y) * uHalfHeight;
    if (uOrtho) {
        origin = uEye + sx * uRight + sy * uUp;
        direction = uForward;
    } else {
        origin = uEye;
        direction = normalize(uForward + sx * uRight + sy * uUp);
    }
}

// ScreenMap::landedAt + Shader::shade for an indirect pixel: the nearest voxel's triangle, the
// exact closest point on it (core::closestPointOnTriangle), colour x 0.6 x (0.7 + 0.3 facing).
vec3 closestBarycentric(vec3 p, int triangle)
{
    uvec3 v = triangleVertices(triangle);
    vec3 a = vertexPosition[v.x].xyz, b = vertexPosition[v.y].xyz, c = vertexPosition[v.z].xyz;
    vec3 ab = b - a, ac = c - a, ap = p - a;
    float d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return vec3(1.0, 0.0, 0.0);
    vec3 bp = p - b;
    float d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return vec3(0.0, 1.0, 0.0);
    float vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
        float w = d1 / (d1 - d3);
        return vec3(1.0 - w, w, 0.0);
    }
    vec3 cp = p - c;
    float d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return vec3(0.0, 0.0, 1.0);
    float vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
        float w = d2 / (d2 - d6);
        return vec3(1.0 - w, 0.0, w);
    }
    float va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
        float w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return vec3(0.0, 1.0 - w, w);
    }
    float denom = va + vb + vc;
    if (denom <= 0.0) {  // degenerate: the closest vertex
        float da = dot(p - a, p - a), db = dot(p - b, p - b), dc = dot(p - c, p - c);
        if (da <= db && da <= dc) return vec3(1.0, 0.0, 0.0);
        return db <= dc ? vec3(0.0, 1.0, 0.0) : vec3(0.0, 0.0, 1.0);
    }
    float v2 = vb / denom, w2 = vc / denom;
    return vec3(1.0 - v2 - w2, v2, w2);
}

// Colour of an indirect pixel that shows point @a barycentric of @a triangle, seen along @a arrival.
vec3 shadeIndirect(int triangle, vec3 barycentric, vec3 arrival)
{
    float len = length(arrival);
    arrival = len > 0.0 ? arrival / len : uForward;
    vec3 normal = shadingNormal(triangle, barycentric);
    if (dot(normal, arrival) > 0.0) normal = -normal;
    float facing = -dot(normal, arrival);
    uvec3 v = triangleVertices(triangle);
    float value = barycentric.x * vertexPosition[v.x].w + barycentric.y * vertexPosition[v.y].w +
                  barycentric.z * vertexPosition[v.z].w;
    return albedo(triangle, value) * uIndirectBrightness * (0.7 + 0.3 * facing);
}

// ScreenMap::landedAt finds the exact closest surface point of p with a BVH query bounded by the
// distance to the triangle stored at the nearest voxel. Here: the closest point on the closest of
// the triangles stored at the 8 voxels around p (the nearest one among them). The exact closest
// triangle of a point within half a voxel of the surface is, but for near-ties, one of those.
bool closestStoredPoint(vec3 p, out int best, out vec3 bestBarycentric)
{
    vec3 q = floor((p - uTriangleOrigin) * uInvVoxel);
    best = -1;
    bestBarycentric = vec3(1.0, 0.0, 0.0);
    float bestDistance = 1e30;
    for (int i = 0; i < 8; ++i) {
        vec3 corner = q + vec3(float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1));
        if (!(all(greaterThanEqual(corner, vec3(0.0))) && all(lessThan(corner, vec3(uTriangleDims))))) continue;
        int triangle = texelFetch(uTriangles, ivec3(corner), 0).r;
        if (triangle < 0 || triangle == best) continue;
        vec3 barycentric = closestBarycentric(p, triangle);
        uvec3 v = triangleVertices(triangle);
        vec3 x = barycentric.x * vertexPosition[v.x].xyz + barycentric.y * vertexPosition[v.y].xyz +
                 barycentric.z * vertexPosition[v.z].xyz;
        float d = dot(p - x, p - x);
        if (d < bestDistance || (d == bestDistance && triangle < best)) {  // ties to the lower index, as the BVH
            bestDistance = d;
            best = triangle;
            bestBarycentric = barycentric;
        }
    }
    return best >= 0;
}

bool shadeLanding(vec3 p, vec3 arrival, out vec3 colour)
{
    colour = vec3(0.0);
    int triangle;
    vec3 barycentric;
    if (!closestStoredPoint(p, triangle, barycentric)) return false;
    colour = shadeIndirect(triangle, barycentric, arrival);
    return true;
}

// The ring map's CPU reference intersects its straight ray with the BVH. Here the ray was
// sphere-traced to within uEpsilon of the surface at p: intersect it exactly (Moller-Trumbore) with
// the triangles stored at the 8 voxels around p and take the first hit; when none is hit (grazing
// rays), take the closest stored point to p.
bool shadeRayLanding(vec3 origin, vec3 direction, vec3 p, out vec3 colour)
{
    colour = vec3(0.0);
    vec3 q = floor((p - uTriangleOrigin) * uInvVoxel);
    int hit = -1;
    vec3 hitBarycentric = vec3(1.0, 0.0, 0.0);
    float hitT = 1e30;
    for (int i = 0; i < 8; ++i) {
        vec3 corner = q + vec3(float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1));
        if (!(all(greaterThanEqual(corner, vec3(0.0))) && all(lessThan(corner, vec3(uTriangleDims))))) continue;
        int triangle = texelFetch(uTriangles, ivec3(corner), 0).r;
        if (triangle < 0 || triangle == hit) continue;
        uvec3 v = triangleVertices(triangle);
        vec3 a = vertexPosition[v.x].xyz, b = vertexPosition[v.y].xyz, c = vertexPosition[v.z].xyz;
        vec3 e1 = b - a, e2 = c - a, s1 = cross(direction, e2);
        float det = dot(s1, e1);
        if (abs(det) <= 1e-12) continue;
        vec3 ao = origin - a;
        float u = dot(ao, s1) / det;
        vec3 s2 = cross(ao, e1);
        float w = dot(direction, s2) / det, t = dot(e2, s2) / det;
        if (u >= 0.0 && w >= 0.0 && u + w <= 1.0 && t > 0.0 && t < hitT) {
            hitT = t;
            hit = triangle;
            hitBarycentric = vec3(1.0 - u - w, u, w);
        }
    }
    if (hit >= 0) {
        colour = shadeIndirect(hit, hitBarycentric, direction);
        return true;
    }
    return shadeLanding(p, direction, colour);
}

// ---- InverseVis (render/src/curved_ray.cpp, ScreenMap::inverseVis)
bool boxInterval(vec3 origin, vec3 direction, out float tEnter, out float tExit)
{
    tEnter = 0.0;
    tExit = 1e30;
    for (int a = 0; a < 3; ++a) {
        if (abs(direction[a]) < 1e-12) {
            if (origin[a] < uHullLo[a] || origin[a] > uHullHi[a]) return false;
            continue;
        }
        float t0 = (uHullLo[a] - origin[a]) / direction[a], t1 = (uHullHi[a] - origin[a]) / direction[a];
        if (t0 > t1) {
            float s = t0;
            t0 = t1;
            t1 = s;
        }
        tEnter = max(tEnter, t0);
        tExit = min(tExit, t1);
    }
    return tEnter < tExit;
}

// render::findHullExit: the FARTHEST crossing of {phi = phi0}, sphere-traced backward.
bool findHullExit(vec3 origin, vec3 direction, out vec3 seed)
{
    float tEnter, tExit;
    seed = origin;
    if (!boxInterval(origin, direction, tEnter, tExit)) return false;
    const float minStep = 1e-4;
    float tOutside = tExit;
    float t = tExit;
    for (int i = 0; i < uMaxHullSteps && t >= tEnter; ++i) {
        float excess = phiAt(origin + t * direction) - uHullOffset;
        if (excess <= 0.0) {
            float lo = t, hi = tOutside;
            for (int k = 0; k < 64 && hi - lo > 1e-5; ++k) {
                float mid = 0.5 * (lo + hi);
                if (phiAt(origin + mid * direction) <= uHullOffset) lo = mid;
                else hi = mid;
            }
            seed = origin + hi * direction;
            return true;
        }
        tOutside = t;
        t -= max(excess, minStep);
    }
    return false;
}

// ScreenMap::alphaOf: uAlpha, or for the adaptive method AlphaProfile::at of the seed's alignment
// c = r . g / |g| (ScreenMap::seedFromRay).
float alphaAt(vec3 gradient, vec3 viewDirection)
{
    if (uMethod != 5) return uAlpha;
    float len = length(gradient);
    float c = len > 0.0 ? dot(viewDirection, gradient) / len : 0.0;
    return clamp(uAlphaProfile.x + c * (uAlphaProfile.y + c * uAlphaProfile.z), 0.0, uMaxAlpha);
}

// render::initialVelocity: alpha times the part of the view direction tangential to the hull.
vec3 initialVelocity(vec3 gradient, vec3 viewDirection, float alpha)
{
    float len = length(gradient);
    if (!(len > 0.0)) return alpha * viewDirection;
    vec3 g = gradient / len;
    return alpha * cross(g, cross(viewDirection, g));
}

// render::integrateCurvedRay from @a p with velocity @a v: symplectic Euler, h = uStepSize; true
// when it lands (phi < uEpsilon), with p and v there.
bool integrateCurvedRay(inout vec3 p, inout vec3 v)
{
    vec3 gradient;
    for (int step = 0; step < uMaxSteps; ++step) {
        float phi = phiAndGradient(p, gradient);
        if (phi < uEpsilon) return true;
        if (phi >= uEscape) return false;
        v -= uStepSize * gradient;
        float speed = length(v);
        vec3 heading = speed > 0.0 ? v / speed : -gradient;
        p += uStepSize * phi * heading;
    }
    return false;
}

// ScreenMap::inverseVis and ScreenMap::traceFrom: the adaptive method relaunches a ray that does
// not land with half its alpha, up to uRetries times.
bool inverseVis(vec3 origin, vec3 direction, out vec3 colour)
{
    vec3 seed;
    colour = vec3(0.0);
    if (!findHullExit(origin, direction, seed)) return false;
    vec3 gradient;
    phiAndGradient(seed, gradient);
    float alpha = alphaAt(gradient, direction);
    int retries = uMethod == 5 ? uRetries : 0;
    for (int attempt = 0; attempt <= retries; ++attempt) {
        vec3 p = seed, v = initialVelocity(gradient, direction, alpha);
        if (integrateCurvedRay(p, v)) return shadeLanding(p, v, colour);
        if (alpha == 0.0) break;
        alpha *= 0.5;
    }
    return false;
}

// ---- quadratic mirror (render/src/quadratic_mirror.cpp, ScreenMap::mirror)
vec3 toEye(vec3 v) { return vec3(dot(v, uRight), dot(v, uUp), -dot(v, uForward)); }
vec3 toWorld(vec3 v) { return v.x * uRight + v.y * uUp - v.z * uForward; }

bool smallestPositiveRoot(float a, float b, float c, out float t)
{
    t = 0.0;
    if (abs(a) < 1e-12) {
        if (abs(b) < 1e-15) return false;
        t = -c / b;
        return t > 0.0;
    }
    float discriminant = b * b - 4.0 * a * c;
    if (discriminant < 0.0) return false;
    float q = -0.5 * (b + (b >= 0.0 ? sqrt(discriminant) : -sqrt(discriminant)));
    float t0 = q / a, t1 = q != 0.0 ? c / q : t0;
    if (t0 > t1) {
        float s = t0;
        t0 = t1;
        t1 = s;
    }
    t = t0 > 0.0 ? t0 : t1;
    return t > 0.0;
}

bool mirror(vec3 origin, vec3 direction, out vec3 colour)
{
    colour = vec3(0.0);
    float w0 = uMirrorW[0], w1 = uMirrorW[1], w2 = uMirrorW[2], w3 = uMirrorW[3], w4 = uMirrorW[4];
    vec3 o = toEye(origin - uEye), r = toEye(direction);
    float a = -(w0 * r.x * r.x + w1 * r.y * r.y + w2 * r.x * r.y);
    float b = r.z - (2.0 * w0 * o.x * r.x + 2.0 * w1 * o.y * r.y + w2 * (o.x * r.y + o.y * r.x) + w3 * r.x + w4 * r.y);
    float c = o.z - uMirrorZm - (w0 * o.x * o.x + w1 * o.y * o.y + w2 * o.x * o.y + w3 * o.x + w4 * o.y);
    float t;
    if (!smallestPositiveRoot(a, b, c, t)) return false;
    vec3 m = o + t * r;
    vec3 normal = toWorld(normalize(vec3(-2.0 * w0 * m.x - w2 * m.y - w3, -2.0 * w1 * m.y - w2 * m.x - w4, 1.0)));
    vec3 p = uEye + toWorld(m);
    for (int step = 0; step < uMirrorMaxSteps; ++step) {
        if (any(greaterThan(abs(p), vec3(uBoxHalf)))) return false;
        float phi = phiAt(p);
        if (phi < uEpsilon) return shadeLanding(p, normal, colour);
        p += phi * normal;
    }
    return false;
}

// ---- ring map (render/src/neugebauer_map.cpp, ScreenMap::ring). The CPU intersects the ring ray
// with the BVH; here it is sphere-traced with |phi| (steps capped inside closed meshes, where the
// field only bounds the distance) and lands within uEpsilon of the same first hit.
bool ringRayDirection(vec2 pixel, out vec3 direction)
{
    direction = uForward;
    vec2 back = pixel - uBackCentre;
    float backR = length(back);
    if (backR <= uBackRadius) {
        float angle = 0.5 * kPi * backR / uBackRadius;
        vec3 u = backR > 0.0 ? normalize(-back.x * uRight - back.y * uUp) : vec3(0.0);
        direction = cos(angle) * uForward + sin(angle) * u;
        return true;
    }
    vec2 offset = pixel - uRingCentre;
    float r = length(offset);
    if (r < uRingInner || r > uRingOuter) return false;
    vec3 u = normalize(offset.x * uRight - offset.y * uUp);
    float k = 2.0 * r / (uRingInner + uRingOuter) - 1.0;
    direction = normalize(u + k * uForward);
    return true;
}

bool ring(out vec3 colour)
{
    colour = vec3(0.0);
    vec3 direction;
    if (!ringRayDirection(vec2(gl_FragCoord.x, uViewport.y - gl_FragCoord.y), direction)) return false;
    float t = 0.0;
    for (int step = 0; step < uRingMaxSteps; ++step) {
        vec3 p = uRingOrigin + t * direction;
        if (any(greaterThan(abs(p), vec3(uBoxHalf)))) return false;
        float phi = phiAt(p);
        if (abs(phi) < uEpsilon) return shadeRayLanding(uRingOrigin, direction, p, colour);
        t += phi > 0.0 ? phi : min(-phi, uInteriorStep);
    }
    return false;
}

void main()
{
    if (!uVolumeReady) discard;
    vec3 origin, direction, colour;
    cameraRay(origin, direction);
    bool landed = false;
    if (uMethod == 4 || uMethod == 5) landed = inverseVis(origin, direction, colour);
    else if (uMethod == 3) landed = mirror(origin, direction, colour);
    else if (uMethod == 2) landed = ring(colour);
    if (!landed) discard;  // background: the cleared colour and region 0 stay
    oColour = vec4(srgbFromLinear(colour), 1.0);
    oRegion = 2u;
}
)GLSL";

}  // namespace

std::string meshVertex() { return std::string(kVersion) + kMeshVertex; }
std::string meshFragment() { return std::string(kVersion) + kCommon + kMeshFragment; }
std::string fullScreenVertex() { return std::string(kVersion) + kFullScreenVertex; }
std::string indirectFragment() { return std::string(kVersion) + kCommon + kIndirectFragment; }

}  // namespace ivis::app::shaders
