// Fragment shader of the mesh pass (the direct part): colour map, key light + ambient, shadows
// (lighting() in shading.glsl).
in vec3 vPosition;
in vec3 vNormal;
in float vScalar;
uniform vec3 uEye;
uniform vec3 uForward;
uniform bool uOrtho;
layout(location = 0) out vec4 oColour;
layout(location = 1) out uint oRegion;

// render::Shader::shade for a direct pixel (the rasteriser's barycentrics = the ray hit's).
void main()
{
    int triangle = gl_PrimitiveID;
    vec3 arrival = uOrtho ? uForward : normalize(vPosition - uEye);
    float len = length(vNormal);
    vec3 normal = len > 1e-3 ? vNormal / len : triangleNormal(triangle);
    if (dot(normal, arrival) > 0.0) normal = -normal;  // the side the point is seen from
    vec3 base = albedo(triangle, vScalar);
    oColour = vec4(srgbFromLinear(base * lighting(vPosition, normal, uToLight, uShadows)), 1.0);
    oRegion = 1u;
}
