// The colour scale and colour bar flags of `inversevis render`.
#include "cli_fixture.h"

#include <ivis/core/image_io.h>

#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>

namespace ivis::app {
namespace {

/// The artery of ../shared/meshes, looked up when a test runs (a missing file fails that test only).
std::string artery() { return test::sharedMesh("vampy_artery_cfd_pressure.ply"); }

std::string fileText(const std::string& path)
{
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST_F(Cli, ContradictoryScaleFlagsAreRejectedBeforeTheMeshIsRead)
{
    expectRejected(render(artery(), "--log --symmetric"), {"--log and --symmetric exclude each other"});
    expectRejected(render(artery(), "--range 0 1 --range-percentile 1 99"),
                   {"--range and --range-percentile exclude each other"});
    expectRejected(render(artery(), "--range-percentile 99 1"), {"--range-percentile [99, 1]"});
    expectRejected(render(artery(), "--log --range 0 1"), {"--log needs a positive range"});
    expectRejected(render(artery(), "--legend top"), {"unknown colour-bar side 'top'"});
    expectRejected(renderLegendOnly(artery(), output("bar.pdf")), {"bar.pdf", ".svg or .png"});
}

TEST_F(Cli, LegendOnlyWritesTheBarAloneAsSvgOrPng)
{
    const std::string svg = output("bar.svg");
    const test::CliResult vector = test::runCli(renderLegendOnly(artery(), svg, "--units 'dyn/cm²'"));
    ASSERT_EQ(vector.status, 0) << vector.err;
    const std::string text = fileText(svg);
    EXPECT_NE(text.find("<linearGradient"), std::string::npos);
    EXPECT_NE(text.find("[dyn/cm²]"), std::string::npos);

    const std::string png = output("bar.png");
    const test::CliResult raster = test::runCli("render " + quoted(artery()) + " --res 400x300 --legend bottom --legend-only " + quoted(png));
    ASSERT_EQ(raster.status, 0) << raster.err;
    const core::Image bar = core::readPng(png);
    EXPECT_EQ(bar.width(), 400);     // below a 400-pixel-wide picture
    EXPECT_LT(bar.height(), 150);
    EXPECT_EQ(contents(mOutputs.path()), (std::vector<std::string>{"bar.png", "bar.svg"}));  // nothing else, no volume
    // The extension in any case, as the mesh readers take it (.SVG was accepted, then refused after the read).
    const test::CliResult upper = test::runCli(renderLegendOnly(artery(), output("BAR.SVG")));
    ASSERT_EQ(upper.status, 0) << upper.err;
    EXPECT_NE(fileText(output("BAR.SVG")).find("<linearGradient"), std::string::npos);
}

TEST_F(Cli, TheColourBarWidensThePngButNotTheExr)
{
    const test::CliResult result =
        test::runCli(render(artery(), "--log --invert --legend left --exr " + quoted(output("x.exr"))));
    ASSERT_EQ(result.status, 0) << result.err;
    const core::Image png = core::readPng(output("x.png"));
    EXPECT_GT(png.width(), 32);
    EXPECT_EQ(core::readExrChannel(output("x.exr"), "region").size(), 32u * 32u);
}

}  // namespace
}  // namespace ivis::app
