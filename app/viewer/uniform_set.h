/// @file uniform_set.h
/// @brief Uniform values kept by name and written to any program, so that a program compiled later
///        (the indirect programs are compiled on first use) gets them too.
/// @note applyTo needs a current OpenGL context; not thread-safe.
#pragma once

#include "gl_objects.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <map>
#include <string>
#include <variant>

namespace ivis::app {

/// @brief Named uniform values (int, float, vec2, vec3, ivec3; bools as int).
class UniformSet {
public:
    using Value = std::variant<int, float, glm::vec2, glm::vec3, glm::ivec3>;

    /// @brief Keeps @a value for the uniform @a name, replacing the one kept before (one overload
    ///        per type, as GlProgram::set, so that no argument converts to another type).
    void set(const std::string& name, int value) { mValues[name] = value; }
    void set(const std::string& name, bool value) { mValues[name] = int(value); }
    void set(const std::string& name, float value) { mValues[name] = value; }
    void set(const std::string& name, const glm::vec2& value) { mValues[name] = value; }
    void set(const std::string& name, const glm::vec3& value) { mValues[name] = value; }
    void set(const std::string& name, const glm::ivec3& value) { mValues[name] = value; }
    /// @brief Writes every kept value to @a program; GL ignores the uniforms it does not use.
    void applyTo(GlProgram& program) const;

private:
    std::map<std::string, Value> mValues;
};

}  // namespace ivis::app
