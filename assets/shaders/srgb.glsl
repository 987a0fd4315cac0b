// core::srgbFromLinear and its inverse: the colour attachment holds sRGB-encoded 8-bit values, as
// the PNGs do (the only place of this encoding in the shaders).
vec3 srgbFromLinear(vec3 c)
{
    c = clamp(c, 0.0, 1.0);
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, greaterThan(c, vec3(0.0031308)));
}

vec3 linearFromSrgb(vec3 c)
{
    return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), greaterThan(c, vec3(0.04045)));
}
