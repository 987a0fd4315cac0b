/// @file series_scene.h
/// @brief The scene of a time series' current step: its volume is loaded or built once and kept
///        while the geometry stays the same (same core::meshHash), only the scalar changing; a
///        step with other geometry gets a volume of its own (its own cache file).
#pragma once

#include <ivis/core/interrupter.h>
#include <ivis/core/surface_field.h>
#include <ivis/render/render_scene.h>
#include <ivis/vdb/surface_volume.h>

#include <cstdint>
#include <memory>
#include <string>

namespace ivis::app {

/// @brief The current step's field, volume and render scene.
class SeriesScene {
public:
    /// @param cacheFolder folder of the volume caches, named vdb::defaultVolumePath(cacheFolder, @a source, ...)
    /// @param source the source that names the series (core::SurfaceSeries::source)
    SeriesScene(const vdb::VolumeOptions& options, std::string cacheFolder, std::string source);

    /// @brief Shows @a field: when its geometry is the current one, its scalar (and arrays) replace
    ///        the current field's and the volume and scene stay; otherwise its volume is read from
    ///        its cache or built (and cached) and a new scene made.
    /// @return "kept" when the volume stayed, else vdb::toString of the cache outcome ("built", "reused", ...)
    std::string show(core::SurfaceField field, core::Interrupter* interrupter = nullptr);

    /// @brief The scene of the step shown last. Call after show().
    const render::RenderScene& scene() const { return *mScene; }
    /// @brief The field of the step shown last (the scene refers to it).
    const core::SurfaceField& field() const { return *mField; }
    /// @brief The cache file of the current volume.
    const std::string& volumePath() const { return mVolumePath; }
    /// @brief How many volumes show() loaded or built so far (one per change of geometry).
    int volumesLoaded() const { return mVolumesLoaded; }

private:
    vdb::VolumeOptions mOptions;
    std::string mCacheFolder;
    std::string mSource;
    std::uint64_t mMeshHash = 0;
    std::string mVolumePath;
    int mVolumesLoaded = 0;
    // Heap objects: the scene refers to the field and the volume, which keep their addresses.
    std::unique_ptr<core::SurfaceField> mField;
    std::unique_ptr<vdb::SurfaceVolume> mVolume;
    std::unique_ptr<render::RenderScene> mScene;
};

}  // namespace ivis::app
