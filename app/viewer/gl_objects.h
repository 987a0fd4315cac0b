/// @file gl_objects.h
/// @brief Owning handles for OpenGL objects, shader compilation and error checks (libepoxy).
/// @note Every function needs a current OpenGL 4.3 core context on the calling thread.
#pragma once

#include <epoxy/gl.h>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <initializer_list>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

namespace ivis::app {

/// @brief An OpenGL failure: no suitable context, a shader that does not compile, out of memory.
class GlError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// @brief Throws GlError naming @a what if glGetError reports anything (drains the error queue).
void checkGl(const char* what);

/// @brief A new GL object name from a glGen* function (glGenBuffers, glGenTextures, ...).
GLuint newName(void (*generate)(GLsizei, GLuint*));

/// @brief Filtering @a filter at level 0 only, clamped to the edge, for the texture bound to @a target.
void textureParameters(GLenum target, GLint filter);

/// @brief A GL object name with its delete function; move-only.
template <void (*Delete)(GLuint)>
class GlHandle {
public:
    GlHandle() = default;
    explicit GlHandle(GLuint id) : mId(id) {}
    ~GlHandle() { reset(); }
    GlHandle(GlHandle&& other) noexcept : mId(std::exchange(other.mId, 0)) {}
    GlHandle& operator=(GlHandle&& other) noexcept
    {
        if (this != &other) {
            reset();
            mId = std::exchange(other.mId, 0);
        }
        return *this;
    }
    GlHandle(const GlHandle&) = delete;
    GlHandle& operator=(const GlHandle&) = delete;
    /// @brief The GL name (0 when empty).
    GLuint id() const { return mId; }
    /// @brief Deletes the object.
    void reset()
    {
        if (mId) Delete(mId);
        mId = 0;
    }

private:
    GLuint mId = 0;
};

namespace detail {
void deleteBuffer(GLuint id);
void deleteTexture(GLuint id);
void deleteFramebuffer(GLuint id);
void deleteRenderbuffer(GLuint id);
void deleteVertexArray(GLuint id);
void deleteProgram(GLuint id);
}  // namespace detail

using GlBuffer = GlHandle<detail::deleteBuffer>;
using GlTexture = GlHandle<detail::deleteTexture>;
using GlFramebuffer = GlHandle<detail::deleteFramebuffer>;
using GlRenderbuffer = GlHandle<detail::deleteRenderbuffer>;
using GlVertexArray = GlHandle<detail::deleteVertexArray>;

/// @brief A linked program with cached uniform locations; setters use glProgramUniform (no bind).
class GlProgram {
public:
    GlProgram() = default;
    /// @brief Compiles and links; throws GlError with the driver's log on failure.
    GlProgram(const char* name, const char* vertexSource, const char* fragmentSource);
    /// @brief A compute program (the shader tests run the snippets' functions in one); throws
    ///        GlError with the driver's log on failure.
    GlProgram(const char* name, const char* computeSource);
    GLuint id() const { return mProgram.id(); }
    void set(const char* name, int value);
    void set(const char* name, bool value) { set(name, int(value)); }
    void set(const char* name, float value);
    void set(const char* name, const glm::vec2& value);
    void set(const char* name, const glm::vec3& value);
    void set(const char* name, const glm::ivec3& value);
    void set(const char* name, const glm::mat4& value);
    /// @brief A float array uniform (name without brackets).
    void setArray(const char* name, const float* values, int count);

private:
    /// Links @a shaders (deleting them) into mProgram; throws GlError with the driver's log on failure.
    void link(const char* name, std::initializer_list<GLuint> shaders);
    GLint location(const char* name);
    GlHandle<detail::deleteProgram> mProgram;
    std::unordered_map<std::string, GLint> mLocations;
};

}  // namespace ivis::app
