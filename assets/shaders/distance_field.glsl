// The distance field phi: volume textures and their trilinear sampling (render::DistanceField).
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

uniform float uBoxHalf;         // 2.5: the volume's box

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
