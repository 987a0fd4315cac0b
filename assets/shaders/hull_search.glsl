// The hull {phi = phi0} the curved rays start from (render/src/curved_ray.cpp).
uniform float uHullOffset;
uniform int uMaxHullSteps;      // cap of the backward hull search (the CPU has none)
uniform vec3 uHullLo;
uniform vec3 uHullHi;

// The ray's interval inside the hull's box [uHullLo, uHullHi].
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

// render::refineHullCrossing: regula falsi with the Illinois rule between lo (inside) and hi.
float refineHullCrossing(vec3 origin, vec3 direction, float lo, float excessLo, float hi, float excessHi)
{
    int lastSide = 0;
    for (int i = 0; i < 64 && hi - lo > 1e-5; ++i) {
        float mid = clamp(lo + (hi - lo) * excessLo / (excessLo - excessHi), lo, hi);
        float excess = phiAt(origin + mid * direction) - uHullOffset;
        if (abs(excess) < 1e-6) return mid;
        if (excess <= 0.0) {
            lo = mid;
            excessLo = excess;
            if (lastSide < 0) excessHi *= 0.5;
            lastSide = -1;
        } else {
            hi = mid;
            excessHi = excess;
            if (lastSide > 0) excessLo *= 0.5;
            lastSide = 1;
        }
    }
    return hi;
}

// render::findHullExit: the FARTHEST crossing of {phi = phi0}, sphere-traced backward.
bool findHullExit(vec3 origin, vec3 direction, out vec3 seed)
{
    float tEnter, tExit;
    seed = origin;
    if (!boxInterval(origin, direction, tEnter, tExit)) return false;
    const float minStep = 1e-4;
    float tOutside = tExit;
    float excessOutside = 0.0;
    float t = tExit;
    for (int i = 0; i < uMaxHullSteps && t >= tEnter; ++i) {
        float excess = phiAt(origin + t * direction) - uHullOffset;
        if (excess <= 0.0) {
            seed = origin + refineHullCrossing(origin, direction, t, excess, tOutside, excessOutside) * direction;
            return true;
        }
        tOutside = t;
        excessOutside = excess;
        t -= max(excess, minStep);
    }
    return false;
}
