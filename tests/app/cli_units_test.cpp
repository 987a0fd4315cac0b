// Outputs in the mesh's own units: the EXR's position layer with the normalising transform in its
// header lands on the file's mesh; the camera JSON and `info --json` carry the same transform.
#include "brute_force.h"
#include "cli_fixture.h"

#include <ivis/core/image_io.h>
#include <ivis/core/mesh_reader.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>

namespace ivis::app {
namespace {

TEST_F(Cli, ExrPositionsMapBackOntoTheMeshInItsOwnUnits)
{
    const std::string mesh = test::sharedMesh("vampy_artery_cfd_pressure.ply");
    const test::CliResult result = test::runCli(render(mesh, "--exr " + quoted(output("x.exr"))));
    ASSERT_EQ(result.status, 0) << result.err;
    const core::Similarity units = core::readExrMeshUnits(output("x.exr"));
    EXPECT_GT(std::abs(units.scale - 1.0), 0.1);  // the artery is not in normalised units already

    core::SurfaceField file = core::readMesh(mesh);  // in the file's own coordinates, shifted at most
    for (glm::vec3& p : file.mesh.positions) p = glm::vec3(file.normalization.meshFromNormalized(glm::dvec3(p)));
    const test::BruteForceClosest closest(file.mesh);
    const std::vector<float> region = core::readExrChannel(output("x.exr"), "region");
    const std::vector<float> x = core::readExrChannel(output("x.exr"), "P.X"), y = core::readExrChannel(output("x.exr"), "P.Y"),
                             z = core::readExrChannel(output("x.exr"), "P.Z");
    int checked = 0;
    for (std::size_t i = 0; i < region.size(); ++i) {
        if (region[i] != 1.0f) continue;  // direct pixels: P is the point seen
        const glm::dvec3 p = units.meshFromNormalized(glm::dvec3(x[i], y[i], z[i]));
        EXPECT_LT(std::sqrt(closest.closest(p).distanceSquared), 1e-4 / units.scale) << "pixel " << i;
        ++checked;
    }
    EXPECT_GT(checked, 100);

    const nlohmann::json camera = nlohmann::json::parse(std::ifstream(output("x.png.camera.json")));
    const nlohmann::json info = nlohmann::json::parse(test::runCli("info --json " + quoted(mesh)).out);
    for (const nlohmann::json& recorded : {camera.at("mesh_units"), info.at("mesh_units")}) {
        EXPECT_NEAR(recorded.at("scale").get<double>(), units.scale, 1e-9 * units.scale);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(recorded.at("center")[k].get<double>(), units.center[k], 1e-9);
    }
}

}  // namespace
}  // namespace ivis::app
