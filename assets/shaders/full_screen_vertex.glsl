// Vertex shader of the full-screen pass: one triangle at depth 1 (drawn where no mesh is).
void main()
{
    const vec2 corners[3] = vec2[](vec2(-1.0, -1.0), vec2(3.0, -1.0), vec2(-1.0, 3.0));
    gl_Position = vec4(corners[gl_VertexID], 1.0, 1.0);  // depth 1: passes only where no mesh was drawn
}
