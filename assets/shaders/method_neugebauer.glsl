// neugebauer: the ring map of Neugebauer et al. 2009 plus the back-side disc
// (render/src/neugebauer_map.cpp, NeugebauerMethod's RingMap::map).
// ---- ring map (render::RingLayout, pixels)
uniform vec2 uRingPixelCentre;
uniform float uRingInner;
uniform float uRingWidth;       // r2 - r1 in image half-heights (render::RingParams::ringWidth)
uniform vec2 uBackCentre;
uniform float uBackRadius;
uniform vec3 uRingCentre;       // the centre c the ring rays start from
uniform float uInteriorStep;    // largest trusted step where phi < 0 (inside a closed mesh)

const float kPi = 3.14159265358979;
const int kRingMaxSteps = 1000;  // the sphere trace's step cap (the CPU intersects the BVH)

// The ring map's CPU reference intersects its straight ray with the BVH. Here the ray was
// sphere-traced to within uLanding voxels of the surface at p: intersect it exactly (Moller-Trumbore) with
// the triangles stored at the 8 voxels around p and take the first hit; when none is hit (grazing
// rays), take the closest stored point to p.
bool shadeRayLanding(vec3 origin, vec3 direction, vec3 p, out vec3 colour)
{
    colour = vec3(0.0);
    vec3 q = floor((p - uTriangleOrigin) * uInvVoxel);
    int hit = -1;
    vec3 hitBarycentric = vec3(1.0, 0.0, 0.0);
    float hitT = 1e30;
    for (int i = 0; i < 8; ++i) {
        vec3 corner = q + vec3(float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1));
        if (!(all(greaterThanEqual(corner, vec3(0.0))) && all(lessThan(corner, vec3(uTriangleDims))))) continue;
        int triangle = texelFetch(uTriangles, ivec3(corner), 0).r;
        if (triangle < 0 || triangle == hit) continue;
        uvec3 v = triangleVertices(triangle);
        vec3 a = vertexPosition[v.x].xyz, b = vertexPosition[v.y].xyz, c = vertexPosition[v.z].xyz;
        vec3 e1 = b - a, e2 = c - a, s1 = cross(direction, e2);
        float det = dot(s1, e1);
        if (abs(det) <= 1e-12) continue;
        vec3 ao = origin - a;
        float u = dot(ao, s1) / det;
        vec3 s2 = cross(ao, e1);
        float w = dot(direction, s2) / det, t = dot(e2, s2) / det;
        if (u >= 0.0 && w >= 0.0 && u + w <= 1.0 && t > 0.0 && t < hitT) {
            hitT = t;
            hit = triangle;
            hitBarycentric = vec3(1.0 - u - w, u, w);
        }
    }
    if (hit >= 0) {
        colour = shadeIndirect(hit, hitBarycentric, direction);
        return true;
    }
    return shadeLanding(p, direction, colour);
}

// The ring ray's direction for @a pixel: through the ring, or the back-side disc; false elsewhere.
bool ringRayDirection(vec2 pixel, out vec3 direction)
{
    direction = uForward;
    vec2 back = pixel - uBackCentre;
    float backR = length(back);
    if (backR <= uBackRadius) {
        float angle = 0.5 * kPi * backR / uBackRadius;
        vec3 u = backR > 0.0 ? normalize(-back.x * uRight - back.y * uUp) : vec3(0.0);
        direction = cos(angle) * uForward + sin(angle) * u;
        return true;
    }
    vec2 offset = pixel - uRingPixelCentre;
    float r = length(offset);
    float outer = uRingInner + uRingWidth * 0.5 * uViewport.y;  // render::layoutRings
    if (r < uRingInner || r > outer) return false;
    vec3 u = normalize(offset.x * uRight - offset.y * uUp);
    float k = 2.0 * r / (uRingInner + outer) - 1.0;
    direction = normalize(u + k * uForward);
    return true;
}

// The indirect ray of @a pixel: the ring ray from the centre uRingCentre. The CPU intersects it with
// the BVH; here it is sphere-traced with |phi| (steps capped inside closed meshes, where the field
// only bounds the distance) and lands within uLanding voxels of the same first hit.
bool indirectRay(vec2 pixel, out vec3 colour)
{
    colour = vec3(0.0);
    vec3 direction;
    if (!ringRayDirection(pixel, direction)) return false;
    float t = 0.0;
    for (int step = 0; step < kRingMaxSteps; ++step) {
        vec3 p = uRingCentre + t * direction;
        if (any(greaterThan(abs(p), vec3(uBoxHalf)))) return false;
        float phi = phiAt(p);
        if (abs(phi) < uLanding * uVoxel) return shadeRayLanding(uRingCentre, direction, p, colour);
        t += phi > 0.0 ? phi : min(-phi, uInteriorStep);
    }
    return false;
}
