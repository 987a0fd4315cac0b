// InverseVis curved rays (render/src/curved_ray.cpp, render::CurvedRayMap::map); the methods that use
// them differ only in the alpha they launch with (method_inversevis*.glsl).
uniform float uStep;
uniform float uEscape;          // 0.999 * reach
uniform int uMaxSteps;

// render::initialVelocity: alpha times the part of the view direction tangential to the hull.
vec3 initialVelocity(vec3 gradient, vec3 viewDirection, float alpha)
{
    float len = length(gradient);
    if (!(len > 0.0)) return alpha * viewDirection;
    vec3 g = gradient / len;
    return alpha * cross(g, cross(viewDirection, g));
}

// render::integrateCurvedRay from @a p with velocity @a v: symplectic Euler, h = uStep; true
// when it lands (phi < uLanding voxels), with p and v there.
bool integrateCurvedRay(inout vec3 p, inout vec3 v)
{
    vec3 gradient;
    for (int step = 0; step < uMaxSteps; ++step) {
        float phi = phiAndGradient(p, gradient);
        if (phi < uLanding * uVoxel) return true;
        if (phi >= uEscape) return false;
        v -= uStep * gradient;
        float speed = length(v);
        vec3 heading = speed > 0.0 ? v / speed : -gradient;
        p += uStep * phi * heading;
    }
    return false;
}

// CurvedRayMap::start: where the view ray leaves the hull, and the gradient of phi there.
bool hullSeed(vec3 origin, vec3 direction, out vec3 seed, out vec3 gradient)
{
    if (!findHullExit(origin, direction, seed)) return false;
    phiAndGradient(seed, gradient);
    return true;
}

// CurvedRayMap::trace: launches from the hull seed with @a alpha; a ray that does not land is
// relaunched with half its alpha, up to @a retries times.
bool landCurvedRay(vec3 seed, vec3 gradient, vec3 direction, float alpha, int retries, out vec3 colour)
{
    colour = vec3(0.0);
    for (int attempt = 0; attempt <= retries; ++attempt) {
        vec3 p = seed, v = initialVelocity(gradient, direction, alpha);
        if (integrateCurvedRay(p, v)) return shadeLanding(p, v, colour);
        if (alpha == 0.0) break;
        alpha *= 0.5;
    }
    return false;
}
