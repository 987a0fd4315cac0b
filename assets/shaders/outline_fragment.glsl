// Outline pass (render::renderImage's drawOutline): darkens each direct pixel that has a
// non-direct pixel (or the border) within uOutlineRadius pixels, in place; writes no outputs.
layout(r8ui, binding = 0) uniform readonly uimage2D uRegionImage;
layout(rgba8, binding = 1) uniform image2D uColourImage;
uniform int uOutlineRadius;

const uint kDirect = 1u;

bool isDirect(ivec2 p, ivec2 size)
{
    if (any(lessThan(p, ivec2(0))) || any(greaterThanEqual(p, size))) return false;
    return imageLoad(uRegionImage, p).r == kDirect;
}

float linearFromSrgb(float c) { return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4); }
float srgbFromLinear(float c) { return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055; }

void main()
{
    ivec2 size = imageSize(uRegionImage);
    ivec2 p = ivec2(gl_FragCoord.xy);
    if (!isDirect(p, size)) return;
    bool edge = false;
    for (int dy = -uOutlineRadius; dy <= uOutlineRadius && !edge; ++dy)
        for (int dx = -uOutlineRadius; dx <= uOutlineRadius; ++dx)
            if (dx * dx + dy * dy <= uOutlineRadius * uOutlineRadius && !isDirect(p + ivec2(dx, dy), size)) {
                edge = true;
                break;
            }
    if (!edge) return;
    // core::Image::blendOver(colour 0.05, opacity 0.85) in linear light, stored sRGB-encoded.
    vec4 stored = imageLoad(uColourImage, p);
    vec3 c;
    for (int i = 0; i < 3; ++i) c[i] = srgbFromLinear(mix(linearFromSrgb(stored[i]), 0.05, 0.85));
    imageStore(uColourImage, p, vec4(c, stored.a));
}
