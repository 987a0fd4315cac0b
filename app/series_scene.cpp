#include "series_scene.h"


#include <ivis/vdb/cache_folder.h>
#include <ivis/core/content_hash.h>
#include <ivis/vdb/volume_cache.h>

namespace ivis::app {

SeriesScene::SeriesScene(const vdb::VolumeOptions& options, std::string cacheFolder, std::string source)
    : mOptions(options), mCacheFolder(std::move(cacheFolder)), mSource(std::move(source))
{
}

std::string SeriesScene::show(core::SurfaceField field, core::Interrupter* interrupter)
{
    const std::uint64_t hash = core::meshHash(field.mesh);
    if (mScene && hash == mMeshHash) {
        // Same geometry: the mesh (which the BVH shares) stays; only what it shows changes.
        core::showStepData(*mField, std::move(field));
        return "kept";
    }
    mScene.reset();
    mField = std::make_unique<core::SurfaceField>(std::move(field));
    mVolumePath = vdb::defaultVolumePath(mCacheFolder, mSource, mField->mesh, mOptions);
    vdb::CacheOutcome outcome{};
    mVolume = std::make_unique<vdb::SurfaceVolume>(
        vdb::loadOrBuildVolume(mField->mesh, mOptions, mVolumePath, interrupter, &outcome));
    mScene = std::make_unique<render::RenderScene>(*mField, *mVolume);
    mVolume->releaseSampledGrids();  // the scene holds its own copies of what it samples
    mMeshHash = hash;
    ++mVolumesLoaded;
    return vdb::toString(outcome);
}

}  // namespace ivis::app
