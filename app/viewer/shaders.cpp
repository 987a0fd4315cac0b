// Composes the viewer's shaders from the embedded files of assets/shaders/.
#include "shaders.h"

#include "embedded_shaders.h"
#include "gl_objects.h"

#include <ivis/render/curved_ray.h>
#include <ivis/render/method_registry.h>
#include <ivis/render/quadratic_mirror.h>
#include <ivis/render/shading.h>
#include <ivis/render/shadow.h>
#include <ivis/render/inversevis_wrap_method.h>

#include <cstdio>
#include <initializer_list>
#include <string>

namespace ivis::app::shaders {
namespace {

/// The text of assets/shaders/@a name, or null.
const char* findFile(const std::string& name)
{
    for (const EmbeddedFile& f : embeddedFiles())
        if (name == f.name) return f.text;
    return nullptr;
}

/// The text of assets/shaders/@a name; throws GlError when it was not embedded.
const char* file(const std::string& name)
{
    if (const char* text = findFile(name)) return text;
    throw GlError("no shader file '" + name + "' is embedded (assets/shaders/, app/CMakeLists.txt)");
}

/// A GLSL float literal of @a value that parses to the same float.
std::string floatLiteral(double value)
{
    char text[40];
    std::snprintf(text, sizeof text, "%.9g", value);
    std::string literal = text;
    if (literal.find_first_of(".e") == std::string::npos) literal += ".0";
    return literal;
}

/// @brief GLSL constant declarations of render's constants that the snippets read: one source for
///        both sides (the CPU renderer's headers), so that the two cannot drift.
std::string renderConstants()
{
    std::string text;
    auto real = [&](const char* name, double value) { text += "const float " + std::string(name) + " = " + floatLiteral(value) + ";\n"; };
    auto whole = [&](const char* name, int value) { text += "const int " + std::string(name) + " = " + std::to_string(value) + ";\n"; };
    real("kClosestApproachSpacing", render::kClosestApproachSpacing);
    real("kClosestApproachCoarseSteps", render::kClosestApproachCoarseSteps);
    real("kClosestApproachValley", render::kClosestApproachValley);
    real("kGoldenSectionRatio", render::kGoldenSectionRatio);
    real("kWrapProbeStep", render::kWrapProbeStep);
    real("kShadowSoftness", render::kShadowSoftness);
    real("kShadowStartVoxels", render::kShadowStartVoxels);
    real("kShadowHitVoxels", render::kShadowHitVoxels);
    real("kShadowLeastStepVoxels", render::kShadowLeastStepVoxels);
    whole("kShadowMaxSteps", render::kShadowMaxSteps);
    real("kShadowMaxDistance", render::kShadowMaxDistance);
    real("kShadowWallVoxels", render::kShadowWallVoxels);
    real("kKeyLightRight", render::kKeyLightRight);
    real("kKeyLightUp", render::kKeyLightUp);
    real("kKeyLightForward", render::kKeyLightForward);
    whole("kMirrorMaxSteps", render::MirrorParams{}.maxSteps);
    return text;
}

/// The bindings of the methods' vertex arrays, kMethodBuffer0 ... (macros: a layout qualifier of
/// GLSL 4.30 takes literals only).
std::string methodBufferBindings()
{
    std::string text;
    for (int k = 0; k < kMaxMethodBuffers; ++k)
        text += "#define kMethodBuffer" + std::to_string(k) + " " + std::to_string(kFirstMethodBuffer + k) + "\n";
    return text;
}

/// The GLSL version line, render's constants, then the files @a names, in order.
std::string compose(std::initializer_list<std::string> names)
{
    std::string source = "#version 430 core\n" + renderConstants() + methodBufferBindings();
    for (const std::string& name : names) source += file(name);
    return source;
}

}  // namespace

std::string meshVertex() { return compose({"mesh_vertex.glsl"}); }

std::string meshFragment()
{
    return compose({"distance_field.glsl", "mesh_buffers.glsl", "srgb.glsl", "colour_map.glsl", "shading.glsl",
                    "mesh_fragment.glsl"});
}

std::string fullScreenVertex() { return compose({"full_screen_vertex.glsl"}); }

std::string outlineFragment() { return compose({"srgb.glsl", "outline_fragment.glsl"}); }

void checkIndirectSnippets()
{
    for (const render::MethodInfo* info : render::methodRegistry()) {
        if (render::makeMethod(info->name)->drawsIndirect() && !findFile("method_" + info->name + ".glsl"))
            throw GlError("the method " + info->name + " has no viewer shader: assets/shaders/method_" + info->name +
                          ".glsl is missing (or not embedded by app/CMakeLists.txt)");
        if (info->vertexArrays.size() > std::size_t(kMaxMethodBuffers))
            throw GlError("the method " + info->name + " has more vertex arrays than the viewer binds (" +
                          std::to_string(kMaxMethodBuffers) + ", app/viewer/shaders.h)");
    }
}

std::string indirectFunctions(const std::string& method)
{
    return compose({"distance_field.glsl", "mesh_buffers.glsl", "srgb.glsl", "colour_map.glsl", "shading.glsl",
                    "camera_ray.glsl", "landing.glsl", "hull_search.glsl", "curved_ray.glsl",
                    "method_" + method + ".glsl"});
}

std::string indirectFragment(const std::string& method) { return indirectFunctions(method) + file("indirect_main.glsl"); }

}  // namespace ivis::app::shaders
