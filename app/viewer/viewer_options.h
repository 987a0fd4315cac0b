/// @file viewer_options.h
/// @brief Command-line options of `inversevis-view`: the mesh and view options shared with the
///        CLI, plus the window size, the headless screenshot / benchmark modes and the cache folder.
/// @note The viewer has no --res (the window or --width/--height is the image) and no
///       supersampling or transparency flags; the rest of ViewOptions applies unchanged.
#pragma once

#include "../mesh_options.h"
#include "../optimization_options.h"
#include "../view_options.h"

#include <CLI/CLI.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace ivis::app {

/// @brief Everything `inversevis-view` reads from its command line.
struct ViewerOptions {
    MeshOptions mesh;           ///< MESH, --scalar, --volume-res, ... (as the CLI); source: the first of sources
    std::vector<std::string> sources;  ///< one mesh, or the steps of a time series (core::isSeries)
    ViewOptions view;           ///< --theta, --phi, --method, --alpha, --colormap, --range, ...
    OptimizationOptions optimization;  ///< --energy, --steps, --seed, ... (as `inversevis optimize`)
    int optResolution = 100;    ///< rays per side while optimising (--opt-res)
    int views = 1;              ///< 'optimise view' also chooses this many views in all (--views)
    int width = 1024;           ///< window (and headless image) width in pixels
    int height = 768;           ///< window (and headless image) height in pixels
    std::string screenshot;     ///< headless: write the last frame here (of a series, each step's, numbered) and exit
    int frames = 3;             ///< headless: frames rendered before the screenshot
    std::string regionPng;      ///< debug: region of the last frame as grey (0 background, 128 direct, 255 indirect)
    std::string uiScreenshot;   ///< debug: run the window with its panel, write it (panel included) once settled, exit
    std::string optimise;       ///< "parameters" or "view": press that optimiser's button once loaded
    std::string probe;          ///< "X,Y": probe that pixel of the picture once loaded, as a click would
    bool play = false;          ///< a time series: press "play" once the window opens
    double playRate = 4.0;      ///< steps per second while playing (the panel's "steps/s")
    std::string tracer = "auto";  ///< what traces the picture: "gpu", "cpu" or "auto" (cpu on software GL)
    bool benchmark = false;     ///< headless: time a fixed orbit and print frames per second
    int benchmarkFrames = 120;  ///< frames of the benchmark orbit (360 degrees of azimuth)
    std::string cacheDir;       ///< --cache-dir ("" = vdb::cacheFolder's default)
    int textureBudgetMiB = 512; ///< GPU memory allowed for the volume textures

    /// @brief Registers every option on @a app.
    void addTo(CLI::App& app);
    /// @brief After parsing: the mesh source is the first of the sources.
    void takeSources() { mesh.source = sources.front(); }
    /// @brief Throws InputError / ValueError for values CLI11 does not check (sizes, frames, budget,
    ///        the method's parameters and the hull offset against the volume's reach); fits the
    ///        volume's reach to the method (MeshOptions::fitReachTo), as `render` does.
    void validate();
    /// @brief True when the program renders without a user (screenshot or benchmark).
    bool headless() const { return !screenshot.empty() || benchmark; }
};

}  // namespace ivis::app
