// `inversevis-bench sdf`: the full volume build (band distance + triangle IDs + gradients + far
// field) against OpenVDB's bare meshToVolume (3-voxel band each side, polygon-index grid), each in
// its own child process so that time and peak memory belong to it alone.
#include "benchmarks.h"
#include "child_measurement.h"

#include <ivis/core/surface_source.h>
#include <ivis/vdb/surface_volume.h>

#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>

namespace ivis::bench {

Benchmark addSdfBenchmark(CLI::App& app)
{
    struct Options {
        std::string mesh;
        int resolution = 1000;
        bool json = false;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand("sdf", "Full volume build vs OpenVDB's bare conversion");
    command->add_option("mesh", options->mesh, "Mesh file or scene:<name>")->required();
    command->add_option("--volume-res", options->resolution, "Volume resolution: voxels across [-2.5,2.5]")->capture_default_str();
    command->add_flag("--json", options->json, "Print one JSON object");

    return {command, [options] {
        const core::SurfaceField field = core::loadSurface(options->mesh);
        vdb::VolumeOptions volumeOptions;
        volumeOptions.resolution = options->resolution;
        vdb::validate(volumeOptions);
        const bool isUnsigned = vdb::usesUnsignedDistance(field.mesh, volumeOptions.sign);

        const Measurement reference = measureInChild("openvdb reference", [&] {
            openvdb::Int32Grid index(openvdb::Int32(-1));
            auto grid = vdb::meshToNarrowBand(field.mesh, options->resolution, 3.0f, 3.0f, isUnsigned, nullptr, &index);
            return double(grid->activeVoxelCount());
        });
        const Measurement ours = measureInChild("full build", [&] {
            const vdb::SurfaceVolume volume = vdb::buildSurfaceVolume(field.mesh, volumeOptions);
            return double(volume.activeVoxels());
        });
        const nlohmann::json out = {
            {"mesh", options->mesh},
            {"resolution", options->resolution},
            {"triangles", field.mesh.triangles.size()},
            {"ours_seconds", ours.seconds},
            {"openvdb_seconds", reference.seconds},
            {"ratio", ours.seconds / reference.seconds},
            {"peak_rss_bytes", ours.peakRssBytes},
            {"openvdb_peak_rss_bytes", reference.peakRssBytes},
            {"active_voxels", std::size_t(ours.value)},
            {"openvdb_active_voxels", std::size_t(reference.value)}};
        if (options->json) {
            std::cout << out.dump() << "\n";
            return;
        }
        std::cout << "N=" << options->resolution << "  ours " << ours.seconds << " s (" << (ours.peakRssBytes >> 20)
                  << " MiB peak)  openvdb " << reference.seconds << " s (" << (reference.peakRssBytes >> 20)
                  << " MiB peak)  ratio " << ours.seconds / reference.seconds << "\n";
    }};
}

}  // namespace ivis::bench
