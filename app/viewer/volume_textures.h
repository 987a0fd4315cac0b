/// @file volume_textures.h
/// @brief The volume on the GPU: the far, band and closest-triangle boxes of DenseSlices as 3D
///        textures fetched texel by texel (no filtering: the shaders interpolate as the CPU does).
/// @note Needs a current OpenGL 4.3 core context; not thread-safe.
#pragma once

#include "dense_slices.h"
#include "gl_objects.h"

namespace ivis::app {

/// @brief Texture units the shaders read the volume from (layout(binding) in distance_field.glsl).
inline constexpr GLuint kFarUnit = 1, kTriangleUnit = 2, kBandUnit = 4;

/// @brief The three volume textures.
class VolumeTextures {
public:
    /// @brief Creates the (empty) textures.
    VolumeTextures();
    /// @brief Copies the boxes of @a slices into the textures (an empty box becomes one zero texel).
    /// @throw GlError (e.g. GL_OUT_OF_MEMORY)
    void upload(const DenseSlices& slices);
    /// @brief Binds the textures to kFarUnit, kBandUnit and kTriangleUnit (leaves unit 0 active).
    void bind() const;

private:
    GlTexture mFar;
    GlTexture mBand;
    GlTexture mTriangles;
};

}  // namespace ivis::app
