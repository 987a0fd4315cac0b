// One optimisation for a time series: the scalar energy of the mean importance field is the mean
// of the steps' scalar energies, view by view and method by method (the artery's five steps).
#include "test_support.h"
#include "vtk_files.h"

#include <ivis/core/errors.h>
#include <ivis/optimize/curved_ray_gradient.h>
#include <ivis/optimize/energy.h>
#include <ivis/optimize/series_importance.h>
#include <ivis/render/method_registry.h>
#include <ivis/vdb/surface_volume.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace ivis::optimize {
namespace {

core::SurfaceLoadOptions arteryPattern()
{
    core::SurfaceLoadOptions options;
    options.read.scalarName = "pressure_t*";
    return options;
}

EnergyOptions scalarEnergy(const core::ScalarRange& range)
{
    EnergyOptions options;
    options.kind = EnergyKind::Scalar;
    options.resolution = 64;
    options.importanceRange = range;
    return options;
}

TEST(SeriesImportance, MeanFieldEnergyIsTheMeanOfTheStepsEnergies)
{
    core::SurfaceSeries series({test::sharedMesh("vampy_artery_cfd_pressure.ply")}, arteryPattern());
    const std::size_t count = series.steps().size();
    ASSERT_EQ(count, 5u);
    std::vector<core::SurfaceField> steps;
    std::vector<float> all;
    for (std::size_t k = 0; k < count; ++k) {
        steps.push_back(series.load(k));
        all.insert(all.end(), steps.back().values.begin(), steps.back().values.end());
    }
    const core::ScalarRange range = core::scalarRangeFromData(all);
    const core::SurfaceField mean = meanImportanceField(series, range);
    EXPECT_EQ(mean.name, "mean importance of 5 steps");
    EXPECT_EQ(mean.mesh.positions, steps[0].mesh.positions);

    vdb::VolumeOptions volumeOptions;
    volumeOptions.resolution = 64;
    const vdb::SurfaceVolume volume = vdb::buildSurfaceVolume(mean.mesh, volumeOptions);
    const render::RenderScene meanScene(mean, volume);
    const EnergyEvaluator meanEnergy(meanScene, scalarEnergy({0.0f, 1.0f}));
    for (const auto& [theta, phi, method] : {std::tuple{90.0, 0.0, "inversevis"}, std::tuple{40.0, 120.0, "inversevis"},
                                             std::tuple{120.0, 250.0, "neugebauer"}}) {
        SCOPED_TRACE(std::string(method) + " theta " + std::to_string(theta) + " phi " + std::to_string(phi));
        const core::Camera camera = core::Camera::fromAngles(theta, phi);
        const render::MethodPtr m = render::makeMethod(method);
        double sum = 0.0, first = 0.0;
        std::vector<double> gradients(1, 0.0);
        for (std::size_t k = 0; k < count; ++k) {
            const render::RenderScene scene(steps[k], volume);
            const EnergyEvaluator stepEnergy(scene, scalarEnergy(range));
            const double e = stepEnergy.evaluate(camera, m).energy;
            if (k == 0) first = e;
            sum += e;
            if (std::string(method) == "inversevis") gradients[0] += curvedRayGradient(stepEnergy, camera, m)[0];
        }
        const double meanValue = meanEnergy.evaluate(camera, m).energy;
        EXPECT_NEAR(meanValue, sum / double(count), 1e-5 * sum);
        EXPECT_GT(std::abs(first - sum / double(count)), 0.05 * sum / double(count))
            << "the steps' energies differ, so the mean is observable";
        if (std::string(method) == "inversevis") {
            const double meanGradient = curvedRayGradient(meanEnergy, camera, m)[0];
            EXPECT_NEAR(meanGradient, gradients[0] / double(count), 1e-4 * std::abs(gradients[0]) + 1e-9);
        }
    }
}

TEST(SeriesImportance, OtherGeometryIsRejectedNamingTheStep)
{
    test::TempDir dir;
    test::VtkDataSet tet;
    tet.points = {33, 31, 41, 34, 31, 41, 33, 32, 41, 33, 31, 42};  // inside the artery's frame
    tet.polys.connectivity = {0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2};
    tet.polys.offsets = {3, 6, 9, 12};
    tet.pointData = {{"pressure", "Float32", 1, {0.1, 0.2, 0.3, 0.4}}};
    test::VtkXmlLayout layout;
    layout.format = test::VtkXmlLayout::Ascii;
    test::writeFile(dir.file("tet.vtp"), test::vtpText(tet, layout));
    core::SurfaceLoadOptions options;
    options.read.scalarName = "pressure";
    core::SurfaceSeries series({test::sharedMesh("vtk/artery_series/artery_t0200.vtp"), dir.file("tet.vtp")}, options);
    try {
        meanImportanceField(series, {0.0f, 1.0f});
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(dir.file("tet.vtp") + ": step 1 (tet.vtp) has other geometry", 0), 0u)
            << e.what();
    }
}

}  // namespace
}  // namespace ivis::optimize
