// inversevis: curved rays from the hull, all launched with the one alpha (render::InverseVisMethod).
uniform float uAlpha;

// The indirect ray of @a pixel: CurvedRayMap::map with alpha = uAlpha and no retries.
bool indirectRay(vec2 pixel, out vec3 colour)
{
    colour = vec3(0.0);
    vec3 origin, direction, seed, gradient;
    cameraRay(pixel, origin, direction);
    if (!hullSeed(origin, direction, seed, gradient)) return false;
    return landCurvedRay(seed, gradient, direction, uAlpha, 0, colour);
}
