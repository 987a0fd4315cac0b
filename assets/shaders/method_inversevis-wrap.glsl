// inversevis-wrap: curved rays from the view ray's closest approach, in rings as wide as each part
// is thick, launched faster and steeper outward across the ring (render::InverseVisWrapMethod).
uniform float uWrapSpeed;
uniform float uWrapTilt;
uniform float uRingScale;
uniform float uStableShift;
layout(std430, binding = kMethodBuffer0) readonly buffer LocalRadii { float localRadius[]; };  // render::vertexLocalRadii

// render::findClosestApproach: the point of the view ray closest to the surface, within the hull,
// centred in the ray's valley where phi stays within a voxel of its least (the k* constants are
// render's: app/viewer/shaders.cpp writes them).
bool closestApproach(vec3 origin, vec3 direction, out vec3 seed, out float distance)
{
    float tEnter, tExit;
    seed = origin;
    distance = uHullOffset;
    if (!boxInterval(origin, direction, tEnter, tExit)) return false;
    float tolerance = kClosestApproachSpacing * uVoxel;
    float best = uHullOffset, tBest = tEnter;
    for (int pass = 0; pass < 2; ++pass) {  // coarse, then fine from the coarse best
        float step = pass == 0 ? kClosestApproachCoarseSteps * tolerance : tolerance;
        float t = tEnter;
        for (int i = 0; i < uMaxHullSteps && t < tExit; ++i) {
            float phi = phiAt(origin + t * direction);
            if (phi < best) {
                best = phi;
                tBest = t;
            }
            t += max(phi - best, step);
        }
    }
    if (!(best < uHullOffset)) return false;
    float lo = max(tEnter, tBest - 2.0 * tolerance), hi = min(tExit, tBest + 2.0 * tolerance);
    const float ratio = kGoldenSectionRatio;
    float a = hi - ratio * (hi - lo), b = lo + ratio * (hi - lo);
    float phiA = phiAt(origin + a * direction), phiB = phiAt(origin + b * direction);
    for (int k = 0; k < 64 && hi - lo > 1e-5; ++k) {
        if (phiA < phiB) {
            hi = b;
            b = a;
            phiB = phiA;
            a = hi - ratio * (hi - lo);
            phiA = phiAt(origin + a * direction);
        } else {
            lo = a;
            a = b;
            phiA = phiB;
            b = lo + ratio * (hi - lo);
            phiB = phiAt(origin + b * direction);
        }
    }
    // The centre of the valley round that minimum, where phi stays within a voxel of it.
    float tMin = 0.5 * (lo + hi);
    float phiMin = phiAt(origin + tMin * direction);
    float depth = kClosestApproachValley * uVoxel;
    float weights = 0.0, weighted = 0.0;
    for (int side = -1; side <= 1; side += 2) {
        float s = side > 0 ? tolerance : 0.0;
        for (int i = 0; i < uMaxHullSteps; ++i, s += tolerance) {
            float t = tMin + float(side) * s;
            if (t < tEnter || t > tExit) break;
            float below = depth - (phiAt(origin + t * direction) - phiMin);
            if (!(below > 0.0)) break;
            weights += below;
            weighted += below * t;
        }
    }
    seed = origin + (weights > 0.0 ? weighted / weights : tMin) * direction;
    distance = phiAt(seed);
    return distance < uHullOffset;
}

// The local radius at the surface point closest to @a p (phi and its gradient lead there), or -1.
float localRadiusNear(vec3 p)
{
    vec3 gradient;
    float phi = phiAndGradient(p, gradient);
    float len = length(gradient);
    vec3 q = len > 0.0 ? p - phi * gradient / len : p;
    int triangle;
    vec3 barycentric;
    if (!closestStoredPoint(q, triangle, barycentric)) return -1.0;
    uvec3 v = triangleVertices(triangle);
    return barycentric.x * localRadius[v.x] + barycentric.y * localRadius[v.y] + barycentric.z * localRadius[v.z];
}

// The launch at ring coordinate @a t (WrapLaunch::alphaAt and directionAt): alpha = speed t (2 - t)
// along the view direction's tangential part, tilted outward by tilt t.
vec3 wrapLaunch(float t, vec3 along, vec3 outward)
{
    return uWrapSpeed * t * (2.0 - t) * normalize(along + uWrapTilt * t * outward);
}

// The indirect ray of @a pixel: CurvedRayMap::map with InverseVisWrapMethod::aim.
bool indirectRay(vec2 pixel, out vec3 colour)
{
    colour = vec3(0.0);
    vec3 origin, direction, seed;
    float distance;
    cameraRay(pixel, origin, direction);
    if (!closestApproach(origin, direction, seed, distance)) return false;
    float radius = localRadiusNear(seed);
    if (radius < 0.0) return false;
    float width = min(uRingScale * radius, uHullOffset);
    float ring = distance / width;
    if (!(ring < 1.0)) return false;
    vec3 gradient;
    phiAndGradient(seed, gradient);
    float len = length(gradient);
    vec3 outward = len > 0.0 ? gradient / len : vec3(0.0);
    vec3 along = normalize(initialVelocity(gradient, direction, 1.0));
    // The ray, and the rays of the neighbouring pixels across the ring: seeds a step further in and
    // out (InverseVisWrapMethod's kNeighbourStep), the ring coordinate moving with them.
    float step = min(kWrapProbeStep, distance);
    vec3 here = seed, inner = seed - step * outward, outer = seed + step * outward;
    vec3 v = wrapLaunch(ring, along, outward);
    vec3 vInner = wrapLaunch(ring - step / width, along, outward);
    vec3 vOuter = wrapLaunch(ring + step / width, along, outward);
    if (!integrateCurvedRay(here, v) || !integrateCurvedRay(inner, vInner) || !integrateCurvedRay(outer, vOuter))
        return false;
    if (length(inner + outer - 2.0 * here) > uStableShift) return false;
    return shadeLanding(here, v, colour);
}
