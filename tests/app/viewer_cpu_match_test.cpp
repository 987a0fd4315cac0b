// inversevis-view against the CPU renderer: the same view of the generated vessel tree rendered by
// the viewer's shaders (under Xvfb with Mesa's llvmpipe) and by render::renderImage.
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

// The acceptance test of issue 5. Regions: >= 97% of pixels (the figure; measured 99.999%).
// Colours, as mean |difference| in 8-bit sRGB levels over the pixels both call indirect (or direct):
// the viewer interpolates the same voxels with the same formulas, in float where the CPU mixes
// float and double, so a curved ray may land a hair away from the CPU's, and 8-bit rounding adds
// up to half a level. Measured: 0.14 (indirect) and 0.002 (direct). The bound of 1 level is 7x that
// and still fails for any systematic error: a wrong colour map, light, brightness factor or landing
// rule moves the mean by 10 levels or more.
TEST_F(Viewer, InverseVisMatchesCpuRenderer)
{
    const Agreement a = compareWithCpu("inversevis");
    EXPECT_GE(a.regionAgreement, 0.97);
    EXPECT_GT(a.bothIndirect, std::size_t(10000));
    EXPECT_LT(a.indirectMeanDiff, 1.0);
    EXPECT_LT(a.directMeanDiff, 0.5);
    // The adaptive method: the same curved rays, alpha from the default profile at each seed and a
    // ray that misses relaunched at half its alpha (measured 0.16 levels).
    const Agreement adaptive = compareWithCpu("inversevis-adaptive");
    EXPECT_GE(adaptive.regionAgreement, 0.97);
    EXPECT_GT(adaptive.bothIndirect, std::size_t(10000));
    EXPECT_LT(adaptive.indirectMeanDiff, 1.0);
    EXPECT_LT(adaptive.directMeanDiff, 0.5);
    // The wrapped method: closest-approach seeds, rings sized by the local radius (the viewer finds
    // the closest point from phi and its gradient, the CPU with the BVH) and the stability rule.
    const Agreement wrap = compareWithCpu("inversevis-wrap");
    EXPECT_GE(wrap.regionAgreement, 0.97);
    EXPECT_GT(wrap.bothIndirect, std::size_t(5000));
    EXPECT_LT(wrap.indirectMeanDiff, 1.0);
    EXPECT_LT(wrap.directMeanDiff, 0.5);
}

// --unshaded-indirect draws the indirect part in the colour bar's own colours in the shaders too (it
// was dimmed to 0.75 of them in both).
TEST_F(Viewer, UnshadedIndirectMatchesCpuRenderer)
{
    const Agreement flat = compareWithCpu("inversevis-wrap", 200, "", nullptr, "scene:vessel-tree", {}, false);
    EXPECT_GE(flat.regionAgreement, 0.97);
    EXPECT_GT(flat.bothIndirect, std::size_t(5000));
    EXPECT_LT(flat.indirectMeanDiff, 1.0);
}

TEST_F(Viewer, MirrorAndRingMatchCpuRenderer)
{
    // Mirror: the same sphere tracing as the CPU (measured 0.13 levels). Ring map: the CPU intersects
    // the BVH, the viewer sphere-traces and then intersects the triangles stored around the landing
    // point, so grazing rays may differ (measured 0.9 levels, 99.88% of regions).
    const Agreement mirror = compareWithCpu("mirror");
    EXPECT_GE(mirror.regionAgreement, 0.97);
    EXPECT_GT(mirror.bothIndirect, std::size_t(5000));
    EXPECT_LT(mirror.indirectMeanDiff, 1.0);
    const Agreement ring = compareWithCpu("neugebauer");
    EXPECT_GE(ring.regionAgreement, 0.97);
    EXPECT_GT(ring.bothIndirect, std::size_t(5000));
    EXPECT_LT(ring.indirectMeanDiff, 3.0);
}

// A cell array is one value per triangle in the viewer too (a buffer of triangle values), flat
// as on the CPU: the colours agree as closely as the vertex scalar's (a vertex blend instead, or
// no colour at all, would differ by tens of levels).
TEST_F(Viewer, CellScalarsMatchCpuRenderer)
{
    core::SurfaceLoadOptions load;
    load.read.scalarName = "pressure_cell";
    const Agreement a = compareWithCpu("inversevis", 200, "--scalar pressure_cell", nullptr,
                                       sharedMesh("vtk/artery_series/artery_t0200.vtp"), load);
    EXPECT_GE(a.regionAgreement, 0.97);
    EXPECT_GT(a.bothIndirect, std::size_t(5000));
    EXPECT_LT(a.indirectMeanDiff, 1.0);
    EXPECT_LT(a.directMeanDiff, 0.5);
}

// A volume finer than 200 has a far field: the viewer combines its copy with the fine band as the
// CPU does. With a budget too small for the band at 400 it resamples, and says so.
TEST_F(Viewer, FarFieldAndResampledVolumesMatchCpuRenderer)
{
    std::string output;
    const Agreement exact = compareWithCpu("inversevis", 400, "", &output);
    EXPECT_NE(output.find("resolution 400 (voxel 0.0125), the volume's own, far field at 200"), std::string::npos) << output;
    EXPECT_GE(exact.regionAgreement, 0.97);
    EXPECT_LT(exact.indirectMeanDiff, 1.0);
    // Resampled: the band at a coarser voxel than the CPU's (0.0140 instead of 0.0125); the same
    // regions, colours within a looser bound (measured 1.7 levels).
    const Agreement resampled = compareWithCpu("inversevis", 400, "--texture-budget 48", &output);
    EXPECT_NE(output.find("RESAMPLED from 400"), std::string::npos) << output;
    EXPECT_GE(resampled.regionAgreement, 0.95);
    EXPECT_LT(resampled.indirectMeanDiff, 5.0);
    // The wrap lands its rays within a tenth of the coarse voxel there (its `landing`), on the tree's
    // unsigned field (measured 99.85% of the regions, 3.1 levels).
    const Agreement wrapResampled = compareWithCpu("inversevis-wrap", 400, "--texture-budget 48", &output);
    EXPECT_GE(wrapResampled.regionAgreement, 0.95);
    EXPECT_LT(wrapResampled.indirectMeanDiff, 5.0);
}

// A time series: each step as the time slider shows it (--screenshot writes one per step), on the
// volume loaded once since the geometry stays (the CLI's cache, named by the mesh's hash, is reused),
// with one colour range over all steps: each screenshot agrees with `render`'s frame of its step as
// closely as one picture does (a range of each step's own would move the colours by tens of levels).
TEST_F(Viewer, SeriesStepsShareOneVolumeAndMatchCpuFrames)
{
    TempDir dir;
    const std::string pvd = sharedMesh("vtk/artery_series/artery.pvd");
    // --min-coherence 0: the rule the viewer's --screenshot draws (it chooses none).
    const CliResult cpu = runCli("render '" + pvd + "' --res 256x256 --volume-res 100 --no-legend --no-outline --no-video "
                                 "--min-coherence 0 "
                                 "--cache-dir '" + dir.path() + "' -o '" +
                                 dir.file("cpu.png") + "' --exr '" + dir.file("cpu.exr") + "'");
    ASSERT_EQ(cpu.status, 0) << cpu.err;
    const RunResult run = runViewer("'" + pvd + "' --width 256 --height 256 --volume-res 100 --frames 2 --no-legend "
                                    "--no-outline --screenshot '" +
                                        dir.file("gpu.png") + "' --region-png '" + dir.file("gpu-region.png") +
                                        "' --cache-dir '" + dir.path() + "'",
                                    true, dir);
    ASSERT_EQ(run.status, 0) << run.output;
    EXPECT_NE(run.output.find(".res100.reach1.vdb (reused"), std::string::npos) << run.output;
    EXPECT_EQ(run.output.find("inversevis-view: volume "), run.output.rfind("inversevis-view: volume ")) << run.output;
    for (int step = 2; step <= 5; ++step)
        EXPECT_NE(run.output.find("step " + std::to_string(step) + "/5 (artery_t"), std::string::npos) << run.output;
    std::size_t kept = 0;
    for (std::size_t at = run.output.find("volume kept"); at != std::string::npos; at = run.output.find("volume kept", at + 1))
        ++kept;
    EXPECT_EQ(kept, 4u) << run.output;
    for (int step = 0; step < 5; ++step) {
        SCOPED_TRACE("step " + std::to_string(step));
        const std::string suffix = "_000" + std::to_string(step);
        const Agreement a = agreement(core::readPng(dir.file("cpu" + suffix + ".png")),
                                      core::readExrChannel(dir.file("cpu" + suffix + ".exr"), "region"),
                                      core::readPng(dir.file("gpu" + suffix + ".png")),
                                      core::readPng(dir.file("gpu-region" + suffix + ".png")));
        std::cout << "[ viewer   ] series step " << step << ": regions agree on " << 100.0 * a.regionAgreement
                  << "% of pixels; mean colour difference " << a.indirectMeanDiff << " (indirect), "
                  << a.directMeanDiff << " (direct) 8-bit levels\n";
        EXPECT_GE(a.regionAgreement, 0.97);
        EXPECT_GT(a.bothIndirect, std::size_t(3000));
        EXPECT_LT(a.indirectMeanDiff, 1.0);
        EXPECT_LT(a.directMeanDiff, 0.5);
    }
}

TEST_F(Viewer, CtrlCDuringASeriesLeavesNoScreenshot)
{
    // Killed by the signal, it left the steps written so far (s_0000.png, s_0001.png). The signal goes
    // to the viewer alone: xvfb-run, signalled too, at times failed its own clean-up (status 5).
    TempDir dir;
    const std::string pvd = sharedMesh("vtk/artery_series/artery.pvd");
    const std::string log = dir.file("viewer.log");
    const std::string script =
        "xvfb-run -a -f '" + dir.file("Xauthority") + "' -s '-screen 0 1280x1024x24' '" + std::string(IVIS_VIEW_PATH) +
        "' '" + pvd +
        "' --width 200 --height 200 --volume-res 64 --frames 20 --cache-dir '" + dir.path() + "' --screenshot '" +
        dir.file("s.png") + "' >'" + log + "' 2>&1 & pid=$!; for i in $(seq 1 1200); do grep -q 'step 2/5' '" + log +
        "' && break; sleep 0.1; done; pkill -INT -f -- '^" + std::string(IVIS_VIEW_PATH) + " .*--cache-dir " + dir.path() +
        "'; wait $pid; echo $? >'" +
        dir.file("status") + "'";
    writeFile(dir.file("run.sh"), script + "\n");
    ASSERT_EQ(std::system(("bash '" + dir.file("run.sh") + "'").c_str()), 0);
    const std::string output = readFile(log);
    ASSERT_NE(output.find("step 2/5"), std::string::npos) << output;
    EXPECT_EQ(readFile(dir.file("status")), "130\n") << output;
    EXPECT_NE(output.find("inversevis-view: interrupted"), std::string::npos) << output;
    // The libraries' notes name the viewer too (the default array's said "inversevis: ").
    EXPECT_NE(output.find("inversevis-view: " + sharedMesh("vtk/artery_series/artery_t0200.vtp") + ": showing"),
              std::string::npos)
        << output;
    for (const auto& entry : std::filesystem::directory_iterator(dir.path()))
        EXPECT_EQ(entry.path().filename().string().find("s_"), std::string::npos) << entry.path() << " left behind";
}

// A series' screenshots with their colour bars are one size, as render's frames are: the bar's
// margin was each step's own, so "t = 1000" made the last one wider than the others.
TEST_F(Viewer, SeriesScreenshotsAreOneSizeAsRendersFrames)
{
    TempDir dir;
    const std::string pvd = sharedMesh("vtk/artery_series/artery.pvd");
    const CliResult cpu = runCli("render '" + pvd + "' --scalar pressure_cell --res 160x160 --volume-res 64 --no-video "
                                 "--method front --cache-dir '" + dir.path() + "' -o '" + dir.file("cpu.png") + "'");
    ASSERT_EQ(cpu.status, 0) << cpu.err;
    const RunResult run = runViewer("'" + pvd + "' --scalar pressure_cell --method front --width 160 --height 160 "
                                    "--volume-res 64 --frames 1 --screenshot '" + dir.file("gpu.png") + "' --cache-dir '" +
                                        dir.path() + "'",
                                    true, dir);
    ASSERT_EQ(run.status, 0) << run.output;
    const int width = core::readPng(dir.file("cpu_0000.png")).width();
    EXPECT_GT(width, 160) << "the bar's margin";
    for (int step = 0; step < 5; ++step) {
        const std::string suffix = "_000" + std::to_string(step) + ".png";
        EXPECT_EQ(core::readPng(dir.file("cpu" + suffix)).width(), width) << step;
        EXPECT_EQ(core::readPng(dir.file("gpu" + suffix)).width(), width) << step;
    }
}

// A step of other geometry: the slider uploads its mesh and loads its volume (the direct part
// shows meanwhile); back on the artery, the artery's cache is read again.
TEST_F(Viewer, SeriesStepOfOtherGeometryLoadsItsVolume)
{
    TempDir dir;
    const RunResult run = runViewer("'" + writeMixedSeries(dir) + "' --width 128 --height 128 --volume-res 64 --frames 1 --no-legend " +
                                        "--screenshot '" + dir.file("gpu.png") + "' --region-png '" +
                                        dir.file("region.png") + "' --cache-dir '" + dir.path() + "'",
                                    true, dir);
    ASSERT_EQ(run.status, 0) << run.output;
    EXPECT_NE(run.output.find("step 2/3 (tet.vtp): other geometry, loading its volume"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("step 3/3 (artery_t0400.vtp): other geometry, loading its volume"), std::string::npos)
        << run.output;
    const std::size_t built = run.output.find("(built"), reused = run.output.find("(reused");
    EXPECT_NE(built, std::string::npos) << run.output;
    EXPECT_NE(run.output.find("(built", built + 1), std::string::npos) << "the tetrahedron's own volume\n" << run.output;
    EXPECT_NE(reused, std::string::npos) << "the artery's volume read back for step 3\n" << run.output;
    // Each step's picture is of its own mesh: the tetrahedron's regions differ from the artery's.
    std::array<std::size_t, 3> direct{};
    for (int step = 0; step < 3; ++step) {
        const core::Image region = core::readPng(dir.file("region_000" + std::to_string(step) + ".png"));
        for (int y = 0; y < region.height(); ++y)
            for (int x = 0; x < region.width(); ++x) direct[std::size_t(step)] += regionOfGrey(region.at(x, y).r) == 1;
    }
    EXPECT_EQ(direct[0], direct[2]);
    EXPECT_NE(direct[0], direct[1]);
}

// The interactive path: the ImGui panel, the background loader, the "optimise alpha" (parameters) button pressed
// by --optimize (optimize::optimizeParameters on a background thread), the animation toward its result
// and the window read back with the panel.
TEST_F(Viewer, PanelRunsTheParameterOptimiser)
{
    TempDir dir;
    const std::string shot = dir.file("window.png");
    const RunResult run = runViewer("scene:sphere --method inversevis --optimize parameters --energy scalar --opt-res 48 --frames 2 --width 640 --height 480 --ui-screenshot '" +
                                        shot + "' --cache-dir '" + dir.path() + "'",
                                    true, dir);
    ASSERT_EQ(run.status, 0) << run.output;
    EXPECT_NE(run.output.find("optimised inversevis: alpha 0.500 -> alpha "), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("scalar energy"), std::string::npos) << run.output;
    const core::Image window = core::readPng(shot);
    EXPECT_EQ(window.width(), 640);
    EXPECT_EQ(window.height(), 480);
}

TEST_F(Viewer, UnreadableMeshExitsWithStatus2)
{
    TempDir dir;
    writeFile(dir.file("broken.obj"), "this is not a mesh\n");
    for (const std::string& mesh : {dir.file("missing.ply"), dir.file("broken.obj")}) {
        const RunResult run = runViewer("'" + mesh + "' --screenshot '" + dir.file("x.png") + "'", false, dir);
        EXPECT_EQ(run.status, 2) << run.output;
        EXPECT_EQ(run.output.rfind("inversevis-view: error: ", 0), 0u) << run.output;
        EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
    }
    // A series with a bad step, or a pattern matching no array: every step is checked before a word.
    // A bad camera file fails before the note naming the file's default array.
    writeFile(dir.file("cam.json"), "{bad");
    writeFile(dir.file("late.pvd"), "<VTKFile type=\"Collection\"><Collection>\n<DataSet file=\"" +
                                        sharedMesh("vtk/artery_series/artery_t0200.vtp") +
                                        "\"/>\n<DataSet file=\"broken.obj\"/>\n</Collection></VTKFile>\n");
    for (const std::string& arguments :
         {"'" + dir.file("late.pvd") + "'", "'" + sharedMesh("vampy_artery_cfd_pressure.ply") + "' --scalar 'velocity*'",
          "'" + sharedMesh("vtk/artery_series/artery_t0200.vtp") + "' --camera '" + dir.file("cam.json") + "'"}) {
        const RunResult run = runViewer(arguments + " --screenshot '" + dir.file("x.png") + "'", false, dir);
        EXPECT_EQ(run.status, 2) << run.output;
        EXPECT_EQ(run.output.rfind("inversevis-view: error: ", 0), 0u) << run.output;
        EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
    }
    // Outputs are checked as the CLI checks them: named for their format, apart, not an input.
    writeFile(dir.file("v.png"), "{}");
    const std::string sphere = "scene:sphere --volume-res 32 --cache-dir '" + dir.path() + "' ";
    for (const auto& [arguments, problem] : std::vector<std::pair<std::string, std::string>>{
             {sphere + "--screenshot '" + dir.file("s.jpg") + "'", "s.jpg: --screenshot writes .png files"},
             {sphere + "--screenshot '" + dir.file("s.png") + "' --region-png '" + dir.file("s.png") + "'",
              "s.png: named by both --screenshot and --region-png"},
             {sphere + "--view '" + dir.file("v.png") + "' --screenshot '" + dir.file("v.png") + "'",
              "v.png: --screenshot would overwrite --view, which this command reads"}}) {
        const RunResult run = runViewer(arguments, false, dir);
        EXPECT_EQ(run.status, 2) << run.output;
        EXPECT_NE(run.output.find(problem), std::string::npos) << run.output;
        EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
    }
    // A far field larger than the texture budget is named as the cause (it was "do not fit").
    const RunResult budget = runViewer("scene:sphere --volume-res 256 --reach 2 --texture-budget 16 --cache-dir '" +
                                           dir.path() + "' --screenshot '" + dir.file("s.png") + "'",
                                       true, dir);
    EXPECT_EQ(budget.status, 2) << budget.output;
    EXPECT_NE(budget.output.find("more than --texture-budget 16 MiB: the far field (reach 2) alone takes"),
              std::string::npos)
        << budget.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("s.jpg")));
    EXPECT_FALSE(std::filesystem::exists(dir.file("s.png")));
    // No display at all: a clear error, not a crash.
    const RunResult run = runViewer("scene:sphere --screenshot '" + dir.file("x.png") + "' --cache-dir '" + dir.path() + "'",
                                    false, dir);
    if (std::getenv("DISPLAY") == nullptr && std::getenv("WAYLAND_DISPLAY") == nullptr) {
        EXPECT_EQ(run.status, 2) << run.output;
        EXPECT_EQ(run.output.rfind("inversevis-view: error: ", 0), 0u) << run.output;
    }
}

}  // namespace ivis::test
