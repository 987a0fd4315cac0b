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
    imageStore(uColourImage, p, vec4(srgbFromLinear(mix(linearFromSrgb(stored.rgb), vec3(0.05), 0.85)), stored.a));
}
