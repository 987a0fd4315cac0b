// Fragment shader main of the full-screen pass: the method's indirect ray (indirectRay, defined by
// the method_<name>.glsl composed before this) for every pixel the mesh left empty.
layout(location = 0) out vec4 oColour;
layout(location = 1) out uint oRegion;

void main()
{
    if (!uVolumeReady) discard;
    vec3 colour;
    vec2 pixel = vec2(gl_FragCoord.x, uViewport.y - gl_FragCoord.y);  // (0,0): the top-left corner
    if (!indirectRay(pixel, colour)) discard;  // background: the cleared colour and region 0 stay
    oColour = vec4(srgbFromLinear(colour), 1.0);
    oRegion = 2u;
}
