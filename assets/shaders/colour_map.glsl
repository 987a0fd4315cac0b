// Colours of surface points: scalar range, colour map, albedo and the sRGB encoding.
// ---- look (render::ShadingOptions)
uniform bool uHasScalar;
uniform bool uCellScalar;       // one value per triangle (triangleScalar), not per vertex
uniform int uDataTriangles;     // triangles at or above this index are hole caps
uniform vec2 uRange;            // scalar range lo, hi
uniform bool uLogScale;         // positions by log10 (uRange.x > 0)
uniform bool uInvertScale;      // colour map reversed
uniform vec3 uNanColour;
uniform vec3 uNoDataColour;

// core::ColorScale::position
float normalizedScalar(float value)
{
    float t = 0.5;
    if (uRange.x != uRange.y) {
        if (uLogScale)
            t = value > 0.0 ? clamp(log(value / uRange.x) / log(uRange.y / uRange.x), 0.0, 1.0) : 0.0;
        else
            t = clamp((value - uRange.x) / (uRange.y - uRange.x), 0.0, 1.0);
    }
    return uInvertScale ? 1.0 - t : t;
}

// core::Colormap::at, tabulated at 256 points and interpolated linearly.
vec3 colormap(float t)
{
    return texture(uColormap, vec2((clamp(t, 0.0, 1.0) * 255.0 + 0.5) / 256.0, 0.5)).rgb;
}

// render::Shader::albedo for a point of @a triangle whose interpolated scalar is @a value (a cell
// scalar takes the triangle's own value instead, flat as core::scalarAt).
vec3 albedo(int triangle, float value)
{
    if (!uHasScalar || triangle >= uDataTriangles) return uNoDataColour;
    if (uCellScalar) {
        vec2 cell = triangleScalar[triangle];
        return cell.y > 0.0 ? uNanColour : colormap(normalizedScalar(cell.x));
    }
    uvec3 v = triangleVertices(triangle);
    if (vertexNormal[v.x].w + vertexNormal[v.y].w + vertexNormal[v.z].w > 0.0) return uNanColour;
    return colormap(normalizedScalar(value));
}
