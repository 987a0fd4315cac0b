// View files: optimize writes one for its best view, render --view reproduces the picture.
#include "cli_fixture.h"

#include <ivis/core/image_io.h>

#include <nlohmann/json.hpp>

#include <fstream>

namespace ivis::app {
namespace {

TEST_F(Cli, RenderFromTheOptimisedViewFileReproducesThePicture)
{
    const std::string cache = " --volume-res 48 --cache-dir " + quoted(output(""));
    const test::CliResult optimized =
        test::runCli("optimize scene:vessel-tree --hotspots 2 --opt-res 16 --res 64x48 --steps 3 --method inversevis-wrap "
                     "--colormap magma --invert --range-percentile 5 95 --legend bottom --units 'a.u.'" + cache +
                     " -o " + quoted(output("best.png")));
    ASSERT_EQ(optimized.status, 0) << optimized.err;
    const nlohmann::json view = nlohmann::json::parse(std::ifstream(output("best.png.view.json")));
    EXPECT_EQ(view.at("method").at("method"), "inversevis-wrap");
    EXPECT_EQ(view.at("hotspots"), 2);
    EXPECT_EQ(view.at("colormap"), "magma");
    EXPECT_EQ(view.at("legend"), "bottom");
    EXPECT_EQ(view.at("size"), nlohmann::json::array({64, 48}));

    // Nothing but the mesh and the view file: the same picture, byte for byte after decoding.
    const test::CliResult rendered = test::runCli("render scene:vessel-tree --view " + quoted(output("best.png.view.json")) + cache +
                                            " -o " + quoted(output("again.png")) + " --view-out " + quoted(output("again.json")));
    ASSERT_EQ(rendered.status, 0) << rendered.err;
    const core::Image best = core::readPng(output("best.png")), again = core::readPng(output("again.png"));
    ASSERT_EQ(best.width(), again.width());
    ASSERT_EQ(best.height(), again.height());
    EXPECT_EQ(best.pixels(), again.pixels());
    nlohmann::json written = nlohmann::json::parse(std::ifstream(output("again.json")));
    EXPECT_EQ(written, view);  // the view of the re-rendered picture is the same view

    // A flag given with --view overrides the file.
    const test::CliResult grey = test::runCli("render scene:vessel-tree --view " + quoted(output("best.png.view.json")) + cache +
                                        " --colormap grey -o " + quoted(output("grey.png")));
    ASSERT_EQ(grey.status, 0) << grey.err;
    EXPECT_NE(core::readPng(output("grey.png")).pixels(), best.pixels());
}

TEST_F(Cli, BadViewFilesAreRejectedWithTheirName)
{
    const std::string bad = input("bad.view.json");
    test::writeFile(bad, R"({"inversevis_view": 1, "camera": {"eye": [0, 0, 2.5]}})");
    expectRejected(render("scene:sphere", "--view " + quoted(bad)), {"bad.view.json: bad view file"});
    test::writeFile(bad, R"({"inversevis_view": 7})");
    expectRejected(render("scene:sphere", "--view " + quoted(bad)), {"bad.view.json", "version 7"});
    test::writeFile(bad, "{");
    expectRejected(render("scene:sphere", "--view " + quoted(bad)), {"bad.view.json: bad view file"});
    expectRejected(render("scene:sphere", "--view " + quoted(bad) + " --theta 10"), {"--view"});
}

}  // namespace
}  // namespace ivis::app
