/// @file gpu_renderer.h
/// @brief The viewer's OpenGL renderer: rasterises the mesh (direct part, shadows), then traces the
///        method's indirect rays for the empty pixels in a full-screen pass, into an offscreen
///        target holding sRGB colour and the region of every pixel.
/// @note Needs a current OpenGL 4.3 core context; not thread-safe (GL calls on one thread only).
#pragma once

#include "dense_slices.h"
#include "gl_objects.h"

#include <ivis/core/camera.h>
#include <ivis/core/image.h>
#include <ivis/core/surface_field.h>
#include <ivis/render/method.h>
#include <ivis/render/shading.h>

#include <cstdint>
#include <string>
#include <vector>

namespace ivis::app {

/// @brief What one frame shows.
struct GpuFrame {
    core::Camera camera;
    int width = 0;   ///< pixels of the offscreen target
    int height = 0;
    render::MethodParams method;
    render::ShadingOptions shading;  ///< colormap name is applied by setColormap()
};

/// @brief GL state of the viewer: mesh buffers, volume textures, programs and the offscreen target.
class GpuRenderer {
public:
    /// @brief Compiles the programs. @throw GlError
    GpuRenderer();

    /// @brief Uploads positions, per-vertex scalar (NaN flagged), @a normals and triangles.
    /// @param field normalised surface; kept by reference (ring layout, hull box) and must outlive this
    void setMesh(const core::SurfaceField& field, const std::vector<glm::vec3>& normals);
    /// @brief Uploads the far, band and triangle boxes. @throw GlError (e.g. GL_OUT_OF_MEMORY)
    /// @param fineVoxelSize the volume's own voxel size (the CPU's hull box uses it)
    /// @param interiorStep largest step trusted where phi < 0 (the interior band width)
    void setVolume(const DenseSlices& slices, float fineVoxelSize, float interiorStep);
    /// @brief Tabulates core::colormap(@a name) at 256 points into the colour-map texture.
    void setColormap(const std::string& name);
    /// @brief True once setVolume succeeded (indirect rays and shadows need it).
    bool hasVolume() const { return mHasVolume; }

    /// @brief Renders @a frame into the offscreen target (resized to the frame's size).
    void render(const GpuFrame& frame);
    /// @brief Copies the offscreen colour into the bound draw framebuffer's rectangle (x, y, w, h).
    void blitTo(int x, int y, int width, int height) const;
    /// @brief The last frame as a linear image (decoded from the 8-bit sRGB target), row 0 at the top.
    core::Image readColour() const;
    /// @brief The last frame's regions (0 background, 1 direct, 2 indirect), row 0 at the top.
    std::vector<std::uint8_t> readRegion() const;
    int width() const { return mWidth; }
    int height() const { return mHeight; }

private:
    void resizeTarget(int width, int height);

    GlProgram mMeshProgram;
    GlProgram mIndirectProgram;
    GlVertexArray mMeshVao;
    GlVertexArray mEmptyVao;
    GlBuffer mPositions;  ///< vec4(position, scalar)
    GlBuffer mNormals;    ///< vec4(normal, NaN flag)
    GlBuffer mIndices;    ///< 3 uint per triangle
    GlTexture mFar;
    GlTexture mBand;
    GlTexture mTriangles;
    GlTexture mColormap;
    GlFramebuffer mTarget;
    GlTexture mColourTexture;
    GlTexture mRegionTexture;
    GlRenderbuffer mDepth;
    const core::SurfaceField* mField = nullptr;
    GLsizei mIndexCount = 0;
    bool mHasVolume = false;
    float mFineVoxelSize = 0.0f;
    float mReach = 0.0f;
    float mTextureVoxelSize = 0.0f;
    int mWidth = 0;
    int mHeight = 0;
};

}  // namespace ivis::app
