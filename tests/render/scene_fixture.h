/// @file scene_fixture.h
/// @brief A generated surface with its volume and render scene, built once per test process (its
///        volume once per build tree, then loaded from the build tree's fixture cache).
#pragma once

#include <ivis/core/content_hash.h>
#include <ivis/core/procedural_scenes.h>
#include <ivis/render/method_registry.h>
#include <ivis/render/render_scene.h>
#include <ivis/vdb/surface_volume.h>
#include <ivis/vdb/volume_cache.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace ivis::test {

/// @brief Field + volume + scene, owned together (the scene refers to the other two).
struct SceneFixture {
    core::SurfaceField field;
    vdb::SurfaceVolume volume;
    std::unique_ptr<render::RenderScene> scene;

    /// @brief Builds the volume at @a resolution (its far field at @a farFieldResolution, reaching as
    ///        far as every method's rays need with its defaults, as the programs' volumes do) and the scene.
    SceneFixture(core::SurfaceField surface, int resolution, int farFieldResolution = vdb::VolumeOptions{}.farFieldResolution)
        : field(std::move(surface))
    {
        vdb::VolumeOptions options;
        options.resolution = resolution;
        options.farFieldResolution = farFieldResolution;
        std::vector<render::MethodPtr> methods;
        for (const render::MethodInfo* info : render::methodRegistry()) methods.push_back(render::makeMethod(info->name));
        options.farFieldReach = render::reachNeededBy(methods, options.farFieldReach);
        // Every test runs in a process of its own (gtest_discover_tests): the first to need a
        // fixture builds it into the build tree's cache, the others load it (vdb/volume_cache.h).
        const std::filesystem::path folder = IVIS_FIXTURE_CACHE_DIR;
        std::filesystem::create_directories(folder);
        const std::string path = (folder / (core::toHex(core::meshHash(field.mesh)) + ".res" + std::to_string(resolution) +
                                            ".far" + std::to_string(farFieldResolution) + ".vdb")).string();
        volume = vdb::loadOrBuildVolume(field.mesh, options, path);
        scene = std::make_unique<render::RenderScene>(field, volume);
    }
};

/// @brief Unit sphere (subdivision 4) at volume resolution 200, shared by the tests.
inline const SceneFixture& sphereScene()
{
    static const SceneFixture fixture(core::makeSphere(4), 200);
    return fixture;
}

/// @brief Unit sphere (subdivision 4) at volume resolution 100 (fine voxel 0.05) with a coarse far
///        field at 40 (voxel 0.125): both grids serve samples.
inline const SceneFixture& sphereWithFarField()
{
    static const SceneFixture fixture(core::makeSphere(4), 100, 40);
    return fixture;
}

/// @brief Generated vessel tree at volume resolution 160, shared by the tests.
inline const SceneFixture& vesselScene()
{
    static const SceneFixture fixture(core::makeVesselTree(), 160);
    return fixture;
}

}  // namespace ivis::test
