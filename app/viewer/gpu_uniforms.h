/// @file gpu_uniforms.h
/// @brief The uniforms of the viewer's programs: the scene's (mesh and volume, kept in a UniformSet)
///        and the frame's (camera, look and the method's parameters).
/// @note The set* functions need a current OpenGL context; not thread-safe.
#pragma once

#include "dense_slices.h"
#include "gpu_frame.h"
#include "uniform_set.h"

#include <ivis/core/camera.h>
#include <ivis/core/surface_field.h>

#include <string>

namespace ivis::app {

/// @brief Sizes of the uploaded volume the indirect pass's uniforms derive from.
struct VolumeScale {
    float fineVoxelSize = 0.0f;     ///< the volume's own voxel size (the CPU's hull box uses it)
    float reach = 0.0f;             ///< exterior distance up to which phi is exact
};

/// @brief The uniform a method's parameter feeds: "u" and its key in UpperCamelCase
///        (alpha_profile -> uAlphaProfile).
std::string parameterUniform(const std::string& key);

/// @brief Keeps the mesh's uniforms in @a scene: whether it has a scalar, where the hole caps start.
void keepMeshUniforms(UniformSet& scene, const core::SurfaceField& field);

/// @brief Keeps the volume's uniforms in @a scene: box sizes and origins, voxel sizes, sign, and
///        uVolumeReady = true.
/// @param interiorStep largest step trusted where phi < 0 (the interior band width)
/// @param surfaceBox a box around the surface (render::shadowFactor's)
void keepVolumeUniforms(UniformSet& scene, const DenseSlices& slices, float interiorStep,
                        const core::Bounds3& surfaceBox);

/// @brief Sets the mesh pass's per-frame uniforms: look, camera, clip transform, key light, shadows.
void setMeshPassUniforms(GlProgram& program, const GpuFrame& frame, const core::CameraFrame& camera);

/// @brief Sets the indirect pass's per-frame uniforms: look, camera, and every parameter of the
///        frame's method and every value it derives from the view (each method's program reads its own).
/// @param field the surface (ring layout)
/// @param meshBounds the bounds of its mesh (the hull box), kept from one frame to the next
void setIndirectUniforms(GlProgram& program, const GpuFrame& frame, const core::CameraFrame& camera,
                         const core::SurfaceField& field, const core::Bounds3& meshBounds, const VolumeScale& volume);

}  // namespace ivis::app
