// mirror: a quadratic height-field mirror behind the object (render/src/quadratic_mirror.cpp,
// MirrorMethod's MirrorMap::map).
// ---- quadratic mirror (render::MirrorParams)
uniform float uMirrorW[5];
uniform float uMirrorDistanceBehind;  // the apex behind the object's centre (render::MirrorParams)

vec3 toEye(vec3 v) { return vec3(dot(v, uRight), dot(v, uUp), -dot(v, uForward)); }
vec3 toWorld(vec3 v) { return v.x * uRight + v.y * uUp - v.z * uForward; }

bool smallestPositiveRoot(float a, float b, float c, out float t)
{
    t = 0.0;
    if (abs(a) < 1e-12) {
        if (abs(b) < 1e-15) return false;
        t = -c / b;
        return t > 0.0;
    }
    float discriminant = b * b - 4.0 * a * c;
    if (discriminant < 0.0) return false;
    float q = -0.5 * (b + (b >= 0.0 ? sqrt(discriminant) : -sqrt(discriminant)));
    float t0 = q / a, t1 = q != 0.0 ? c / q : t0;
    if (t0 > t1) {
        float s = t0;
        t0 = t1;
        t1 = s;
    }
    t = t0 > 0.0 ? t0 : t1;
    return t > 0.0;
}

// The indirect ray of @a pixel: the camera ray reflected off the mirror, sphere-traced to the surface.
bool indirectRay(vec2 pixel, out vec3 colour)
{
    colour = vec3(0.0);
    vec3 origin, direction;
    cameraRay(pixel, origin, direction);
    float w0 = uMirrorW[0], w1 = uMirrorW[1], w2 = uMirrorW[2], w3 = uMirrorW[3], w4 = uMirrorW[4];
    vec3 o = toEye(origin - uEye), r = toEye(direction);
    float a = -(w0 * r.x * r.x + w1 * r.y * r.y + w2 * r.x * r.y);
    float b = r.z - (2.0 * w0 * o.x * r.x + 2.0 * w1 * o.y * r.y + w2 * (o.x * r.y + o.y * r.x) + w3 * r.x + w4 * r.y);
    float zm = -uTargetDistance - uMirrorDistanceBehind;  // the apex's height in eye space
    float c = o.z - zm - (w0 * o.x * o.x + w1 * o.y * o.y + w2 * o.x * o.y + w3 * o.x + w4 * o.y);
    float t;
    if (!smallestPositiveRoot(a, b, c, t)) return false;
    vec3 m = o + t * r;
    vec3 normal = toWorld(normalize(vec3(-2.0 * w0 * m.x - w2 * m.y - w3, -2.0 * w1 * m.y - w2 * m.x - w4, 1.0)));
    vec3 p = uEye + toWorld(m);
    for (int step = 0; step < kMirrorMaxSteps; ++step) {
        if (any(greaterThan(abs(p), vec3(uBoxHalf)))) return false;
        float phi = phiAt(p);
        if (phi < uLanding * uVoxel) return shadeLanding(p, normal, colour);
        p += phi * normal;
    }
    return false;
}
