// The measures of a picture from its own layers equal the evaluator's energy of the same view at
// the same pixels: the default picture gives the very same figures (the evaluator maps the wrap's
// pixels adaptively, as the picture does), the full trace's the same to a voxel or so.
#include "render/scene_fixture.h"

#include <ivis/core/errors.h>
#include <ivis/optimize/energy.h>
#include <ivis/optimize/picture_measure.h>
#include <ivis/render/method_registry.h>
#include <ivis/render/renderer.h>

#include <gtest/gtest.h>

namespace ivis::optimize {
namespace {

TEST(PictureMeasure, ThePictureMeasuresAsTheEvaluatorMapsIt)
{
    const auto& fixture = test::vesselScene();
    EnergyOptions options;
    options.kind = EnergyKind::Visibility;
    options.resolution = 240;
    options.paperLiteral = true;
    options.reveal = true;
    options.importanceRange = core::scalarRangeFromData(fixture.field.values);
    const EnergyEvaluator evaluator(*fixture.scene, options);
    for (const char* name : {"inversevis-wrap", "inversevis", "mirror"}) {
        SCOPED_TRACE(name);
        const render::MethodPtr method = render::makeMethod(name);
        const core::Camera camera = core::Camera::fromAngles(70.0, 30.0);
        render::RenderOptions look;
        look.width = look.height = options.resolution;
        look.method = method;
        look.legend = false;
        // The default picture: the wrap's pixels sampled adaptively, as the evaluator maps them
        // (ViewSamples), every other method's pixels each traced alone.
        const render::RenderResult picture = render::renderImage(*fixture.scene, camera, look);
        const EnergyValue traced = evaluator.evaluate(camera, method);
        const EnergyValue measured = measurePicture(evaluator, picture.layers);
        EXPECT_GT(traced.pixelsIndirect, 1000u);
        EXPECT_EQ(measured.pixelsDirect, traced.pixelsDirect);
        EXPECT_EQ(measured.pixelsIndirect, traced.pixelsIndirect);
        EXPECT_DOUBLE_EQ(measured.energy, traced.energy);
        EXPECT_DOUBLE_EQ(measured.front, traced.front);
        EXPECT_DOUBLE_EQ(measured.paperLiteral, traced.paperLiteral);
        EXPECT_DOUBLE_EQ(measured.reveal.total, traced.reveal.total);
        EXPECT_EQ(measured.seenVoxels, traced.seenVoxels);

        look.adaptive.enabled = false;  // every pixel's own trace: its landings within a tenth of a voxel
        const EnergyValue full = measurePicture(evaluator, render::renderImage(*fixture.scene, camera, look).layers);
        EXPECT_NEAR(full.energy, traced.energy, 2.0 / double(evaluator.surfaceVoxels()->count()));
    }
}

TEST(PictureMeasure, TheScalarEnergyIsRefused)
{
    const auto& fixture = test::vesselScene();
    EnergyOptions options;
    options.kind = EnergyKind::Scalar;
    options.importanceRange = core::scalarRangeFromData(fixture.field.values);
    const EnergyEvaluator evaluator(*fixture.scene, options);
    EXPECT_THROW(measurePicture(evaluator, core::ImageLayers(4, 4)), ValueError);
}

}  // namespace
}  // namespace ivis::optimize
