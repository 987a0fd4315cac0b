/// @file indirect_programs.h
/// @brief The full-screen indirect programs, one per visualisation method, each compiled the first
///        time its method is drawn.
/// @note Needs a current OpenGL 4.3 core context; not thread-safe.
#pragma once

#include "gl_objects.h"

#include <map>
#include <string>

namespace ivis::app {

/// @brief Indirect programs by method name, compiled lazily.
class IndirectPrograms {
public:
    /// @brief The program of the method named @a method (its command-line name), compiled on first use
    ///        from shaders::indirectFragment(@a method).
    /// @throw GlError when the method has no snippet or the program does not compile
    GlProgram& get(const std::string& method);

private:
    std::map<std::string, GlProgram> mPrograms;
};

}  // namespace ivis::app
