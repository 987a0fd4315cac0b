// Running `inversevis-view` in the tests and comparing its pictures with the CPU renderer's.
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

std::string writeMixedSeries(const TempDir& dir)
{
    VtkDataSet tet;
    tet.points = {33, 31, 41, 34, 31, 41, 33, 32, 41, 33, 31, 42};  // inside the artery's frame
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

#ifdef IVIS_VIEW_PATH
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
#endif

bool haveXvfbRun() { return std::system("command -v xvfb-run >/dev/null 2>&1") == 0; }

int level(float linear) { return int(std::lround(255.0f * core::srgbFromLinear(std::clamp(linear, 0.0f, 1.0f)))); }

int regionOfGrey(float linear)
{
    const int g = level(linear);
    return g < 64 ? 0 : g < 192 ? 1 : 2;
}

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

#ifdef IVIS_VIEW_PATH
Agreement compareWithCpu(const std::string& method, int volumeResolution, const std::string& viewerArguments,
                         std::string* viewerOutput, const std::string& source, const core::SurfaceLoadOptions& load,
                         bool shadeIndirect)
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
    options.shading.shadeIndirect = shadeIndirect;
    // The viewer frames the view as the CLI does: the same field of view on the CPU and the GPU.
    const core::Camera camera = render::frameView(scene, core::Camera::fromAngles(90.0, 0.0), *options.method, 1.0);
    const render::RenderResult cpu = render::renderImage(scene, camera, options);
    const core::Channel& cpuChannel = cpu.layers.channel("region");
    const std::vector<float> cpuRegion(cpuChannel.begin(), cpuChannel.end());

    const std::string shot = dir.file("gpu.png"), region = dir.file("gpu-region.png");
    const RunResult run = runViewer("'" + source + "' --theta 90 --phi 0 --method " + method + " --width 512 --height 512" +
                                        " --volume-res " + std::to_string(volumeResolution) +
                                        " --frames 3 --no-legend --screenshot '" + shot + "' --region-png '" + region +
                                        "' --cache-dir '" + dir.path() + "' " + viewerArguments +
                                        (shadeIndirect ? "" : " --unshaded-indirect"),
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
#endif

nlohmann::json drawnParameters(const std::string& output)
{
    const std::string tag = "inversevis-view: drawing ";
    const std::size_t at = output.rfind(tag);
    if (at == std::string::npos) return nullptr;
    const std::size_t begin = at + tag.size();
    return nlohmann::json::parse(output.substr(begin, output.find('\n', begin) - begin));
}

double readableShift(const std::string& output)
{
    const std::string tag = "readable rule: stable_shift ";
    const std::size_t at = output.find(tag);
    return at == std::string::npos ? -1.0 : std::stod(output.substr(at + tag.size()));
}

}  // namespace ivis::test
