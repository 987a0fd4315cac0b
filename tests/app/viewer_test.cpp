// inversevis-view as a user runs it: the interactive window's readable rule, its panel, playing a
// series, the optimisers, view files, probes and the CPU tracer.
#include "viewer_run.h"
#include "vtk_files.h"

#include <ivis/core/camera.h>
#include <ivis/core/content_hash.h>
#include <ivis/core/image.h>
#include <ivis/core/image_io.h>
#include <ivis/core/surface_source.h>
#include <ivis/render/framing.h>
#include <ivis/render/method_registry.h>
#include <ivis/render/renderer.h>
#include <ivis/render/screen_map.h>
#include <ivis/vdb/volume_cache.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace ivis::test {

// The interactive window draws the wrap with the readable rule `render` would choose for a 1000 x
// 1000 picture, found on the CPU once the volume is loaded; a rule given is drawn as given.
TEST_F(Viewer, InteractiveWindowDrawsTheWrapsReadableRule)
{
    TempDir dir;
    const std::string common = "scene:vessel-tree --volume-res 64 --width 300 --height 300 --frames 2 --cache-dir '" +
                               dir.path() + "' --ui-screenshot '" + dir.file("window.png") + "'";
    const RunResult chosen = runViewer(common, true, dir);
    ASSERT_EQ(chosen.status, 0) << chosen.output;
    const double shift = readableShift(chosen.output);
    EXPECT_GT(shift, 0.0) << "a rule chosen: " << chosen.output;
    const nlohmann::json drawn = drawnParameters(chosen.output);
    ASSERT_FALSE(drawn.is_null()) << chosen.output;
    EXPECT_NEAR(drawn.at("stable_shift").get<double>(), shift, 1e-4) << "the picture is drawn with the chosen rule";

    const RunResult given = runViewer(common + " --stable-shift 0.005", true, dir);
    ASSERT_EQ(given.status, 0) << given.output;
    EXPECT_EQ(given.output.find("readable rule"), std::string::npos) << given.output;
}

// The panel leaves the picture most of the window: its sections fold what is seldom changed (the
// tracing accuracy, the picture's settings), and the picture lies right of it. The panel used to
// cover 46% of a 1000 x 800 window (485 x 760), over the picture's left part.
TEST_F(Viewer, PanelLeavesThePictureMostOfTheWindow)
{
    TempDir dir;
    const RunResult run = runViewer("scene:vessel-tree --volume-res 64 --width 1000 --height 800 --frames 2 --cache-dir '" +
                                        dir.path() + "' --ui-screenshot '" + dir.file("window.png") + "'",
                                    true, dir);
    ASSERT_EQ(run.status, 0) << run.output;
    const std::size_t at = run.output.find(", panel ");
    ASSERT_NE(at, std::string::npos) << run.output;
    int width = 0, height = 0, pictureWidth = 0, pictureHeight = 0, pictureX = -1;
    ASSERT_EQ(std::sscanf(run.output.c_str() + at, ", panel %dx%d, picture %dx%d from x %d", &width, &height,
                          &pictureWidth, &pictureHeight, &pictureX),
              5)
        << run.output;
    std::cout << "[ viewer   ] panel " << width << " x " << height << ", picture " << pictureWidth << " x "
              << pictureHeight << " from x " << pictureX << " of a 1000 x 800 window\n";
    EXPECT_GT(width * height, 0);
    EXPECT_LE(width, 320) << "a third of the window's width at most";
    EXPECT_LT(double(width) * height, 0.25 * 1000.0 * 800.0) << "a quarter of the window at most";
    EXPECT_GE(pictureX, width) << "the picture lies right of the panel, not under it";
    EXPECT_EQ(pictureHeight, 800);
    EXPECT_GE(pictureWidth, 500) << "what the panel and the colour bar leave";
}

// --play (the panel's play button) shows the series' steps one after the other, from the first to
// the last, and stops there: --ui-screenshot waits for it. A step of other geometry keeps the next
// waiting until its volume is loaded. One surface has nothing to play.
TEST_F(Viewer, PlayShowsEveryStepInTurnAndStopsAtTheLast)
{
    TempDir dir;
    auto play = [&](const std::string& series) {
        return runViewer("'" + series + "' --volume-res 64 --stable-shift 0.2 --play --play-rate 30 --frames 2 " +
                             "--cache-dir '" + dir.path() + "' --ui-screenshot '" + dir.file("window.png") + "'",
                         true, dir);
    };
    // True when each of the lines appears in the output after the one before.
    auto inTurn = [](const std::string& output, const std::vector<std::string>& lines) {
        std::size_t at = 0;
        for (const std::string& line : lines) {
            at = output.find(line, at);
            if (at == std::string::npos) return false;
            ++at;
        }
        return true;
    };
    const RunResult same = play(sharedMesh("vtk/artery_series/artery.pvd"));
    ASSERT_EQ(same.status, 0) << same.output;
    EXPECT_TRUE(inTurn(same.output, {"step 2/5 ", "step 3/5 ", "step 4/5 ", "step 5/5 ", "wrote " + dir.file("window.png")}))
        << "every step in turn, the screenshot after the last\n" << same.output;

    const RunResult mixed = play(writeMixedSeries(dir));
    ASSERT_EQ(mixed.status, 0) << mixed.output;
    EXPECT_TRUE(inTurn(mixed.output, {"step 2/3 (tet.vtp): other geometry", "inversevis-view: volume ",
                                      "step 3/3 (artery_t0400.vtp): other geometry", "inversevis-view: volume ",
                                      "wrote " + dir.file("window.png")}))
        << "each step's volume loaded before the next step\n" << mixed.output;

    const RunResult one = runViewer("scene:sphere --play --ui-screenshot '" + dir.file("one.png") + "'", false, dir);
    EXPECT_EQ(one.status, 2) << one.output;
    EXPECT_NE(one.output.find("--play: scene:sphere is one surface, not a time series"), std::string::npos) << one.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("one.png")));
}

// "optimise view" leaves the picture drawn with every parameter of the best view: the optimised
// speed and the rule its readable rule chose (the rule used to be dropped, and the speed with it).
TEST_F(Viewer, OptimiseViewDrawsTheBestViewsRule)
{
    TempDir dir;
    const RunResult run = runViewer("scene:vessel-tree --volume-res 64 --width 300 --height 300 --frames 2 --optimize view "
                                    "--steps 1 --finalists 0 --opt-res 24 --cache-dir '" + dir.path() +
                                        "' --ui-screenshot '" + dir.file("window.png") + "'",
                                    true, dir);
    ASSERT_EQ(run.status, 0) << run.output;
    ASSERT_NE(run.output.find("annealed view:"), std::string::npos) << run.output;
    const double shift = readableShift(run.output);
    EXPECT_GT(shift, 0.0) << "a rule chosen: " << run.output;
    const nlohmann::json drawn = drawnParameters(run.output);
    ASSERT_FALSE(drawn.is_null()) << run.output;
    EXPECT_NEAR(drawn.at("stable_shift").get<double>(), shift, 1e-4);
}

// --views 2: 'optimise view' also chooses a second view and says what the two show together.
TEST_F(Viewer, OptimiseViewWithViewsChoosesASecondView)
{
    TempDir dir;
    const RunResult run = runViewer("scene:vessel-tree --volume-res 64 --width 300 --height 300 --frames 2 --optimize view "
                                    "--views 2 --steps 1 --finalists 0 --opt-res 24 --cache-dir '" + dir.path() +
                                        "' --ui-screenshot '" + dir.file("window.png") + "'",
                                    true, dir);
    ASSERT_EQ(run.status, 0) << run.output;
    const std::size_t at = run.output.find("2 views together show ");
    ASSERT_NE(at, std::string::npos) << run.output;
    const double together = std::stod(run.output.substr(at + 22));
    const std::size_t each = run.output.find("(each ", at);
    ASSERT_NE(each, std::string::npos) << run.output;
    const double best = std::stod(run.output.substr(each + 6));
    EXPECT_GT(together, best) << run.output;
    EXPECT_LE(together, 1.0);
}

// A view file (here render's --view-out, with a log scale, an inverted map and hot spots) shows the
// same picture in the viewer as in `render --view`.
TEST_F(Viewer, ViewFileShowsTheCpuPicture)
{
    TempDir dir;
    const std::string cache = " --volume-res 100 --cache-dir '" + dir.path() + "'";
    const CliResult made = runCli("render scene:vessel-tree --hotspots 2 --theta 60 --phi 40 --res 256x256 --colormap plasma "
                                  "--log --invert" + cache + " -o '" + dir.file("first.png") + "' --view-out '" +
                                  dir.file("v.json") + "'");
    ASSERT_EQ(made.status, 0) << made.err;
    const CliResult cpu = runCli("render scene:vessel-tree --view '" + dir.file("v.json") + "' --no-legend" + cache +
                                 " -o '" + dir.file("cpu.png") + "' --exr '" + dir.file("cpu.exr") + "'");
    ASSERT_EQ(cpu.status, 0) << cpu.err;
    // The screenshot takes the view's size (256 x 256), as render --view does.
    const RunResult run = runViewer("scene:vessel-tree --view '" + dir.file("v.json") + "' --frames 2 "
                                    "--no-legend --screenshot '" + dir.file("gpu.png") + "' --region-png '" +
                                        dir.file("gpu-region.png") + "'" + cache,
                                    true, dir);
    ASSERT_EQ(run.status, 0) << run.output;
    const core::Image screenshot = core::readPng(dir.file("gpu.png"));
    ASSERT_EQ(std::make_pair(screenshot.width(), screenshot.height()), std::make_pair(256, 256));
    const Agreement a = agreement(core::readPng(dir.file("cpu.png")), core::readExrChannel(dir.file("cpu.exr"), "region"),
                                  core::readPng(dir.file("gpu.png")), core::readPng(dir.file("gpu-region.png")));
    std::cout << "[ viewer   ] view file: regions agree on " << 100.0 * a.regionAgreement << "% of pixels; mean colour "
              << "difference " << a.indirectMeanDiff << " (indirect), " << a.directMeanDiff << " (direct) 8-bit levels\n";
    EXPECT_GT(a.regionAgreement, 0.995);
    EXPECT_GT(a.cpuIndirect, 1000u);
    EXPECT_LT(a.indirectMeanDiff, 2.0);
    EXPECT_LT(a.directMeanDiff, 1.0);
}

// --probe tells of a pixel of the viewer's picture what `render --probe` tells of the same pixel
// of the same view (an indirect one, so the curved ray is traced on the viewer's camera): headless
// after the screenshot, and in the window as a click would.
TEST_F(Viewer, ProbeTellsWhatRenderTellsOfThePixel)
{
    TempDir dir;
    const std::string view = " --theta 60 --phi 40 --stable-shift 0.04 --no-legend --volume-res 64 --cache-dir '" +
                             dir.path() + "'";
    const CliResult cpu = runCli("render scene:vessel-tree --res 160x160" + view + " -o '" + dir.file("cpu.png") +
                                 "' --exr '" + dir.file("cpu.exr") + "'");
    ASSERT_EQ(cpu.status, 0) << cpu.err;
    const std::vector<float> region = core::readExrChannel(dir.file("cpu.exr"), "region");
    int x = 0;
    while (x < 160 && region[80u * 160u + std::size_t(x)] != 2.0f) ++x;
    ASSERT_LT(x, 160) << "an indirect pixel in the middle row";
    const std::string probe = " --probe " + std::to_string(x) + ",80";
    const CliResult told = runCli("render scene:vessel-tree --res 160x160" + view + probe + " -o '" +
                                  dir.file("cpu.png") + "'");
    ASSERT_EQ(told.status, 0) << told.err;
    ASSERT_EQ(told.out.rfind("pixel " + std::to_string(x) + ",80: indirect, wss ", 0), 0u) << told.out;

    const RunResult headless = runViewer("scene:vessel-tree --width 160 --height 160 --frames 1" + view + probe +
                                             " --screenshot '" + dir.file("gpu.png") + "'",
                                         true, dir);
    ASSERT_EQ(headless.status, 0) << headless.output;
    EXPECT_NE(headless.output.find("inversevis-view: " + told.out), std::string::npos) << headless.output;
    const RunResult window = runViewer("scene:vessel-tree --width 160 --height 160 --frames 1" + view + probe +
                                           " --ui-screenshot '" + dir.file("window.png") + "'",
                                       true, dir);
    ASSERT_EQ(window.status, 0) << window.output;
    EXPECT_NE(window.output.find("inversevis-view: " + told.out), std::string::npos) << window.output;
}


// --tracer cpu: the window shows the picture `render` writes, pixel for pixel and region for
// region; its benchmark draws smaller pictures while the camera moves, then the full one.
TEST_F(Viewer, CpuTracerShowsRendersPicture)
{
    TempDir dir;
    const std::string view = " --theta 60 --phi 40 --min-coherence 0 --no-legend --volume-res 64 --cache-dir '" +
                             dir.path() + "'";
    const CliResult cpu = runCli("render scene:vessel-tree --res 200x150" + view + " -o '" + dir.file("cpu.png") +
                                 "' --exr '" + dir.file("cpu.exr") + "'");
    ASSERT_EQ(cpu.status, 0) << cpu.err;
    const RunResult run = runViewer("scene:vessel-tree --width 200 --height 150 --frames 1 --tracer cpu" + view +
                                        " --screenshot '" + dir.file("view.png") + "' --region-png '" +
                                        dir.file("view-region.png") + "'",
                                    true, dir);
    ASSERT_EQ(run.status, 0) << run.output;
    const core::Image rendered = core::readPng(dir.file("cpu.png")), shown = core::readPng(dir.file("view.png"));
    const std::vector<float> region = core::readExrChannel(dir.file("cpu.exr"), "region");
    const core::Image shownRegion = core::readPng(dir.file("view-region.png"));
    ASSERT_EQ(shown.width(), 200);
    ASSERT_EQ(shown.height(), 150);
    std::size_t differing = 0, indirect = 0;
    for (int y = 0; y < 150; ++y)
        for (int x = 0; x < 200; ++x) {
            for (int c = 0; c < 3; ++c) differing += level(rendered.at(x, y)[c]) != level(shown.at(x, y)[c]);
            const int r = int(region[std::size_t(y) * 200 + std::size_t(x)]);
            differing += r != regionOfGrey(shownRegion.at(x, y).r);
            indirect += r == 2;
        }
    EXPECT_EQ(differing, 0u);
    EXPECT_GT(indirect, 1000u);

    const RunResult bench = runViewer("scene:vessel-tree --width 400 --height 300 --benchmark --benchmark-frames 8 "
                                      "--tracer cpu --volume-res 64 --cache-dir '" + dir.path() + "'",
                                      true, dir);
    ASSERT_EQ(bench.status, 0) << bench.output;
    const std::string tag = "traced by the CPU: moving ";
    const std::size_t at = bench.output.find(tag);
    ASSERT_NE(at, std::string::npos) << bench.output;
    int tracedWidth = 0, tracedHeight = 0;
    const std::size_t size = bench.output.find("mean traced size ", at);
    ASSERT_NE(size, std::string::npos) << bench.output;
    ASSERT_EQ(std::sscanf(bench.output.c_str() + size, "mean traced size %dx%d", &tracedWidth, &tracedHeight), 2);
    EXPECT_LT(tracedWidth, 400) << bench.output;
    EXPECT_NEAR(double(tracedWidth) / tracedHeight, 4.0 / 3.0, 0.1) << bench.output;
    EXPECT_NE(bench.output.find("at rest the full 400x300 picture in "), std::string::npos) << bench.output;
}

}  // namespace ivis::test
