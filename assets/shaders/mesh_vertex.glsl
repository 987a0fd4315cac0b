// Vertex shader of the mesh pass: attribute 0 = (position, scalar), 1 = (normal, NaN flag).
layout(location = 0) in vec4 aPositionScalar;
layout(location = 1) in vec4 aNormalNan;
uniform mat4 uClipFromWorld;
out vec3 vPosition;
out vec3 vNormal;
out float vScalar;
void main()
{
    vPosition = aPositionScalar.xyz;
    vNormal = aNormalNan.xyz;
    vScalar = aPositionScalar.w;
    gl_Position = uClipFromWorld * vec4(aPositionScalar.xyz, 1.0);
}
