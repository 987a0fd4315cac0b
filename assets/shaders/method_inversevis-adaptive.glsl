// inversevis-adaptive: curved rays whose alpha follows a profile across the ring, with retries
// (render::AlphaProfile).
uniform vec3 uAlphaProfile;     // a0, a1, a2
uniform float uMaxAlpha;        // the profile's clamp
uniform int uRetries;           // relaunches at half alpha of a ray that does not land

// AlphaProfile::at of the seed's alignment c = r . g / |g| (InverseVisAdaptiveMethod::launchVelocity).
float profileAlpha(vec3 gradient, vec3 viewDirection)
{
    float len = length(gradient);
    float c = len > 0.0 ? dot(viewDirection, gradient) / len : 0.0;
    return clamp(uAlphaProfile.x + c * (uAlphaProfile.y + c * uAlphaProfile.z), 0.0, uMaxAlpha);
}

// The indirect ray of @a pixel: CurvedRayMap::map with the profile's alpha and uRetries retries.
bool indirectRay(vec2 pixel, out vec3 colour)
{
    colour = vec3(0.0);
    vec3 origin, direction, seed, gradient;
    cameraRay(pixel, origin, direction);
    if (!hullSeed(origin, direction, seed, gradient)) return false;
    return landCurvedRay(seed, gradient, direction, profileAlpha(gradient, direction), uRetries, colour);
}
