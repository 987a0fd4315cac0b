#include "viewer_options.h"

#include "../cli_checks.h"
#include "../output_files.h"
#include "../probe_report.h"

#include <ivis/core/errors.h>
#include <ivis/core/number_text.h>

#include <cstdlib>
#include <filesystem>

namespace ivis::app {

void ViewerOptions::addTo(CLI::App& app)
{
    mesh.addTo(app, &sources,
               "one, or a time series (a .pvd, several files, or one file with a --scalar pattern such as "
               "'pressure_t*'): a time slider shows its steps");
    view.addTo(app);
    optimization.addTo(app);
    app.add_option("--opt-res", optResolution, "Optimisation resolution (rays per side) of the optimise buttons")
        ->capture_default_str();
    app.add_option("--views", views,
                   "'optimise view' also chooses the visited views that show the most surface with the best one (as "
                   "optimize --views; visibility energy): the panel's view buttons switch between them")
        ->check(CLI::Range(1, 16))
        ->capture_default_str();
    // Flags of `inversevis render` that have no meaning in a window.
    for (const char* name : {"--res", "--spp", "--transparent"})
        app.remove_option(app.get_option(name));
    app.add_option("--width", width,
                   "Window width in pixels (headless: the picture's width; the colour bar's margin is added beside it, "
                   "as render's --res)")
        ->capture_default_str();
    app.add_option("--height", height,
                   "Window height in pixels (headless: the picture's height; a --screenshot of a --view: the view's "
                   "size unless given)")
        ->capture_default_str();
    app.add_option("--screenshot", screenshot,
                   "Render without input, write this PNG and exit; of a series, one per step, numbered as render "
                   "numbers frames (shot_0000.png, ...), each step shown as the time slider shows it");
    app.add_option("--frames", frames, "Frames rendered before the screenshot")->capture_default_str();
    app.add_option("--region-png", regionPng,
                   "Also write the last frame's regions as grey levels (0 background, 128 direct, 255 indirect)");
    app.add_option("--ui-screenshot", uiScreenshot,
                   "Run the window with its panel; once loading and optimising are done and --frames frames "
                   "drawn, write the window (panel included) to this PNG and exit");
    app.add_option("--optimize", optimise, "Press the parameter optimiser's button or 'optimise view' once the volume is loaded")
        ->check(CLI::IsMember({"parameters", "view"}));
    app.add_option("--probe", probe,
                   "Once the volume is loaded, probe pixel X,Y of the picture (from its top left) as a click does: "
                   "what it shows, printed and in the panel (headless: of each step, after its screenshot)");
    app.add_flag("--play", play,
                 "A time series: play its steps once the window opens, as the panel's play button does (from the "
                 "first step to the last, each step's volume loaded before the next; --ui-screenshot waits for the last)");
    app.add_option("--play-rate", playRate, "Steps per second while playing (0.1 to 60)")->capture_default_str();
    app.add_option("--tracer", tracer,
                   "What traces the picture: the shaders (gpu), the CPU renderer as `render` does (cpu, progressively: "
                   "a smaller picture while the camera moves, the full one once it rests), or auto: cpu where OpenGL "
                   "is software (llvmpipe), gpu elsewhere")
        ->check(CLI::IsMember({"auto", "gpu", "cpu"}))
        ->capture_default_str();
    app.add_flag("--benchmark", benchmark,
                 "Orbit 360 degrees in --benchmark-frames frames, drawn as while the camera moves, then rest; print the "
                 "frames per second and the time to the full picture");
    app.add_option("--benchmark-frames", benchmarkFrames, "Frames of the benchmark orbit")->capture_default_str();
    app.add_option("--cache-dir", cacheDir, kCacheDirHelp)->check(nonEmpty());
    app.add_option("--texture-budget", textureBudgetMiB, "GPU memory for the volume textures, MiB")
        ->capture_default_str();
}

void ViewerOptions::validate()
{
    if (frames < 1 || frames > 100000) throw ValueError("--frames " + std::to_string(frames) + " must be at least 1");
    if (benchmarkFrames < 2 || benchmarkFrames > 100000)
        throw ValueError("--benchmark-frames " + std::to_string(benchmarkFrames) + " must be at least 2");
    if (optResolution < optimize::kMinOptimizationResolution || optResolution > optimize::kMaxOptimizationResolution)
        throw ValueError("--opt-res " + std::to_string(optResolution) + " is out of range (" +
                         std::to_string(optimize::kMinOptimizationResolution) + " to " +
                         std::to_string(optimize::kMaxOptimizationResolution) + ")");
    if (textureBudgetMiB < 16 || textureBudgetMiB > 65536)
        throw ValueError("--texture-budget " + std::to_string(textureBudgetMiB) + " is out of range (16 to 65536 MiB)");
    if (!(playRate >= 0.1 && playRate <= 60.0))
        throw ValueError("--play-rate " + core::shortNumber(playRate) + " is out of range (0.1 to 60 steps per second)");
    if (play && headless())
        throw InputError("--play: --screenshot already shows every step of a series in turn, and --benchmark orbits one");
    if (!regionPng.empty() && screenshot.empty()) throw InputError("--region-png needs --screenshot");
    if (!probe.empty() && benchmark) throw InputError("--probe: the benchmark orbits; probe a screenshot or the window");
    checkOutputFiles({{screenshot, "--screenshot", {".png"}},
                      {regionPng, "--region-png", {".png"}},
                      {uiScreenshot, "--ui-screenshot", {".png"}}},
                     readFiles(sources, mesh.load.read.scalarFile, view.cameraFile, view.viewFile));
    // A screenshot of a view file is the view's picture, sized as `render --view` sizes it (the
    // window's default size was taken instead).
    if (const ViewFile* v = view.view(); v && !screenshot.empty()) {
        if (!view.given("--width")) width = v->width;
        if (!view.given("--height")) height = v->height;
    }
    if (width < 16 || height < 16 || width > 8192 || height > 8192)
        throw ValueError("--width/--height " + std::to_string(width) + "x" + std::to_string(height) +
                         " is out of range (16 to 8192 each)");
    if (!probe.empty()) parseProbePixel(probe, width, height);
    mesh.fitReachTo({view.renderOptions().method});
    view.camera();  // reads --camera or --view now: a bad file fails alone, before the mesh's notes
    if (int(!screenshot.empty()) + int(!uiScreenshot.empty()) + int(benchmark) > 1)
        throw InputError("--screenshot, --ui-screenshot and --benchmark exclude each other");
}

}  // namespace ivis::app
