// The distance field phi: volume textures and their trilinear sampling (render::DistanceField).
// ---- volume (dense_slices.h): the CPU's dense far copy and the fine band, RGBA32F 3D textures of
// (phi, exact gradient), and the closest triangles, R32I; fetched texel by texel (no filtering:
// the trilinear cells are the CPU's)
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
uniform float uFineFrom;        // far values below this use the band alone
uniform float uFineUntil;       // far values above this never use the band; blended between
uniform ivec3 uBandDims;
uniform vec3 uBandOrigin;       // world centre of band voxel (0,0,0)
uniform ivec3 uTriangleDims;
uniform vec3 uTriangleOrigin;   // world centre of triangle voxel (0,0,0)
uniform float uVoxel;           // voxel size of band and triangles (the fine voxel unless resampled)
uniform float uInvVoxel;
uniform bool uUnsigned;         // phi is an unsigned distance (open mesh)

uniform float uBoxHalf;         // 2.5: the volume's box

// render::detail::blend: corners c[dx | dy << 1 | dz << 2] = (phi, exact gradient) of a cell of
// size h at fractions t; the trilinear blend of the gradients, and of each corner's first-order
// Taylor extrapolation of phi; the corners summed in pairs and the pairs in pairs, as on the CPU.
vec4 blend(vec4 c[8], vec3 t, float h)
{
    vec3 s = vec3(1.0) - t;
    float w[8] = float[8](s.x * s.y * s.z, t.x * s.y * s.z, s.x * t.y * s.z, t.x * t.y * s.z,
                          s.x * s.y * t.z, t.x * s.y * t.z, s.x * t.y * t.z, t.x * t.y * t.z);
    vec4 sum = ((w[0] * c[0] + w[1] * c[1]) + (w[2] * c[2] + w[3] * c[3])) +
               ((w[4] * c[4] + w[5] * c[5]) + (w[6] * c[6] + w[7] * c[7]));
    // sum of w_i g_i . d_i, d_i the corner's offset in the cell
    float towardsCorner = ((w[1] * c[1].y + w[2] * c[2].z) + (w[3] * (c[3].y + c[3].z) + w[4] * c[4].w)) +
                          ((w[5] * (c[5].y + c[5].w) + w[6] * (c[6].z + c[6].w)) + w[7] * ((c[7].y + c[7].z) + c[7].w));
    sum.x += h * (dot(sum.yzw, t) - towardsCorner);
    return sum;
}

// render::DenseGrid::valueAndGradient on the far copy.
float farValueAndGradient(vec3 p, out vec3 gradient)
{
    gradient = vec3(0.0);
    vec3 q = (p - uFarOrigin) * uFarInvVoxel;
    vec3 f = floor(q);
    if (!(all(greaterThanEqual(f, vec3(0.0))) && all(lessThan(f, vec3(uFarDims - 1))))) return uOutside;
    ivec3 b = ivec3(f);
    vec4 c[8];
    for (int i = 0; i < 8; ++i) c[i] = texelFetch(uFar, b + ivec3(i & 1, (i >> 1) & 1, (i >> 2) & 1), 0);
    vec4 blended = blend(c, q - f, 1.0 / uFarInvVoxel);
    gradient = blended.yzw;
    return blended.x;
}

// render::DistanceField::Sampler::fineSample: the blended band sample at p, false unless all eight
// corners of its cell are in the band.
bool bandSample(vec3 p, out vec4 blended)
{
    blended = vec4(0.0);
    vec3 q = (p - uBandOrigin) * uInvVoxel;
    vec3 f = floor(q);
    if (!(all(greaterThanEqual(f, vec3(0.0))) && all(lessThan(f, vec3(uBandDims - 1))))) return false;
    ivec3 b = ivec3(f);
    vec4 c[8];
    for (int i = 0; i < 8; ++i) {
        c[i] = texelFetch(uBand, b + ivec3(i & 1, (i >> 1) & 1, (i >> 2) & 1), 0);
        if (c[i].x > 1e29) return false;  // kInactiveBandValue
    }
    blended = blend(c, q - f, uVoxel);
    return true;
}

// render::DistanceField::Sampler::phiAndGradient: the far copy, refined by the fine band where
// all eight corners of the fine cell are in the band, blended by render::detail::fineWeight.
float phiAndGradient(vec3 p, out vec3 gradient)
{
    float far = farValueAndGradient(p, gradient);
    if (!uHasFineBand || far > uFineUntil) return far;
    vec4 blended;
    if (!bandSample(p, blended)) return far;
    float t = clamp((uFineUntil - far) / (uFineUntil - uFineFrom), 0.0, 1.0);
    float w = t * t * (3.0 - 2.0 * t);
    gradient = mix(gradient, blended.yzw, w);
    return mix(far, blended.x, w);
}

// render::DistanceField::Sampler::phi
float phiAt(vec3 p)
{
    vec3 gradient;
    return phiAndGradient(p, gradient);
}
