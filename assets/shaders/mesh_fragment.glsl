// Fragment shader of the mesh pass (the direct part): colour map, key light + ambient, shadows.
in vec3 vPosition;
in vec3 vNormal;
in float vScalar;
uniform vec3 uEye;
uniform vec3 uForward;
uniform bool uOrtho;
uniform vec3 uToLight;
uniform float uAmbient;
uniform bool uShadows;
layout(location = 0) out vec4 oColour;
layout(location = 1) out uint oRegion;

// render::shadowFactor: soft shadow toward the key light, sphere-traced through phi; on an unsigned
// field a wall thinner than a step shows up as phi falling then rising within two voxels.
float shadowFactor(vec3 point, vec3 normal, vec3 toLight)
{
    const float kSoftness = 8.0;
    float hitDistance = 0.5 * uVoxel;
    vec3 start = point + 2.0 * uVoxel * normal;
    float lit = 1.0;
    float t = uVoxel;
    float previousSlope = 0.0;
    for (int step = 0; step < 512 && t < 6.0; ++step) {
        vec3 gradient;
        float phi = phiAndGradient(start + t * toLight, gradient);
        if (phi < hitDistance) return 0.0;
        float slope = dot(gradient, toLight);
        if (phi < 2.0 * uVoxel && previousSlope < 0.0 && slope > 0.0 && uUnsigned) return 0.0;
        previousSlope = slope;
        lit = min(lit, kSoftness * phi / t);
        t += max(phi, 0.5 * uVoxel);
    }
    return clamp(lit, 0.0, 1.0);
}

// render::Shader::shade for a direct pixel (the rasteriser's barycentrics = the ray hit's).
void main()
{
    int triangle = gl_PrimitiveID;
    vec3 arrival = uOrtho ? uForward : normalize(vPosition - uEye);
    float len = length(vNormal);
    vec3 normal = len > 1e-3 ? vNormal / len : triangleNormal(triangle);
    if (dot(normal, arrival) > 0.0) normal = -normal;  // the side the point is seen from
    vec3 base = albedo(triangle, vScalar);
    float diffuse = max(0.0, dot(normal, uToLight));
    if (diffuse > 0.0 && uShadows && uVolumeReady) diffuse *= shadowFactor(vPosition, normal, uToLight);
    oColour = vec4(srgbFromLinear(base * (uAmbient + (1.0 - uAmbient) * diffuse)), 1.0);
    oRegion = 1u;
}
