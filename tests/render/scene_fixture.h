/// @file scene_fixture.h
/// @brief A generated surface with its volume and render scene, built once per test binary run.
#pragma once

#include <ivis/core/procedural_scenes.h>
#include <ivis/render/render_scene.h>
#include <ivis/vdb/surface_volume.h>

#include <memory>
#include <string>

namespace ivis::test {

/// @brief Field + volume + scene, owned together (the scene refers to the other two).
struct SceneFixture {
    core::SurfaceField field;
    vdb::SurfaceVolume volume;
    std::unique_ptr<render::RenderScene> scene;

    /// @brief Builds the volume at @a resolution (its far field at @a farFieldResolution) and the scene.
    SceneFixture(core::SurfaceField surface, int resolution, int farFieldResolution = vdb::VolumeOptions{}.farFieldResolution)
        : field(std::move(surface))
    {
        vdb::VolumeOptions options;
        options.resolution = resolution;
        options.farFieldResolution = farFieldResolution;
        volume = vdb::buildSurfaceVolume(field.mesh, options);
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
