// Where an indirect ray lands on the surface, and the colour shown there.
uniform float uIndirectBrightness;
uniform bool uShadeIndirect;   // light indirect pixels from their arriving ray (else flat colour)
uniform bool uIndirectShadows; // shadow them too (not where the rays arrive from inside the object)
uniform float uLanding;         // landing threshold in voxels: phi < uLanding * uVoxel (render::landingEpsilon)

// render::landedAt + Shader::shade for an indirect pixel: the nearest voxel's triangle, the
// exact closest point on it (core::closestPointOnTriangle), lit from the arriving ray and dimmed.
vec3 closestBarycentric(vec3 p, int triangle)
{
    uvec3 v = triangleVertices(triangle);
    vec3 a = vertexPosition[v.x].xyz, b = vertexPosition[v.y].xyz, c = vertexPosition[v.z].xyz;
    vec3 ab = b - a, ac = c - a, ap = p - a;
    float d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return vec3(1.0, 0.0, 0.0);
    vec3 bp = p - b;
    float d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return vec3(0.0, 1.0, 0.0);
    float vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
        float w = d1 / (d1 - d3);
        return vec3(1.0 - w, w, 0.0);
    }
    vec3 cp = p - c;
    float d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return vec3(0.0, 0.0, 1.0);
    float vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
        float w = d2 / (d2 - d6);
        return vec3(1.0 - w, 0.0, w);
    }
    float va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
        float w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return vec3(0.0, 1.0 - w, w);
    }
    float denom = va + vb + vc;
    if (denom <= 0.0) {  // degenerate: the closest vertex
        float da = dot(p - a, p - a), db = dot(p - b, p - b), dc = dot(p - c, p - c);
        if (da <= db && da <= dc) return vec3(1.0, 0.0, 0.0);
        return db <= dc ? vec3(0.0, 1.0, 0.0) : vec3(0.0, 0.0, 1.0);
    }
    float v2 = vb / denom, w2 = vc / denom;
    return vec3(1.0 - v2 - w2, v2, w2);
}

// render::Shader::toLightAlong: the key light of a camera looking along @a arrival, upright like the view's.
vec3 toLightAlong(vec3 arrival)
{
    vec3 right = cross(arrival, uUp);
    right = length(right) > 1e-3 ? normalize(right) : uRight;
    vec3 up = cross(right, arrival);
    return normalize(kKeyLightRight * right + kKeyLightUp * up + kKeyLightForward * arrival);
}

// Colour of an indirect pixel that shows point @a barycentric of @a triangle, seen along @a arrival.
vec3 shadeIndirect(int triangle, vec3 barycentric, vec3 arrival)
{
    float len = length(arrival);
    arrival = len > 0.0 ? arrival / len : uForward;
    vec3 normal = shadingNormal(triangle, barycentric);
    if (dot(normal, arrival) > 0.0) normal = -normal;
    uvec3 v = triangleVertices(triangle);
    float value = barycentric.x * vertexPosition[v.x].w + barycentric.y * vertexPosition[v.y].w +
                  barycentric.z * vertexPosition[v.z].w;
    vec3 position = barycentric.x * vertexPosition[v.x].xyz + barycentric.y * vertexPosition[v.y].xyz +
                    barycentric.z * vertexPosition[v.z].xyz;
    if (!uShadeIndirect) return albedo(triangle, value);  // flat: the colour bar's own colour
    float light = lighting(position, normal, toLightAlong(arrival), uShadows && uIndirectShadows);
    return albedo(triangle, value) * uIndirectBrightness * light;
}

// render::landedAt finds the exact closest surface point of p with a BVH query bounded by the
// distance to the triangle stored at the nearest voxel. Here: the closest point on the closest of
// the triangles stored at the 8 voxels around p (the nearest one among them). The exact closest
// triangle of a point within half a voxel of the surface is, but for near-ties, one of those.
bool closestStoredPoint(vec3 p, out int best, out vec3 bestBarycentric)
{
    vec3 q = floor((p - uTriangleOrigin) * uInvVoxel);
    best = -1;
    bestBarycentric = vec3(1.0, 0.0, 0.0);
    float bestDistance = 1e30;
    for (int i = 0; i < 8; ++i) {
        vec3 corner = q + vec3(float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1));
        if (!(all(greaterThanEqual(corner, vec3(0.0))) && all(lessThan(corner, vec3(uTriangleDims))))) continue;
        int triangle = texelFetch(uTriangles, ivec3(corner), 0).r;
        if (triangle < 0 || triangle == best) continue;
        vec3 barycentric = closestBarycentric(p, triangle);
        uvec3 v = triangleVertices(triangle);
        vec3 x = barycentric.x * vertexPosition[v.x].xyz + barycentric.y * vertexPosition[v.y].xyz +
                 barycentric.z * vertexPosition[v.z].xyz;
        float d = dot(p - x, p - x);
        if (d < bestDistance || (d == bestDistance && triangle < best)) {  // ties to the lower index, as the BVH
            bestDistance = d;
            best = triangle;
            bestBarycentric = barycentric;
        }
    }
    return best >= 0;
}

bool shadeLanding(vec3 p, vec3 arrival, out vec3 colour)
{
    colour = vec3(0.0);
    int triangle;
    vec3 barycentric;
    if (!closestStoredPoint(p, triangle, barycentric)) return false;
    colour = shadeIndirect(triangle, barycentric, arrival);
    return true;
}
