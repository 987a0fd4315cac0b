#include "gpu_renderer.h"

#include "shaders.h"

#include <ivis/core/colormap.h>
#include <ivis/core/errors.h>
#include <ivis/render/curved_ray.h>
#include <ivis/render/neugebauer_map.h>
#include <ivis/vdb/surface_volume.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace ivis::app {
namespace {

constexpr GLuint kFarUnit = 1, kTriangleUnit = 2, kColormapUnit = 3, kBandUnit = 4;
constexpr int kMaxHullSteps = 4096;  // the CPU's backward hull search is unbounded; 4096 is never reached in practice
constexpr int kRingMaxSteps = 1000;

glm::vec3 toFloat(const glm::dvec3& v) { return glm::vec3(v); }

/// World -> clip for a camera, built from CameraFrame's own basis so rasterised and traced pixels agree.
glm::mat4 clipFromWorld(const core::CameraFrame& frame)
{
    const core::Camera& camera = frame.camera();
    const glm::dvec3 r = frame.right(), u = frame.upVector(), f = frame.forward(), eye = camera.eye;
    glm::dmat4 view(1.0);
    for (int i = 0; i < 3; ++i) {
        view[i][0] = r[i];
        view[i][1] = u[i];
        view[i][2] = -f[i];
    }
    view[3][0] = -glm::dot(r, eye);
    view[3][1] = -glm::dot(u, eye);
    view[3][2] = glm::dot(f, eye);
    // The mesh lies in [-1,1]^3: within sqrt(3) of the origin.
    const double centre = glm::dot(glm::dvec3(0.0) - eye, f), margin = 2.0;
    const double aspect = double(frame.width()) / double(frame.height());
    glm::dmat4 projection(0.0);
    if (camera.orthographic) {
        const double hh = camera.orthoHalfHeight, n = centre - margin, fa = centre + margin;
        projection[0][0] = 1.0 / (hh * aspect);
        projection[1][1] = 1.0 / hh;
        projection[2][2] = -2.0 / (fa - n);
        projection[3][2] = -(fa + n) / (fa - n);
        projection[3][3] = 1.0;
    } else {
        const double hh = std::tan(0.5 * camera.fovYDeg * M_PI / 180.0);
        const double n = std::max(1e-3, centre - margin), fa = std::max(n + 1e-3, centre + margin);
        projection[0][0] = 1.0 / (hh * aspect);
        projection[1][1] = 1.0 / hh;
        projection[2][2] = -(fa + n) / (fa - n);
        projection[2][3] = -1.0;
        projection[3][2] = -2.0 * fa * n / (fa - n);
    }
    return glm::mat4(projection * view);
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

GLuint newName(void (*generate)(GLsizei, GLuint*))
{
    GLuint id = 0;
    generate(1, &id);
    return id;
}

}  // namespace

GpuRenderer::GpuRenderer()
    : mMeshProgram("mesh", shaders::meshVertex().c_str(), shaders::meshFragment().c_str()),
      mIndirectProgram("indirect", shaders::fullScreenVertex().c_str(), shaders::indirectFragment().c_str()),
      mMeshVao(newName(glGenVertexArrays)),
      mEmptyVao(newName(glGenVertexArrays)),
      mPositions(newName(glGenBuffers)),
      mNormals(newName(glGenBuffers)),
      mIndices(newName(glGenBuffers)),
      mFar(newName(glGenTextures)),
      mBand(newName(glGenTextures)),
      mTriangles(newName(glGenTextures)),
      mColormap(newName(glGenTextures)),
      mTarget(newName(glGenFramebuffers)),
      mColourTexture(newName(glGenTextures)),
      mRegionTexture(newName(glGenTextures)),
      mDepth(newName(glGenRenderbuffers))
{
    for (GlProgram* program : {&mMeshProgram, &mIndirectProgram}) program->set("uVolumeReady", false);
    setColormap(core::kDefaultColormap);
    checkGl("creating the renderer");
}

void GpuRenderer::setMesh(const core::SurfaceField& field, const std::vector<glm::vec3>& normals)
{
    const core::TriangleMesh& mesh = field.mesh;
    std::vector<glm::vec4> positions(mesh.positions.size()), normalsNan(mesh.positions.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const float value = field.hasScalar() ? field.values[i] : 0.0f;
        positions[i] = glm::vec4(mesh.positions[i], std::isnan(value) ? 0.0f : value);
        normalsNan[i] = glm::vec4(normals[i], std::isnan(value) ? 1.0f : 0.0f);
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
    mIndexCount = GLsizei(indices.size());
    for (GlProgram* program : {&mMeshProgram, &mIndirectProgram}) {
        program->set("uHasScalar", field.hasScalar());
        program->set("uDataTriangles", int(std::min<std::size_t>(mesh.dataTriangleCount, 0x7fffffff)));
    }
    checkGl("uploading the mesh");
}

void GpuRenderer::setVolume(const DenseSlices& slices, float fineVoxelSize, float interiorStep)
{
    mHasVolume = false;
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    auto upload = [](const GlTexture& texture, GLint internal, GLenum format, GLenum type, const std::array<int, 3>& dims,
                     const void* data, const char* what) {
        glBindTexture(GL_TEXTURE_3D, texture.id());
        textureParameters(GL_TEXTURE_3D, GL_NEAREST);
        const bool empty = dims[0] * dims[1] * dims[2] == 0;
        const float none[4] = {0.0f, 0.0f, 0.0f, 0.0f};
        glTexImage3D(GL_TEXTURE_3D, 0, internal, empty ? 1 : dims[0], empty ? 1 : dims[1], empty ? 1 : dims[2], 0,
                     format, type, empty ? static_cast<const void*>(none) : data);
        checkGl(what);
    };
    upload(mFar, GL_R32F, GL_RED, GL_FLOAT, slices.far.dims, slices.far.values.data(), "uploading the far-field texture");
    upload(mBand, GL_R32F, GL_RED, GL_FLOAT, slices.band.dims, slices.band.values.data(), "uploading the band texture");
    upload(mTriangles, GL_R32I, GL_RED_INTEGER, GL_INT, slices.triangles.dims, slices.triangles.values.data(),
           "uploading the triangle texture");
    glBindTexture(GL_TEXTURE_3D, 0);

    auto dims = [](const std::array<int, 3>& d) { return glm::ivec3(d[0], d[1], d[2]); };
    for (GlProgram* program : {&mMeshProgram, &mIndirectProgram}) {
        program->set("uFarDims", dims(slices.far.dims));
        program->set("uFarOrigin", slices.far.origin);
        program->set("uFarInvVoxel", 1.0f / slices.farVoxelSize);
        program->set("uOutside", slices.outside);
        program->set("uHasFineBand", slices.hasFineBand);
        program->set("uTrustBelow", slices.trustBelow);
        program->set("uBandDims", dims(slices.band.dims));
        program->set("uBandOrigin", slices.band.origin);
        program->set("uTriangleDims", dims(slices.triangles.dims));
        program->set("uTriangleOrigin", slices.triangles.origin);
        program->set("uVoxel", slices.voxelSize);
        program->set("uInvVoxel", 1.0f / slices.voxelSize);
        program->set("uUnsigned", slices.unsignedDistance);
        program->set("uVolumeReady", true);
    }
    mIndirectProgram.set("uInteriorStep", interiorStep);
    mIndirectProgram.set("uBoxHalf", float(vdb::kBoxHalfExtent));
    mFineVoxelSize = fineVoxelSize;
    mReach = slices.reach;
    mTextureVoxelSize = slices.voxelSize;
    mHasVolume = true;
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

void GpuRenderer::resizeTarget(int width, int height)
{
    if (width == mWidth && height == mHeight) return;
    glBindTexture(GL_TEXTURE_2D, mColourTexture.id());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glBindTexture(GL_TEXTURE_2D, mRegionTexture.id());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R8UI, width, height, 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE, nullptr);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindRenderbuffer(GL_RENDERBUFFER, mDepth.id());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, mTarget.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, mColourTexture.id(), 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, mRegionTexture.id(), 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, mDepth.id());
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    checkGl("creating the offscreen target");
    if (status != GL_FRAMEBUFFER_COMPLETE) throw GlError("the offscreen framebuffer is incomplete");
    mWidth = width;
    mHeight = height;
}

void GpuRenderer::render(const GpuFrame& frame)
{
    IVIS_CHECK(mField != nullptr);
    resizeTarget(frame.width, frame.height);
    const core::CameraFrame camera(frame.camera, frame.width, frame.height);
    const render::MethodParams& method = frame.method;
    const render::ShadingOptions& shading = frame.shading;

    // Per-frame uniforms shared by both programs.
    const glm::vec3 eye = toFloat(frame.camera.eye), right = toFloat(camera.right()), up = toFloat(camera.upVector()),
                    forward = toFloat(camera.forward());
    for (GlProgram* program : {&mMeshProgram, &mIndirectProgram}) {
        program->set("uRange", glm::vec2(shading.range.lo, shading.range.hi));
        program->set("uNanColour", shading.nanColour);
        program->set("uNoDataColour", shading.noDataColour);
        program->set("uEye", eye);
        program->set("uForward", forward);
        program->set("uOrtho", frame.camera.orthographic);
    }
    mMeshProgram.set("uClipFromWorld", clipFromWorld(camera));
    mMeshProgram.set("uToLight", toFloat(glm::normalize(-0.35 * camera.right() + 0.55 * camera.upVector() -
                                                        0.75 * camera.forward())));
    mMeshProgram.set("uAmbient", shading.ambient);
    mMeshProgram.set("uShadows", shading.shadows);

    const bool indirect = mHasVolume && (method.curvedRays() || method.method == render::Method::Mirror ||
                                         method.method == render::Method::Neugebauer);
    if (indirect) {
        GlProgram& p = mIndirectProgram;
        p.set("uViewport", glm::vec2(float(frame.width), float(frame.height)));
        p.set("uHalfHeight", float(frame.camera.orthographic ? frame.camera.orthoHalfHeight
                                                             : std::tan(0.5 * frame.camera.fovYDeg * M_PI / 180.0)));
        p.set("uAspect", float(double(frame.width) / double(frame.height)));
        p.set("uRight", right);
        p.set("uUp", up);
        p.set("uMethod", int(method.method));
        p.set("uIndirectBrightness", shading.indirectBrightness);
        const render::CurvedRayParams& curved = method.curved;
        p.set("uEpsilon", curved.landingEpsilon > 0.0f ? curved.landingEpsilon : 0.5f * mTextureVoxelSize);
        p.set("uAlpha", curved.alpha);
        const std::array<float, 3>& a = method.profile.coefficients;
        p.set("uAlphaProfile", glm::vec3(a[0], a[1], a[2]));
        p.set("uMaxAlpha", method.profile.maxAlpha);
        p.set("uRetries", method.profile.retries);
        p.set("uStepSize", curved.stepSize);
        p.set("uHullOffset", curved.hullOffset);
        p.set("uEscape", 0.999f * mReach);
        p.set("uMaxSteps", curved.maxSteps);
        p.set("uMaxHullSteps", kMaxHullSteps);
        const core::Bounds3 hull = render::hullBounds(mField->mesh, curved.hullOffset, mFineVoxelSize);
        p.set("uHullLo", glm::vec3(hull.lo));
        p.set("uHullHi", glm::vec3(hull.hi));
        p.setArray("uMirrorW", method.mirror.w.data(), 5);
        p.set("uMirrorZm", float(-glm::length(frame.camera.target - frame.camera.eye) - method.mirror.distanceBehind));
        p.set("uMirrorMaxSteps", method.mirror.maxSteps);
        if (method.method == render::Method::Neugebauer) {
            const render::RingLayout rings = render::layoutRings(camera, mField->mesh, method.ring);
            p.set("uRingCentre", glm::vec2(rings.centre));
            p.set("uRingInner", float(rings.innerRadius));
            p.set("uRingOuter", float(rings.outerRadius));
            p.set("uBackCentre", glm::vec2(rings.backCentre));
            p.set("uBackRadius", float(rings.backRadius));
            p.set("uRingOrigin", method.ring.centre);
            p.set("uRingMaxSteps", kRingMaxSteps);
        }
    }

    glBindFramebuffer(GL_FRAMEBUFFER, mTarget.id());
    glViewport(0, 0, frame.width, frame.height);
    const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glDrawBuffers(2, buffers);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_FRAMEBUFFER_SRGB);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    const glm::vec3 background(core::srgbFromLinear(shading.background.x), core::srgbFromLinear(shading.background.y),
                               core::srgbFromLinear(shading.background.z));
    const GLfloat clearColour[4] = {background.x, background.y, background.z, 1.0f};
    const GLuint clearRegion[4] = {0, 0, 0, 0};
    const GLfloat clearDepth = 1.0f;
    glClearBufferfv(GL_COLOR, 0, clearColour);
    glClearBufferuiv(GL_COLOR, 1, clearRegion);
    glClearBufferfv(GL_DEPTH, 0, &clearDepth);

    glActiveTexture(GL_TEXTURE0 + kFarUnit);
    glBindTexture(GL_TEXTURE_3D, mFar.id());
    glActiveTexture(GL_TEXTURE0 + kBandUnit);
    glBindTexture(GL_TEXTURE_3D, mBand.id());
    glActiveTexture(GL_TEXTURE0 + kTriangleUnit);
    glBindTexture(GL_TEXTURE_3D, mTriangles.id());
    glActiveTexture(GL_TEXTURE0 + kColormapUnit);
    glBindTexture(GL_TEXTURE_2D, mColormap.id());
    glActiveTexture(GL_TEXTURE0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, mPositions.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, mNormals.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, mIndices.id());

    // Direct part: every face (render::FaceFilter::Any), or only those turned away (Backfaces).
    if (method.method == render::Method::Backfaces) {
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
    if (indirect) {
        glDepthFunc(GL_LEQUAL);
        glDepthMask(GL_FALSE);
        glUseProgram(mIndirectProgram.id());
        glBindVertexArray(mEmptyVao.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glDepthMask(GL_TRUE);
        glDepthFunc(GL_LESS);
    }
    glBindVertexArray(0);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    checkGl("rendering a frame");
}

void GpuRenderer::blitTo(int x, int y, int width, int height) const
{
    glBindFramebuffer(GL_READ_FRAMEBUFFER, mTarget.id());
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    const bool same = width == mWidth && height == mHeight;
    glBlitFramebuffer(0, 0, mWidth, mHeight, x, y, x + width, y + height, GL_COLOR_BUFFER_BIT,
                      same ? GL_NEAREST : GL_LINEAR);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
}

core::Image GpuRenderer::readColour() const
{
    std::vector<std::uint8_t> bytes(std::size_t(mWidth) * mHeight * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, mTarget.id());
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, mWidth, mHeight, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    checkGl("reading the colour back");
    float decode[256];
    for (int i = 0; i < 256; ++i) decode[i] = core::linearFromSrgb(float(i) / 255.0f);
    core::Image image(mWidth, mHeight);
    for (int row = 0; row < mHeight; ++row) {
        const std::uint8_t* src = bytes.data() + std::size_t(mHeight - 1 - row) * mWidth * 4;  // GL rows start at the bottom
        for (int x = 0; x < mWidth; ++x)
            image.at(x, row) = glm::vec4(decode[src[4 * x]], decode[src[4 * x + 1]], decode[src[4 * x + 2]], 1.0f);
    }
    return image;
}

std::vector<std::uint8_t> GpuRenderer::readRegion() const
{
    std::vector<std::uint8_t> bytes(std::size_t(mWidth) * mHeight), region(bytes.size());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, mTarget.id());
    glReadBuffer(GL_COLOR_ATTACHMENT1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, mWidth, mHeight, GL_RED_INTEGER, GL_UNSIGNED_BYTE, bytes.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    checkGl("reading the regions back");
    for (int row = 0; row < mHeight; ++row)
        std::copy_n(bytes.data() + std::size_t(mHeight - 1 - row) * mWidth, mWidth, region.data() + std::size_t(row) * mWidth);
    return region;
}

}  // namespace ivis::app
