/// @file gpu_renderer.h
/// @brief The viewer's OpenGL renderer: rasterises the mesh (direct part, shadows), then traces the
///        method's indirect rays for the empty pixels in a full-screen pass, into an offscreen
///        target holding sRGB colour and the region of every pixel.
/// @note Needs a current OpenGL 4.3 core context; not thread-safe (GL calls on one thread only).
#pragma once

#include "dense_slices.h"
#include "gl_objects.h"
#include "gpu_frame.h"
#include "gpu_uniforms.h"
#include "indirect_programs.h"
#include "offscreen_target.h"
#include "uniform_set.h"
#include "volume_textures.h"

#include <ivis/core/image.h>
#include <ivis/core/surface_field.h>
#include <ivis/render/renderer.h>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace ivis::app {

/// @brief GL state of the viewer: mesh buffers, volume textures, programs and the offscreen target.
class GpuRenderer {
public:
    /// @brief Compiles the mesh program (each method's indirect program is compiled when first drawn).
    /// @throw GlError
    GpuRenderer();

    /// @brief Uploads positions, @a normals, triangles and the shown scalar (NaN flagged): per vertex
    ///        beside the positions, or per triangle for a cell scalar.
    /// @param field normalised surface; kept by reference (ring layout, hull box) and must outlive this
    void setMesh(const core::SurfaceField& field, const std::vector<glm::vec3>& normals);
    /// @brief Uploads the far, band and triangle boxes of the mesh given to setMesh.
    ///        @throw GlError (e.g. GL_OUT_OF_MEMORY)
    /// @param fineVoxelSize the volume's own voxel size (the CPU's hull box uses it)
    /// @param interiorStep largest step trusted where phi < 0 (the interior band width)
    void setVolume(const DenseSlices& slices, float fineVoxelSize, float interiorStep);
    /// @brief Tabulates core::colormap(@a name) at 256 points into the colour-map texture.
    void setColormap(const std::string& name);
    /// @brief Forgets the volume (the mesh changed): only the direct part is drawn until setVolume.
    void dropVolume();

    /// @brief Renders @a frame into the offscreen target (resized to the frame's size).
    /// @throw GlError when the method's indirect program does not compile
    void render(const GpuFrame& frame);
    /// @brief Shows @a picture (a CPU render of the same size or any other) in the offscreen target
    ///        instead of a frame of render(): its colour and its regions.
    void show(const render::RenderResult& picture);
    /// @brief Copies the offscreen colour into the bound draw framebuffer's rectangle (x, y, w, h).
    void blitTo(int x, int y, int width, int height) const { mTarget.blitTo(x, y, width, height); }
    /// @brief The last frame as a linear image (decoded from the 8-bit sRGB target), row 0 at the top.
    core::Image readColour() const { return mTarget.readColour(); }
    /// @brief The last frame's regions (0 background, 1 direct, 2 indirect), row 0 at the top.
    std::vector<std::uint8_t> readRegion() const { return mTarget.readRegion(); }
    /// @brief Size of the offscreen target in pixels.
    int width() const { return mTarget.width(); }
    int height() const { return mTarget.height(); }

private:
    /// Darkens the direct pixels at the direct part's edge in the offscreen colour (frame @a height).
    void drawOutline(int height);

    GlProgram mMeshProgram;
    GlProgram mOutlineProgram;
    IndirectPrograms mIndirectPrograms;  ///< one per method, by name
    UniformSet mSceneUniforms;           ///< mesh and volume uniforms, written to each program drawn
    GlVertexArray mMeshVao;
    GlVertexArray mEmptyVao;
    GlBuffer mPositions;  ///< vec4(position, scalar)
    GlBuffer mNormals;    ///< vec4(normal, NaN flag)
    GlBuffer mIndices;    ///< 3 uint per triangle
    GlBuffer mTriangleScalars;  ///< vec2(scalar, NaN flag) per data triangle, for a cell scalar
    /// Each method's vertex arrays (DenseSlices::methodArrays), by method name.
    std::map<std::string, std::vector<GlBuffer>> mMethodBuffers;
    VolumeTextures mVolume;
    GlTexture mColormap;
    OffscreenTarget mTarget;
    const core::SurfaceField* mField = nullptr;
    core::Bounds3 mMeshBounds;  ///< mField's mesh's bounds
    GLsizei mIndexCount = 0;
    bool mHasVolume = false;
    VolumeScale mVolumeScale;
};

}  // namespace ivis::app
