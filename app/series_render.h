/// @file series_render.h
/// @brief Renders a time series frame by frame: one camera and one method for every frame, one
///        colour range over all steps (unless each frame keeps its own), the volume kept while the
///        geometry stays the same; the numbered PNGs (and EXRs) and the camera appear together,
///        then an MP4 when ffmpeg is on PATH.
#pragma once

#include "output_files.h"
#include "view_options.h"

#include <ivis/core/colormap.h>
#include <ivis/core/progress_bar.h>
#include <ivis/core/surface_series.h>
#include <ivis/vdb/surface_volume.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace ivis::app {

/// @brief What to render of a series and where the frames go.
struct SeriesRenderRequest {
    render::MethodPtr method;                ///< the method and its parameters, the same for every frame
    core::Camera camera;                     ///< framed on the first step's picture when the view is framed
    std::optional<core::ColorScale> scale;   ///< every frame's colour scale; none: as the view gives it per frame
    std::vector<core::ColorScale> stepScales;  ///< without one scale: each step's own (sizes the colour bars alike)
    vdb::VolumeOptions volume;
    std::string cacheFolder;  ///< volume caches (one per geometry, named by the mesh's content hash)
    std::string png;          ///< frame k goes to framePath(png, k, steps)
    std::string exr;          ///< EXR layers of each frame, numbered alike ("" = none)
    std::string cameraOut;    ///< the camera JSON ("" = "<png>.camera.json")
    bool video = true;        ///< an MP4 at videoPath(png) when ffmpeg is on PATH
    double fps = 5;           ///< the video's frames per second (a fraction too: 0.5 shows each step 2 s)
    bool measure = false;     ///< each frame's measures (docs/measures.md) in its statistics (pictureMeasuresJson)
    /// Above 0: the method's readable rule (optimize::loosestReadable at this coherence) is chosen
    /// on the series' first step (step 0, also for a job's part) and replaces the method's.
    double minCoherence = 0.0;
    std::size_t firstStep = 0;                     ///< the steps rendered: firstStep..lastStep (a job's part)
    std::optional<std::size_t> lastStep;           ///< inclusive (past the end: to the last step); none: the last
};

/// @brief Parses --frames "FIRST:LAST" (step indices from 0, inclusive) into @a request.
/// @throw InputError for another form or FIRST > LAST
void parseFrameRange(const std::string& text, SeriesRenderRequest& request);

/// @brief Rejects the first of @a seriesFlags that was given: they apply to a time series only.
/// @throw InputError "--fps: applies to a time series (...); <source> is one mesh"
void rejectSeriesFlags(const std::vector<CLI::Option*>& seriesFlags, const std::string& source);

/// @brief Checks the steps a render of @a request draws of a series of @a steps steps, and the files
///        it writes, before one is read: each frame's PNG and EXR, the video, and the command's
///        @a others (its statistics, its camera, ...), none the same as another nor one of @a inputs
///        (checkOutputFiles). renderSeries draws only requests checked so.
/// @throw InputError for --frames past the last step, or naming the file and the problem
void checkSeriesOutputFiles(const SeriesRenderRequest& request, std::size_t steps, std::vector<OutputFile> others,
                            const std::vector<InputFile>& inputs);

/// @brief Renders every step of @a series as @a view and @a request say.
/// @return the statistics: the series, its range, the volumes loaded, the camera, the video, and
///         per frame its step, time, label, files, volume ("kept" or the cache outcome), range,
///         counts and mapping coherence (and with
///         SeriesRenderRequest::measure its measures), and the readable rule when one was chosen
/// @throw InputError when a step cannot be loaded or an output written (no frame is then written);
///        Cancelled when interrupted
/// @param progress optional progress line, labelled with the frame ("frame 3/40")
/// @param request its method becomes the one drawn, with the readable rule when one is chosen
nlohmann::json renderSeries(core::SurfaceSeries& series, const ViewOptions& view, SeriesRenderRequest& request,
                            core::ProgressBar* progress = nullptr);

}  // namespace ivis::app
