/// @file render_scene.h
/// @brief Everything the renderer reads about one surface: the normalised field, its volume, the
///        distance sampler and the triangle BVH for straight rays, built once and shared by all threads.
#pragma once

#include <ivis/core/surface_field.h>
#include <ivis/core/triangle_bvh.h>
#include <ivis/render/distance_field.h>
#include <ivis/render/local_radius.h>
#include <ivis/render/surface_point.h>
#include <ivis/vdb/surface_volume.h>

#include <mutex>
#include <vector>

namespace ivis::render {

/// @brief Immutable scene; @a field and @a volume must outlive it.
class RenderScene {
public:
    /// @brief Builds the distance sampler and the BVH of @a field's mesh.
    RenderScene(const core::SurfaceField& field, const vdb::SurfaceVolume& volume)
        : mField(field), mVolume(volume), mDistance(volume), mBvh(field.mesh), mNormals(vertexNormals(field.mesh))
    {
    }
    const core::SurfaceField& field() const { return mField; }
    const core::TriangleMesh& mesh() const { return mField.mesh; }
    /// @brief The volume it was built from; once built, the scene reads only its triangle grid, so a
    ///        program that renders only may release the rest (vdb::SurfaceVolume::releaseSampledGrids).
    const vdb::SurfaceVolume& volume() const { return mVolume; }
    const DistanceField& distance() const { return mDistance; }
    const core::TriangleBvh& bvh() const { return mBvh; }
    /// @brief Area-weighted vertex normals of the mesh (for smooth shading).
    const std::vector<glm::vec3>& normals() const { return mNormals; }
    /// @brief vertexLocalRadii() of the mesh capped at the normalised half-extent 1, computed on
    ///        first use (thread-safe).
    const std::vector<float>& localRadii() const
    {
        std::call_once(mLocalRadiiOnce, [this] { mLocalRadii = vertexLocalRadii(mesh(), mBvh, mNormals, 1.0f); });
        return mLocalRadii;
    }

private:
    const core::SurfaceField& mField;
    const vdb::SurfaceVolume& mVolume;
    DistanceField mDistance;
    core::TriangleBvh mBvh;
    std::vector<glm::vec3> mNormals;
    mutable std::once_flag mLocalRadiiOnce;
    mutable std::vector<float> mLocalRadii;
};

}  // namespace ivis::render
