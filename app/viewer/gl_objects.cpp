#include "gl_objects.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace ivis::app {
namespace {

const char* errorName(GLenum error)
{
    switch (error) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    default: return "unknown GL error";
    }
}

GLuint compileShader(const char* program, GLenum type, const char* source)
{
    const GLuint shader = glCreateShader(type);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
        std::vector<char> log(std::size_t(std::max(length, 1)), '\0');
        glGetShaderInfoLog(shader, length, nullptr, log.data());
        glDeleteShader(shader);
        const char* stage = type == GL_VERTEX_SHADER ? "vertex" : type == GL_FRAGMENT_SHADER ? "fragment" : "compute";
        throw GlError(std::string("shader '") + program + "' (" + stage + ") does not compile: " + log.data());
    }
    return shader;
}

}  // namespace

void checkGl(const char* what)
{
    GLenum first = glGetError();
    if (first == GL_NO_ERROR) return;
    for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; ++i) {
    }
    throw GlError(std::string(what) + ": " + errorName(first));
}

GLuint newName(void (*generate)(GLsizei, GLuint*))
{
    GLuint id = 0;
    generate(1, &id);
    return id;
}

void textureParameters(GLenum target, GLint filter)
{
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, filter);
    glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(target, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    glTexParameteri(target, GL_TEXTURE_MAX_LEVEL, 0);
}

void detail::deleteBuffer(GLuint id) { glDeleteBuffers(1, &id); }
void detail::deleteTexture(GLuint id) { glDeleteTextures(1, &id); }
void detail::deleteFramebuffer(GLuint id) { glDeleteFramebuffers(1, &id); }
void detail::deleteRenderbuffer(GLuint id) { glDeleteRenderbuffers(1, &id); }
void detail::deleteVertexArray(GLuint id) { glDeleteVertexArrays(1, &id); }
void detail::deleteProgram(GLuint id) { glDeleteProgram(id); }

GlProgram::GlProgram(const char* name, const char* vertexSource, const char* fragmentSource)
{
    const GLuint vertex = compileShader(name, GL_VERTEX_SHADER, vertexSource);
    GLuint fragment = 0;
    try {
        fragment = compileShader(name, GL_FRAGMENT_SHADER, fragmentSource);
    } catch (...) {
        glDeleteShader(vertex);
        throw;
    }
    link(name, {vertex, fragment});
}

GlProgram::GlProgram(const char* name, const char* computeSource)
{
    link(name, {compileShader(name, GL_COMPUTE_SHADER, computeSource)});
}

void GlProgram::link(const char* name, std::initializer_list<GLuint> shaders)
{
    mProgram = GlHandle<detail::deleteProgram>(glCreateProgram());
    for (GLuint shader : shaders) glAttachShader(mProgram.id(), shader);
    glLinkProgram(mProgram.id());
    for (GLuint shader : shaders) glDeleteShader(shader);
    GLint ok = 0;
    glGetProgramiv(mProgram.id(), GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetProgramiv(mProgram.id(), GL_INFO_LOG_LENGTH, &length);
        std::vector<char> log(std::size_t(std::max(length, 1)), '\0');
        glGetProgramInfoLog(mProgram.id(), length, nullptr, log.data());
        throw GlError(std::string("program '") + name + "' does not link: " + log.data());
    }
}

GLint GlProgram::location(const char* name)
{
    auto it = mLocations.find(name);
    if (it == mLocations.end()) it = mLocations.emplace(name, glGetUniformLocation(mProgram.id(), name)).first;
    return it->second;  // -1 for uniforms the compiler removed: GL ignores those writes
}

void GlProgram::set(const char* name, int value) { glProgramUniform1i(id(), location(name), value); }
void GlProgram::set(const char* name, float value) { glProgramUniform1f(id(), location(name), value); }
void GlProgram::set(const char* name, const glm::vec2& value)
{
    glProgramUniform2f(id(), location(name), value.x, value.y);
}
void GlProgram::set(const char* name, const glm::vec3& value)
{
    glProgramUniform3f(id(), location(name), value.x, value.y, value.z);
}
void GlProgram::set(const char* name, const glm::ivec3& value)
{
    glProgramUniform3i(id(), location(name), value.x, value.y, value.z);
}
void GlProgram::set(const char* name, const glm::mat4& value)
{
    glProgramUniformMatrix4fv(id(), location(name), 1, GL_FALSE, glm::value_ptr(value));
}
void GlProgram::setArray(const char* name, const float* values, int count)
{
    glProgramUniform1fv(id(), location(name), count, values);
}

}  // namespace ivis::app
