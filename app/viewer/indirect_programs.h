/// @file indirect_programs.h
/// @brief The full-screen indirect programs, one per visualisation method, each compiled the first
///        time its method is drawn.
/// @note Needs a current OpenGL 4.3 core context; not thread-safe.
#pragma once

#include "gl_objects.h"

#include <ivis/render/method.h>

#include <map>
#include <string>

namespace ivis::app {

/// @brief Indirect programs by method name, compiled lazily.
class IndirectPrograms {
public:
    /// @brief The program of the method @a method describes, compiled on first use from
    ///        shaders::indirectFragment(its name).
    /// @throw GlError when the method has no snippet, the program does not compile, or it reads no
    ///        uniform for one of the method's parameters (a renamed key would feed nothing)
    GlProgram& get(const render::MethodInfo& method);

private:
    std::map<std::string, GlProgram> mPrograms;
};

}  // namespace ivis::app
