/// @file render_scene.h
/// @brief Everything the renderer reads about one surface: the normalised field, its volume, the
///        distance sampler, the triangle BVH for straight rays, the mesh's bounds and its clustered
///        vertices for framing, built once and shared by all threads.
#pragma once

#include <ivis/core/clustered_vertices.h>
#include <ivis/core/surface_field.h>
#include <ivis/core/triangle_bvh.h>
#include <ivis/render/distance_field.h>
#include <ivis/render/surface_point.h>
#include <ivis/vdb/surface_volume.h>

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

namespace ivis::render {

/// @brief Immutable scene; @a field and @a volume must outlive it.
class RenderScene {
public:
    /// @brief Builds the distance sampler, the BVH and the vertex clusters of @a field's mesh.
    RenderScene(const core::SurfaceField& field, const vdb::SurfaceVolume& volume)
        : mField(field),
          mVolume(volume),
          mDistance(volume),
          mBvh(field.mesh),
          mNormals(vertexNormals(field.mesh)),
          mVertices(field.mesh.positions),
          mBounds(core::bounds(field.mesh))
    {
    }
    /// @brief The mesh with the scalar it shows.
    const core::SurfaceField& field() const { return mField; }
    /// @brief The mesh (normalised units).
    const core::TriangleMesh& mesh() const { return mField.mesh; }
    /// @brief The volume it was built from; once built, the scene reads only its triangle grid, so a
    ///        program that renders only may release the rest (vdb::SurfaceVolume::releaseSampledGrids).
    const vdb::SurfaceVolume& volume() const { return mVolume; }
    /// @brief The volume's distance field, which curved rays and shadows sample.
    const DistanceField& distance() const { return mDistance; }
    /// @brief The mesh's BVH, which straight rays and landings query.
    const core::TriangleBvh& bvh() const { return mBvh; }
    /// @brief The mesh's bounding box.
    const core::Bounds3& bounds() const { return mBounds; }
    /// @brief The mesh's vertices in spatial clusters, which framing scans (offsetMeshExtent).
    const core::ClusteredVertices& vertices() const { return mVertices; }
    /// @brief Area-weighted vertex normals of the mesh (for smooth shading).
    const std::vector<glm::vec3>& normals() const { return mNormals; }
    /// @brief What @a make (a callable taking the scene, returning a T) derives from this scene (a
    ///        method's own data, such as the wrap's local radii), made on first use and kept under
    ///        @a key; thread-safe (other callers of the same key wait while it is made). A lookup
    ///        takes a lock and searches a map: keep it out of a ray's steps.
    template <class T, class Make>
    const T& derived(std::string_view key, Make&& make) const
    {
        Derived* entry = nullptr;
        {
            const std::lock_guard<std::mutex> lock(mDerivedMutex);
            auto it = mDerived.find(key);
            if (it == mDerived.end()) it = mDerived.emplace(std::string(key), std::make_unique<Derived>()).first;
            entry = it->second.get();  // entries are never removed: the pointer stays valid
        }
        std::call_once(entry->once, [&] { entry->value = std::make_shared<const T>(make(*this)); });
        return *static_cast<const T*>(entry->value.get());
    }

private:
    /// One derived value, made once.
    struct Derived {
        std::once_flag once;
        std::shared_ptr<const void> value;
    };

    const core::SurfaceField& mField;
    const vdb::SurfaceVolume& mVolume;
    DistanceField mDistance;
    core::TriangleBvh mBvh;
    std::vector<glm::vec3> mNormals;
    core::ClusteredVertices mVertices;
    core::Bounds3 mBounds;
    mutable std::mutex mDerivedMutex;
    mutable std::map<std::string, std::unique_ptr<Derived>, std::less<>> mDerived;
};

}  // namespace ivis::render
