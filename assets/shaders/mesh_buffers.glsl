// The mesh's vertex buffers, read again as storage buffers, and its normals (render::shadingNormal).
layout(std430, binding = 0) readonly buffer VertexPositions { vec4 vertexPosition[]; };  // xyz, w = scalar (NaN -> 0)
layout(std430, binding = 1) readonly buffer VertexNormals { vec4 vertexNormal[]; };      // xyz, w = 1 where NaN
layout(std430, binding = 2) readonly buffer TriangleIndices { uint triangleIndex[]; };
layout(std430, binding = 3) readonly buffer TriangleScalars { vec2 triangleScalar[]; };  // cell scalar: value, 1 where NaN

uvec3 triangleVertices(int triangle)
{
    uint i = 3u * uint(triangle);
    return uvec3(triangleIndex[i], triangleIndex[i + 1u], triangleIndex[i + 2u]);
}

// render::triangleNormal
vec3 triangleNormal(int triangle)
{
    uvec3 v = triangleVertices(triangle);
    vec3 a = vertexPosition[v.x].xyz, b = vertexPosition[v.y].xyz, c = vertexPosition[v.z].xyz;
    vec3 n = cross(b - a, c - a);
    float len = length(n);
    return len > 0.0 ? n / len : vec3(0.0, 0.0, 1.0);
}

// render::shadingNormal: barycentric blend of the vertex normals.
vec3 shadingNormal(int triangle, vec3 barycentric)
{
    uvec3 v = triangleVertices(triangle);
    vec3 n = barycentric.x * vertexNormal[v.x].xyz + barycentric.y * vertexNormal[v.y].xyz +
             barycentric.z * vertexNormal[v.z].xyz;
    float len = length(n);
    return len > 1e-3 ? n / len : triangleNormal(triangle);
}
