/// @file shaders.h
/// @brief GLSL 4.30 sources of the viewer's two passes: the mesh (direct part, with shadows) and
///        the full-screen indirect pass (InverseVis curved rays, fixed or adaptive alpha, the quadratic
///        mirror, the ring map).
/// @note Each function of the shaders mirrors one CPU function of render/ (named in comments in the
///       source) so that the GPU picture equals render::renderImage's up to float rounding.
#pragma once

#include <string>

namespace ivis::app::shaders {

/// @brief Vertex shader of the mesh pass: attribute 0 = (position, scalar), 1 = (normal, NaN flag).
std::string meshVertex();
/// @brief Fragment shader of the mesh pass: colour map, key light + ambient, sphere-traced shadows.
std::string meshFragment();
/// @brief Vertex shader of the full-screen pass: one triangle at depth 1 (drawn where no mesh is).
std::string fullScreenVertex();
/// @brief Fragment shader of the full-screen pass: the method's indirect ray for empty pixels.
std::string indirectFragment();

}  // namespace ivis::app::shaders
