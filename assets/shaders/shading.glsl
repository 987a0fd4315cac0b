// Light of a surface point (render::Shader::lighting): ambient plus diffuse toward a key light,
// with soft shadows sphere-traced through phi.
uniform vec3 uToLight;         // the view's key light
uniform float uAmbient;
uniform bool uShadows;
uniform vec3 uSurfaceLo;       // a box around the surface (render::hullBounds(mesh, 0, voxel))
uniform vec3 uSurfaceHi;

// render::shadowFactor: soft shadow toward the key light, sphere-traced by max(phi, distance to the
// surface's box) (phi is clamped beyond the field's reach) until the ray leaves the box for good; on
// an unsigned field a wall thinner than a step shows up as phi falling then rising within
// kShadowWallVoxels. The k* constants are render's (app/viewer/shaders.cpp writes them).
float shadowFactor(vec3 point, vec3 normal, vec3 toLight)
{
    float hitDistance = kShadowHitVoxels * uVoxel;
    vec3 start = point + kShadowStartVoxels * uVoxel * normal;
    float lit = 1.0;
    float t = uVoxel;
    float previousSlope = 0.0;
    for (int step = 0; step < kShadowMaxSteps && t < kShadowMaxDistance; ++step) {
        vec3 p = start + t * toLight;
        vec3 gradient;
        float phi = phiAndGradient(p, gradient);
        if (phi < hitDistance) return 0.0;
        float slope = dot(gradient, toLight);
        if (phi < kShadowWallVoxels * uVoxel && previousSlope < 0.0 && slope > 0.0 && uUnsigned) return 0.0;
        previousSlope = slope;
        float distance = max(phi, length(max(max(uSurfaceLo - p, p - uSurfaceHi), vec3(0.0))));
        lit = min(lit, kShadowSoftness * distance / t);
        bool leaves = false;  // left the surface's box for good: nothing ahead can shadow it
        for (int a = 0; a < 3; ++a)
            leaves = leaves || (p[a] > uSurfaceHi[a] && toLight[a] >= 0.0) || (p[a] < uSurfaceLo[a] && toLight[a] <= 0.0);
        if (leaves) break;
        t += max(distance, kShadowLeastStepVoxels * uVoxel);
    }
    return clamp(lit, 0.0, 1.0);
}

// render::Shader::lighting: ambient plus diffuse at a point whose normal faces the viewer, shadowed
// when @a shadows.
float lighting(vec3 point, vec3 normal, vec3 toLight, bool shadows)
{
    float diffuse = max(0.0, dot(normal, toLight));
    if (diffuse > 0.0 && shadows && uVolumeReady) diffuse *= shadowFactor(point, normal, toLight);
    return uAmbient + (1.0 - uAmbient) * diffuse;
}
