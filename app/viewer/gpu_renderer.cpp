#include "gpu_renderer.h"

#include "shaders.h"

#include <ivis/core/colormap.h>
#include <ivis/core/errors.h>
#include <ivis/core/image_io.h>
#include <ivis/render/curved_ray.h>

#include <algorithm>
#include <cmath>

namespace ivis::app {
namespace {

constexpr GLuint kColormapUnit = 3;  // layout(binding = 3) in colour_map.glsl

}  // namespace

GpuRenderer::GpuRenderer()
    : mMeshProgram("mesh", shaders::meshVertex().c_str(), shaders::meshFragment().c_str()),
      mOutlineProgram("outline", shaders::fullScreenVertex().c_str(), shaders::outlineFragment().c_str()),
      mMeshVao(newName(glGenVertexArrays)),
      mEmptyVao(newName(glGenVertexArrays)),
      mPositions(newName(glGenBuffers)),
      mNormals(newName(glGenBuffers)),
      mIndices(newName(glGenBuffers)),
      mTriangleScalars(newName(glGenBuffers)),
      mColormap(newName(glGenTextures))
{
    shaders::checkIndirectSnippets();
    mSceneUniforms.set("uVolumeReady", false);
    setColormap(core::kDefaultColormap);
    checkGl("creating the renderer");
}

void GpuRenderer::setMesh(const core::SurfaceField& field, const std::vector<glm::vec3>& normals)
{
    const core::TriangleMesh& mesh = field.mesh;
    const bool pointScalar = field.hasScalar() && field.valuesOn == core::Association::Point;
    std::vector<glm::vec4> positions(mesh.positions.size()), normalsNan(mesh.positions.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const float value = pointScalar ? field.values[i] : 0.0f;
        positions[i] = glm::vec4(mesh.positions[i], std::isnan(value) ? 0.0f : value);
        normalsNan[i] = glm::vec4(normals[i], std::isnan(value) ? 1.0f : 0.0f);
    }
    std::vector<glm::vec2> cellScalars;
    if (field.hasScalar() && !pointScalar) {
        for (const float value : field.values)
            cellScalars.emplace_back(std::isnan(value) ? 0.0f : value, std::isnan(value) ? 1.0f : 0.0f);
    }
    std::vector<GLuint> indices;
    indices.reserve(mesh.triangles.size() * 3);
    for (const auto& t : mesh.triangles) indices.insert(indices.end(), t.begin(), t.end());
    auto upload = [](const GlBuffer& buffer, const void* data, std::size_t bytes) {
        glBindBuffer(GL_ARRAY_BUFFER, buffer.id());
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(std::max<std::size_t>(bytes, 16)), data, GL_STATIC_DRAW);
    };
    upload(mPositions, positions.data(), positions.size() * sizeof(glm::vec4));
    upload(mNormals, normalsNan.data(), normalsNan.size() * sizeof(glm::vec4));
    upload(mIndices, indices.data(), indices.size() * sizeof(GLuint));
    upload(mTriangleScalars, cellScalars.data(), cellScalars.size() * sizeof(glm::vec2));

    glBindVertexArray(mMeshVao.id());
    glBindBuffer(GL_ARRAY_BUFFER, mPositions.id());
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, sizeof(glm::vec4), nullptr);
    glBindBuffer(GL_ARRAY_BUFFER, mNormals.id());
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(glm::vec4), nullptr);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, mIndices.id());
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);

    mField = &field;
    mMeshBounds = core::bounds(field.mesh);
    mIndexCount = GLsizei(indices.size());
    keepMeshUniforms(mSceneUniforms, field);
    checkGl("uploading the mesh");
}

void GpuRenderer::setVolume(const DenseSlices& slices, float fineVoxelSize, float interiorStep)
{
    mHasVolume = false;
    mVolume.upload(slices);
    mMethodBuffers.clear();
    for (const auto& [method, arrays] : slices.methodArrays)
        for (const std::vector<float>& array : arrays) {
            GlBuffer& buffer = mMethodBuffers[method].emplace_back(newName(glGenBuffers));
            glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer.id());
            glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(std::max<std::size_t>(array.size() * sizeof(float), 16)),
                         array.data(), GL_STATIC_DRAW);
        }
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    keepVolumeUniforms(mSceneUniforms, slices, interiorStep, render::hullBounds(mMeshBounds, 0.0f, fineVoxelSize));
    mVolumeScale = {fineVoxelSize, slices.reach};
    mHasVolume = true;
}

void GpuRenderer::dropVolume()
{
    mHasVolume = false;
    mSceneUniforms.set("uVolumeReady", false);
}

void GpuRenderer::setColormap(const std::string& name)
{
    const core::Colormap& map = core::colormap(name);
    std::vector<glm::vec4> table(256);
    for (int i = 0; i < 256; ++i) table[std::size_t(i)] = glm::vec4(map.at(float(i) / 255.0f), 1.0f);
    glBindTexture(GL_TEXTURE_2D, mColormap.id());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, 256, 1, 0, GL_RGBA, GL_FLOAT, table.data());
    glBindTexture(GL_TEXTURE_2D, 0);
    checkGl("uploading the colour map");
}

void GpuRenderer::drawOutline(int height)
{
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
    mTarget.bindImages(0, 1);
    mOutlineProgram.set("uOutlineRadius", std::max(1, height / 400));  // as the CPU renderer's
    glDisable(GL_DEPTH_TEST);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glUseProgram(mOutlineProgram.id());
    glBindVertexArray(mEmptyVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glEnable(GL_DEPTH_TEST);
    glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_PIXEL_BUFFER_BARRIER_BIT);
}

void GpuRenderer::show(const render::RenderResult& picture)
{
    const core::Channel& regions = picture.layers.channel("region");
    std::vector<std::uint8_t> region(regions.size());
    std::transform(regions.begin(), regions.end(), region.begin(), [](float r) { return std::uint8_t(r); });
    const std::vector<std::uint8_t> rgb = core::srgbPixels(picture.image, false);  // the PNG's pixels
    std::vector<std::uint8_t> rgba(region.size() * 4, 255);
    for (std::size_t i = 0; i < region.size(); ++i) std::copy_n(rgb.data() + 3 * i, 3, rgba.data() + 4 * i);
    mTarget.upload(rgba, region, picture.image.width(), picture.image.height());
}

void GpuRenderer::render(const GpuFrame& frame)
{
    IVIS_CHECK(mField != nullptr);
    mTarget.resize(frame.width, frame.height);
    const core::CameraFrame camera(frame.camera, frame.width, frame.height);
    const render::Method& method = *frame.method;

    mSceneUniforms.applyTo(mMeshProgram);
    setMeshPassUniforms(mMeshProgram, frame, camera);
    GlProgram* indirectProgram = mHasVolume && method.drawsIndirect() ? &mIndirectPrograms.get(method.info()) : nullptr;
    if (indirectProgram) {
        mSceneUniforms.applyTo(*indirectProgram);
        setIndirectUniforms(*indirectProgram, frame, camera, *mField, mMeshBounds, mVolumeScale);
    }

    mTarget.beginFrame(frame.shading.background);
    mVolume.bind();
    glActiveTexture(GL_TEXTURE0 + kColormapUnit);
    glBindTexture(GL_TEXTURE_2D, mColormap.id());
    glActiveTexture(GL_TEXTURE0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, mPositions.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, mNormals.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, mIndices.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, mTriangleScalars.id());
    if (const auto buffers = mMethodBuffers.find(method.name()); buffers != mMethodBuffers.end())
        for (std::size_t k = 0; k < buffers->second.size(); ++k)
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(shaders::kFirstMethodBuffer + int(k)), buffers->second[k].id());

    // Direct part: every face, or only those turned away from the camera.
    if (method.directFaces() == core::FaceFilter::BackOnly) {
        glEnable(GL_CULL_FACE);
        glFrontFace(GL_CCW);
        glCullFace(GL_FRONT);
    } else {
        glDisable(GL_CULL_FACE);
    }
    glUseProgram(mMeshProgram.id());
    glBindVertexArray(mMeshVao.id());
    glDrawElements(GL_TRIANGLES, mIndexCount, GL_UNSIGNED_INT, nullptr);
    glDisable(GL_CULL_FACE);

    // Indirect part: only where the depth is still the cleared 1.
    if (indirectProgram) {
        glDepthFunc(GL_LEQUAL);
        glDepthMask(GL_FALSE);
        glUseProgram(indirectProgram->id());
        glBindVertexArray(mEmptyVao.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glDepthMask(GL_TRUE);
        glDepthFunc(GL_LESS);
    }
    if (frame.outline) drawOutline(frame.height);
    glBindVertexArray(0);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    checkGl("rendering a frame");
}

}  // namespace ivis::app
