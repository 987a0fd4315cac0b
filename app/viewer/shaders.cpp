// Composes the viewer's shaders from the embedded files of assets/shaders/.
#include "shaders.h"

#include "embedded_shaders.h"
#include "gl_objects.h"

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

/// The GLSL version line followed by the files @a names, in order.
std::string compose(std::initializer_list<std::string> names)
{
    std::string source = "#version 430 core\n";
    for (const std::string& name : names) source += file(name);
    return source;
}

}  // namespace

std::string meshVertex() { return compose({"mesh_vertex.glsl"}); }

std::string meshFragment()
{
    return compose({"distance_field.glsl", "mesh_buffers.glsl", "colour_map.glsl", "shading.glsl", "mesh_fragment.glsl"});
}

std::string fullScreenVertex() { return compose({"full_screen_vertex.glsl"}); }

std::string outlineFragment() { return compose({"outline_fragment.glsl"}); }

bool hasIndirectFragment(const std::string& method) { return findFile("method_" + method + ".glsl") != nullptr; }

std::string indirectFragment(const std::string& method)
{
    return compose({"distance_field.glsl", "mesh_buffers.glsl", "colour_map.glsl", "shading.glsl", "camera_ray.glsl", "landing.glsl",
                    "hull_search.glsl", "curved_ray.glsl", "method_" + method + ".glsl", "indirect_main.glsl"});
}

}  // namespace ivis::app::shaders
