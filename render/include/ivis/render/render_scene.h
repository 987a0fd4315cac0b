/// @file render_scene.h
/// @brief Everything the renderer reads about one surface: the normalised field, its volume, the
///        distance sampler and the triangle BVH for straight rays, built once and shared by all threads.
#pragma once

#include <ivis/core/surface_field.h>
#include <ivis/core/triangle_bvh.h>
#include <ivis/render/distance_field.h>
#include <ivis/render/surface_point.h>
#include <ivis/vdb/surface_volume.h>

#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
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
    /// @brief What @a make derives from this scene (a method's own data, such as the wrap's local
    ///        radii), made on first use and kept under @a key; thread-safe (other callers of the
    ///        same key wait while it is made).
    template <class T>
    const T& derived(const std::string& key, const std::function<T(const RenderScene&)>& make) const
    {
        std::shared_ptr<Derived> entry;
        {
            const std::lock_guard<std::mutex> lock(mDerivedMutex);
            std::shared_ptr<Derived>& slot = mDerived[key];
            if (!slot) slot = std::make_shared<Derived>();
            entry = slot;
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
    mutable std::mutex mDerivedMutex;
    mutable std::map<std::string, std::shared_ptr<Derived>> mDerived;
};

}  // namespace ivis::render
