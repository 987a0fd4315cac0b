// inversevis-view against the CPU renderer: the same view of the generated vessel tree rendered by
// the viewer's shaders (under Xvfb with Mesa's llvmpipe) and by render::renderImage.
#include "test_support.h"
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
namespace {

#ifdef IVIS_VIEW_PATH

constexpr int kSize = 512;

struct RunResult {
    int status = -1;
    std::string output;  ///< stdout and stderr
};

/// Writes mixed.pvd in @a dir: the artery's first step, a tetrahedron (other geometry, tet.vtp),
/// the artery's second step; returns its path.
std::string writeMixedSeries(const TempDir& dir)
{
    VtkDataSet tet;
    tet.points = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    tet.polys.connectivity = {0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2};
    tet.polys.offsets = {3, 6, 9, 12};
    tet.pointData = {{"pressure", "Float32", 1, {0.1, 0.2, 0.3, 0.4}}};
    VtkXmlLayout layout;
    layout.format = VtkXmlLayout::Ascii;
    writeFile(dir.file("tet.vtp"), vtpText(tet, layout));
    writeFile(dir.file("mixed.pvd"),
              "<VTKFile type=\"Collection\"><Collection>\n<DataSet timestep=\"0\" file=\"" +
                  sharedMesh("vtk/artery_series/artery_t0200.vtp") + "\"/>\n<DataSet timestep=\"1\" file=\"tet.vtp\"/>\n" +
                  "<DataSet timestep=\"2\" file=\"" + sharedMesh("vtk/artery_series/artery_t0400.vtp") +
                  "\"/>\n</Collection></VTKFile>\n");
    return dir.file("mixed.pvd");
}

/// Runs `inversevis-view` with @a arguments, under xvfb-run when @a display. Unless @a arguments
/// choose a --tracer, the shaders trace (on Xvfb's software GL the viewer would choose the CPU):
/// these tests compare the shaders with the CPU renderer.
RunResult runViewer(std::string arguments, bool display, const TempDir& dir)
{
    if (arguments.find("--tracer ") == std::string::npos) arguments += " --tracer gpu";
    const std::string log = dir.file("viewer.log");
    // An authority file of the test's own: xvfb-run then makes no folder of its own, whose removal at
    // times failed (status 5, not the viewer's).
    const std::string prefix =
        display ? "xvfb-run -a -f '" + dir.file("Xauthority") + "' -s '-screen 0 1280x1024x24' " : "";
    static const TempDir cacheHome;  // the default cache folder is the test run's own, never the user's
    const std::string command =
        prefix + "env XDG_CACHE_HOME='" + cacheHome.path() + "' '" + IVIS_VIEW_PATH + "' " + arguments + " >'" + log + "' 2>&1";
    const int raw = std::system(command.c_str());
    RunResult result;
    result.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    result.output = text.str();
    return result;
}

bool haveXvfbRun() { return std::system("command -v xvfb-run >/dev/null 2>&1") == 0; }

/// 8-bit sRGB level of a linear value, as writePng stores it.
int level(float linear) { return int(std::lround(255.0f * core::srgbFromLinear(std::clamp(linear, 0.0f, 1.0f)))); }

/// Region of a --region-png grey level (0 background, 128 direct, 255 indirect), decoded by readPng.
int regionOfGrey(float linear)
{
    const int g = level(linear);
    return g < 64 ? 0 : g < 192 ? 1 : 2;
}

struct Agreement {
    double regionAgreement = 0.0;   ///< fraction of pixels with the same region
    double indirectMeanDiff = 0.0;  ///< mean |difference| in 8-bit levels over channels of pixels both call indirect
    double directMeanDiff = 0.0;    ///< same over pixels both call direct
    std::size_t bothIndirect = 0;
    std::size_t cpuIndirect = 0, gpuIndirect = 0;
};

/// How a viewer screenshot (@a gpu, its --region-png @a gpuRegion) agrees with a CPU picture of the
/// same size (@a cpu, its region layer @a cpuRegion).
Agreement agreement(const core::Image& cpu, const std::vector<float>& cpuRegion, const core::Image& gpu,
                    const core::Image& gpuRegion)
{
    const int width = cpu.width(), height = cpu.height();
    Agreement a;
    std::size_t same = 0, bothDirect = 0;
    double indirectSum = 0.0, directSum = 0.0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::size_t i = std::size_t(y) * width + x;
            const int c = int(cpuRegion[i]), g = regionOfGrey(gpuRegion.at(x, y).r);
            same += c == g;
            a.cpuIndirect += c == 2;
            a.gpuIndirect += g == 2;
            if (c != g || c == 0) continue;
            double diff = 0.0;
            for (int k = 0; k < 3; ++k) diff += std::abs(level(cpu.at(x, y)[k]) - level(gpu.at(x, y)[k]));
            (c == 2 ? indirectSum : directSum) += diff / 3.0;
            (c == 2 ? a.bothIndirect : bothDirect)++;
        }
    a.regionAgreement = double(same) / double(width * height);
    a.indirectMeanDiff = a.bothIndirect ? indirectSum / double(a.bothIndirect) : 0.0;
    a.directMeanDiff = bothDirect ? directSum / double(bothDirect) : 0.0;
    return a;
}

/// Renders @a method on the CPU and in the viewer at 512x512 (theta 90, phi 0, framed) and compares.
/// @param volumeResolution volume resolution of both
/// @param viewerArguments further viewer arguments (with the scalar options matching @a load)
/// @param viewerOutput optional output: what the viewer printed
/// @param source the mesh of both
/// @param load how the CPU side loads it
Agreement compareWithCpu(const std::string& method, int volumeResolution = 200, const std::string& viewerArguments = "",
                         std::string* viewerOutput = nullptr, const std::string& source = "scene:vessel-tree",
                         const core::SurfaceLoadOptions& load = {})
{
    TempDir dir;
    const core::SurfaceField field = core::loadSurface(source, load);
    vdb::VolumeOptions volumeOptions;
    volumeOptions.resolution = volumeResolution;
    volumeOptions.farFieldReach = render::reachNeededBy({render::makeMethod(method)}, volumeOptions.farFieldReach);
    // The viewer's cache name (vdb/cache_folder.h defaultVolumePath): it reuses this very volume.
    char reach[32];
    std::snprintf(reach, sizeof reach, ".reach%g", volumeOptions.farFieldReach);
    const std::string cache = dir.file(core::sourceStem(source) + "." + core::toHex(core::meshHash(field.mesh)) + ".res" +
                                       std::to_string(volumeOptions.resolution) + reach + ".vdb");
    const vdb::SurfaceVolume volume = vdb::loadOrBuildVolume(field.mesh, volumeOptions, cache);
    const render::RenderScene scene(field, volume);
    render::RenderOptions options;
    options.width = options.height = kSize;
    options.method = render::makeMethod(method);
    options.shading.scale.range = core::scalarRangeFromData(field.values);
    options.legend = false;
    options.outline = true;  // the viewer's outline pass draws the same
    // The viewer frames the view as the CLI does: the same field of view on the CPU and the GPU.
    const core::Camera camera = render::frameView(scene, core::Camera::fromAngles(90.0, 0.0), *options.method, 1.0);
    const render::RenderResult cpu = render::renderImage(scene, camera, options);
    const core::Channel& cpuChannel = cpu.layers.channel("region");
    const std::vector<float> cpuRegion(cpuChannel.begin(), cpuChannel.end());

    const std::string shot = dir.file("gpu.png"), region = dir.file("gpu-region.png");
    const RunResult run = runViewer("'" + source + "' --theta 90 --phi 0 --method " + method + " --width 512 --height 512" +
                                        " --volume-res " + std::to_string(volumeResolution) +
                                        " --frames 3 --no-legend --screenshot '" + shot + "' --region-png '" + region +
                                        "' --cache-dir '" + dir.path() + "' " + viewerArguments,
                                    true, dir);
    if (viewerOutput) *viewerOutput = run.output;
    EXPECT_EQ(run.status, 0) << run.output;
    if (run.status != 0) return {};
    EXPECT_NE(run.output.find("reused"), std::string::npos) << "the viewer should reuse the test's volume\n" << run.output;
    const core::Image gpu = core::readPng(shot), gpuRegion = core::readPng(region);
    EXPECT_EQ(gpu.width(), kSize);
    EXPECT_EQ(gpu.height(), kSize);
    if (gpu.width() != kSize || gpu.height() != kSize || gpuRegion.width() != kSize) return {};

    const Agreement a = agreement(cpu.image, cpuRegion, gpu, gpuRegion);
    std::cout << "[ viewer   ] " << method << " (volume " << volumeResolution << " " << viewerArguments << "): regions agree on " << 100.0 * a.regionAgreement << "% of pixels; "
              << "indirect CPU " << a.cpuIndirect << " / GPU " << a.gpuIndirect << " pixels; mean colour difference "
              << a.indirectMeanDiff << " (indirect), " << a.directMeanDiff << " (direct) 8-bit levels\n";
    return a;
}

#endif  // IVIS_VIEW_PATH

}  // namespace

// The acceptance test of issue 5. Regions: >= 97% of pixels (the figure; measured 99.999%).
// Colours, as mean |difference| in 8-bit sRGB levels over the pixels both call indirect (or direct):
// the viewer interpolates the same voxels with the same formulas, in float where the CPU mixes
// float and double, so a curved ray may land a hair away from the CPU's, and 8-bit rounding adds
// up to half a level. Measured: 0.14 (indirect) and 0.002 (direct). The bound of 1 level is 7x that
// and still fails for any systematic error: a wrong colour map, light, brightness factor or landing
// rule moves the mean by 10 levels or more.
TEST(Viewer, InverseVisMatchesCpuRenderer)
{
#ifndef IVIS_VIEW_PATH
    GTEST_SKIP() << "inversevis-view is not built (IVIS_BUILD_APP=OFF)";
#else
    ASSERT_TRUE(haveXvfbRun()) << "xvfb-run is missing: install it with scripts/setup.sh (Debian package xvfb)";
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
#endif
}

TEST(Viewer, MirrorAndRingMatchCpuRenderer)
{
#ifndef IVIS_VIEW_PATH
    GTEST_SKIP() << "inversevis-view is not built (IVIS_BUILD_APP=OFF)";
#else
    ASSERT_TRUE(haveXvfbRun()) << "xvfb-run is missing: install it with scripts/setup.sh (Debian package xvfb)";
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
#endif
}

// A cell array is one value per triangle in the viewer too (a buffer of triangle values), flat
// as on the CPU: the colours agree as closely as the vertex scalar's (a vertex blend instead, or
// no colour at all, would differ by tens of levels).
TEST(Viewer, CellScalarsMatchCpuRenderer)
{
#ifndef IVIS_VIEW_PATH
    GTEST_SKIP() << "inversevis-view is not built (IVIS_BUILD_APP=OFF)";
#else
    ASSERT_TRUE(haveXvfbRun()) << "xvfb-run is missing: install it with scripts/setup.sh (Debian package xvfb)";
    core::SurfaceLoadOptions load;
    load.read.scalarName = "pressure_cell";
    const Agreement a = compareWithCpu("inversevis", 200, "--scalar pressure_cell", nullptr,
                                       sharedMesh("vtk/artery_series/artery_t0200.vtp"), load);
    EXPECT_GE(a.regionAgreement, 0.97);
    EXPECT_GT(a.bothIndirect, std::size_t(5000));
    EXPECT_LT(a.indirectMeanDiff, 1.0);
    EXPECT_LT(a.directMeanDiff, 0.5);
#endif
}

// A volume finer than 200 has a far field: the viewer combines its copy with the fine band as the
// CPU does. With a budget too small for the band at 400 it resamples, and says so.
TEST(Viewer, FarFieldAndResampledVolumesMatchCpuRenderer)
{
#ifndef IVIS_VIEW_PATH
    GTEST_SKIP() << "inversevis-view is not built (IVIS_BUILD_APP=OFF)";
#else
    ASSERT_TRUE(haveXvfbRun()) << "xvfb-run is missing: install it with scripts/setup.sh (Debian package xvfb)";
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
#endif
}

// The interactive path: the ImGui panel, the background loader, the "optimise alpha" (parameters) button pressed
// by --optimize (optimize::optimizeParameters on a background thread), the animation toward its result
// and the window read back with the panel.
// A time series: each step as the time slider shows it (--screenshot writes one per step), on the
// volume loaded once since the geometry stays (the CLI's cache, named by the mesh's hash, is reused),
// with one colour range over all steps: each screenshot agrees with `render`'s frame of its step as
// closely as one picture does (a range of each step's own would move the colours by tens of levels).
TEST(Viewer, SeriesStepsShareOneVolumeAndMatchCpuFrames)
{
#ifndef IVIS_VIEW_PATH
    GTEST_SKIP() << "inversevis-view is not built (IVIS_BUILD_APP=OFF)";
#else
    ASSERT_TRUE(haveXvfbRun()) << "xvfb-run is missing: install it with scripts/setup.sh (Debian package xvfb)";
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
#endif
}

TEST(Viewer, CtrlCDuringASeriesLeavesNoScreenshot)
{
#ifndef IVIS_VIEW_PATH
    GTEST_SKIP() << "inversevis-view is not built (IVIS_BUILD_APP=OFF)";
#else
    ASSERT_TRUE(haveXvfbRun()) << "xvfb-run is missing: install it with scripts/setup.sh (Debian package xvfb)";
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
#endif
}

// A step of other geometry: the slider uploads its mesh and loads its volume (the direct part
// shows meanwhile); back on the artery, the artery's cache is read again.
TEST(Viewer, SeriesStepOfOtherGeometryLoadsItsVolume)
{
#ifndef IVIS_VIEW_PATH
    GTEST_SKIP() << "inversevis-view is not built (IVIS_BUILD_APP=OFF)";
#else
    ASSERT_TRUE(haveXvfbRun()) << "xvfb-run is missing: install it with scripts/setup.sh (Debian package xvfb)";
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
#endif
}

TEST(Viewer, PanelRunsTheParameterOptimiser)
{
#ifndef IVIS_VIEW_PATH
    GTEST_SKIP() << "inversevis-view is not built (IVIS_BUILD_APP=OFF)";
#else
    ASSERT_TRUE(haveXvfbRun()) << "xvfb-run is missing: install it with scripts/setup.sh (Debian package xvfb)";
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
#endif
}

TEST(Viewer, UnreadableMeshExitsWithStatus2)
{
#ifndef IVIS_VIEW_PATH
    GTEST_SKIP() << "inversevis-view is not built (IVIS_BUILD_APP=OFF)";
#else
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
    ASSERT_TRUE(haveXvfbRun()) << "xvfb-run is missing: install it with scripts/setup.sh (Debian package xvfb)";
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
#endif
}

}  // namespace ivis::test

namespace ivis::test {
namespace {

/// The parameters of the viewer's "inversevis-view: drawing {...}" line (the last one), or null.
nlohmann::json drawnParameters(const std::string& output)
{
    const std::string tag = "inversevis-view: drawing ";
    const std::size_t at = output.rfind(tag);
    if (at == std::string::npos) return nullptr;
    const std::size_t begin = at + tag.size();
    return nlohmann::json::parse(output.substr(begin, output.find('\n', begin) - begin));
}

/// The number after "readable rule: stable_shift " in @a output, or -1.
double readableShift(const std::string& output)
{
    const std::string tag = "readable rule: stable_shift ";
    const std::size_t at = output.find(tag);
    return at == std::string::npos ? -1.0 : std::stod(output.substr(at + tag.size()));
}

// The interactive window draws the wrap with the readable rule `render` would choose for a 1000 x
// 1000 picture, found on the CPU once the volume is loaded; a rule given is drawn as given.
TEST(Viewer, InteractiveWindowDrawsTheWrapsReadableRule)
{
#ifndef IVIS_VIEW_PATH
    GTEST_SKIP() << "inversevis-view is not built (IVIS_BUILD_APP=OFF)";
#else
    ASSERT_TRUE(haveXvfbRun()) << "xvfb-run is missing: install it with scripts/setup.sh (Debian package xvfb)";
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
#endif
}

// The panel leaves the picture most of the window: its sections fold what is seldom changed (the
// tracing accuracy, the picture's settings), and the picture lies right of it. The panel used to
// cover 46% of a 1000 x 800 window (485 x 760), over the picture's left part.
TEST(Viewer, PanelLeavesThePictureMostOfTheWindow)
{
#ifndef IVIS_VIEW_PATH
    GTEST_SKIP() << "inversevis-view is not built (IVIS_BUILD_APP=OFF)";
#else
    ASSERT_TRUE(haveXvfbRun()) << "xvfb-run is missing: install it with scripts/setup.sh (Debian package xvfb)";
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
#endif
}

// --play (the panel's play button) shows the series' steps one after the other, from the first to
// the last, and stops there: --ui-screenshot waits for it. A step of other geometry keeps the next
// waiting until its volume is loaded. One surface has nothing to play.
TEST(Viewer, PlayShowsEveryStepInTurnAndStopsAtTheLast)
{
#ifndef IVIS_VIEW_PATH
    GTEST_SKIP() << "inversevis-view is not built (IVIS_BUILD_APP=OFF)";
#else
    ASSERT_TRUE(haveXvfbRun()) << "xvfb-run is missing: install it with scripts/setup.sh (Debian package xvfb)";
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
#endif
}

// "optimise view" leaves the picture drawn with every parameter of the best view: the optimised
// speed and the rule its readability step chose (the rule used to be dropped, and the speed with it).
TEST(Viewer, OptimiseViewDrawsTheBestViewsRule)
{
#ifndef IVIS_VIEW_PATH
    GTEST_SKIP() << "inversevis-view is not built (IVIS_BUILD_APP=OFF)";
#else
    ASSERT_TRUE(haveXvfbRun()) << "xvfb-run is missing: install it with scripts/setup.sh (Debian package xvfb)";
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
#endif
}

// --views 2: 'optimise view' also chooses a second view and says what the two show together.
TEST(Viewer, OptimiseViewWithViewsChoosesASecondView)
{
#ifndef IVIS_VIEW_PATH
    GTEST_SKIP() << "inversevis-view is not built (IVIS_BUILD_APP=OFF)";
#else
    ASSERT_TRUE(haveXvfbRun()) << "xvfb-run is missing: install it with scripts/setup.sh (Debian package xvfb)";
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
#endif
}

// A view file (here render's --view-out, with a log scale, an inverted map and hot spots) shows the
// same picture in the viewer as in `render --view`.
TEST(Viewer, ViewFileShowsTheCpuPicture)
{
#ifndef IVIS_VIEW_PATH
    GTEST_SKIP() << "inversevis-view is not built (IVIS_BUILD_APP=OFF)";
#else
    ASSERT_TRUE(haveXvfbRun()) << "xvfb-run is missing: install it with scripts/setup.sh (Debian package xvfb)";
    TempDir dir;
    const std::string cache = " --volume-res 100 --cache-dir '" + dir.path() + "'";
    const CliResult made = runCli("render scene:vessel-tree --hotspots 2 --theta 60 --phi 40 --res 256x256 --colormap plasma "
                                  "--log --invert" + cache + " -o '" + dir.file("first.png") + "' --view-out '" +
                                  dir.file("v.json") + "'");
    ASSERT_EQ(made.status, 0) << made.err;
    const CliResult cpu = runCli("render scene:vessel-tree --view '" + dir.file("v.json") + "' --no-legend" + cache +
                                 " -o '" + dir.file("cpu.png") + "' --exr '" + dir.file("cpu.exr") + "'");
    ASSERT_EQ(cpu.status, 0) << cpu.err;
    const RunResult run = runViewer("scene:vessel-tree --view '" + dir.file("v.json") + "' --width 256 --height 256 --frames 2 "
                                    "--no-legend --screenshot '" + dir.file("gpu.png") + "' --region-png '" +
                                        dir.file("gpu-region.png") + "'" + cache,
                                    true, dir);
    ASSERT_EQ(run.status, 0) << run.output;
    const Agreement a = agreement(core::readPng(dir.file("cpu.png")), core::readExrChannel(dir.file("cpu.exr"), "region"),
                                  core::readPng(dir.file("gpu.png")), core::readPng(dir.file("gpu-region.png")));
    std::cout << "[ viewer   ] view file: regions agree on " << 100.0 * a.regionAgreement << "% of pixels; mean colour "
              << "difference " << a.indirectMeanDiff << " (indirect), " << a.directMeanDiff << " (direct) 8-bit levels\n";
    EXPECT_GT(a.regionAgreement, 0.995);
    EXPECT_GT(a.cpuIndirect, 1000u);
    EXPECT_LT(a.indirectMeanDiff, 2.0);
    EXPECT_LT(a.directMeanDiff, 1.0);
#endif
}

// --probe tells of a pixel of the viewer's picture what `render --probe` tells of the same pixel
// of the same view (an indirect one, so the curved ray is traced on the viewer's camera): headless
// after the screenshot, and in the window as a click would.
TEST(Viewer, ProbeTellsWhatRenderTellsOfThePixel)
{
#ifndef IVIS_VIEW_PATH
    GTEST_SKIP() << "inversevis-view is not built (IVIS_BUILD_APP=OFF)";
#else
    ASSERT_TRUE(haveXvfbRun()) << "xvfb-run is missing: install it with scripts/setup.sh (Debian package xvfb)";
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
#endif
}


// --tracer cpu: the window shows the picture `render` writes, pixel for pixel and region for
// region; its benchmark draws smaller pictures while the camera moves, then the full one.
TEST(Viewer, CpuTracerShowsRendersPicture)
{
#ifndef IVIS_VIEW_PATH
    GTEST_SKIP() << "inversevis-view is not built (IVIS_BUILD_APP=OFF)";
#else
    ASSERT_TRUE(haveXvfbRun()) << "xvfb-run is missing: install it with scripts/setup.sh (Debian package xvfb)";
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
#endif
}

}  // namespace
}  // namespace ivis::test
