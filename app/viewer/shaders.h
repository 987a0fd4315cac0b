/// @file shaders.h
/// @brief GLSL 4.30 sources of the viewer's passes, composed from the snippets in assets/shaders/:
///        the mesh (direct part, with shadows) and, per method, the full-screen indirect pass.
/// @note Each function of the shaders mirrors one CPU function of render/ (named in comments in the
///       snippets) so that the GPU picture equals render::renderImage's up to float rounding.
#pragma once

#include <string>

namespace ivis::app::shaders {

/// @brief The storage-buffer binding of a method's first vertex array (render::MethodInfo::vertexArrays);
///        its k-th is bound at kFirstMethodBuffer + k, which its snippet names kMethodBuffer<k>.
inline constexpr int kFirstMethodBuffer = 4;
/// @brief Vertex arrays a method may have.
inline constexpr int kMaxMethodBuffers = 2;

/// @brief Vertex shader of the mesh pass: attribute 0 = (position, scalar), 1 = (normal, NaN flag).
std::string meshVertex();
/// @brief Fragment shader of the mesh pass: colour map, key light + ambient, sphere-traced shadows.
std::string meshFragment();
/// @brief Vertex shader of the full-screen pass: one triangle at depth 1 (drawn where no mesh is).
std::string fullScreenVertex();
/// @brief Fragment shader of the outline pass (full screen, image load/store, no outputs).
std::string outlineFragment();
/// @brief Checks that every registered method that draws an indirect part has its snippet
///        method_<name>.glsl embedded, and no method more vertex arrays than kMaxMethodBuffers.
/// @throw GlError naming the first method that fails
void checkIndirectSnippets();
/// @brief Fragment shader of the full-screen pass for the method named @a method: indirectFunctions(),
///        then indirect_main.glsl.
/// @throw GlError when no snippet method_<method>.glsl was embedded
std::string indirectFragment(const std::string& method);
/// @brief The functions of the full-screen pass for the method named @a method, without a main:
///        the shared snippets, then method_<method>.glsl (which defines indirectRay). The shader
///        tests call them from a compute shader (tests/shader/).
/// @throw GlError when no snippet method_<method>.glsl was embedded
std::string indirectFunctions(const std::string& method);

}  // namespace ivis::app::shaders
