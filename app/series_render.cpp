#include "series_render.h"
#include "series_survey.h"

#include "frame_video.h"
#include "json_output.h"
#include "series_scene.h"

#include <ivis/core/atomic_file.h>
#include <ivis/core/errors.h>
#include <ivis/core/image_io.h>
#include <ivis/core/log.h>
#include <ivis/optimize/coherence.h>
#include <ivis/optimize/readable_rule.h>
#include <ivis/render/method_json.h>
#include <ivis/render/renderer.h>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <string_view>

namespace ivis::app {

void parseFrameRange(const std::string& text, SeriesRenderRequest& request)
{
    // Digits only: sscanf's %lu took "-1" as the largest number and skipped spaces and a '+'.
    auto index = [](std::string_view digits, std::uint64_t& value) {
        if (digits.empty() || !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
            return false;
        if (std::from_chars(digits.data(), digits.data() + digits.size(), value).ec != std::errc())
            value = std::numeric_limits<std::uint64_t>::max();  // more digits than 64 bits: past any end
        return true;
    };
    const std::size_t colon = text.find(':');
    std::uint64_t first = 0, last = 0;
    if (colon == std::string::npos || !index(std::string_view(text).substr(0, colon), first) ||
        !index(std::string_view(text).substr(colon + 1), last) || first > last)
        throw InputError("--frames '" + text + "': expected FIRST:LAST, step indices from 0 with FIRST <= LAST (e.g. 0:99)");
    request.firstStep = first;
    request.lastStep = last;
}

void rejectSeriesFlags(const std::vector<CLI::Option*>& seriesFlags, const std::string& source)
{
    for (const CLI::Option* flag : seriesFlags)
        if (flag->count() > 0)
            throw InputError(flag->get_name() + ": applies to a time series (a .pvd, several files, or a --scalar "
                                                "pattern); " + source + " is one mesh");
}

void checkSeriesOutputFiles(const SeriesRenderRequest& request, std::size_t steps, std::vector<OutputFile> others,
                            const std::vector<InputFile>& inputs)
{
    IVIS_CHECK(steps > 0);
    if (request.firstStep >= steps)
        throw InputError("--frames " + std::to_string(request.firstStep) + ":" + std::to_string(*request.lastStep) +
                         ": the series has " + std::to_string(steps) + " steps (0 to " + std::to_string(steps - 1) + ")");
    for (std::size_t k = request.firstStep; k <= std::min(request.lastStep.value_or(steps - 1), steps - 1); ++k) {
        const std::string frame = " (frame " + std::to_string(k) + ")";
        others.push_back({framePath(request.png, k, steps), "-o" + frame, {}});
        if (!request.exr.empty()) others.push_back({framePath(request.exr, k, steps), "--exr" + frame, {}});
    }
    if (request.video) others.push_back({videoPath(request.png), "the video (-o's name as .mp4)", {}});
    checkOutputFiles(others, inputs);
}

nlohmann::json renderSeries(core::SurfaceSeries& series, const ViewOptions& view, SeriesRenderRequest& request,
                            core::ProgressBar* progress)
{
    const std::size_t count = series.steps().size();
    SeriesScene current(request.volume, request.cacheFolder, series.source());
    core::AtomicFileSet files;
    core::Camera camera;
    nlohmann::json frames = nlohmann::json::array();
    int width = 0, height = 0, legendMargin = 0;
    const std::size_t first = request.firstStep, last = std::min(request.lastStep.value_or(count - 1), count - 1);
    IVIS_CHECK(first < count);  // checkSeriesOutputFiles said so
    if (request.lastStep && *request.lastStep >= count)  // the last job of equal parts may ask past the end
        core::logInfo("--frames " + std::to_string(first) + ":" + std::to_string(*request.lastStep) +
                      ": the series has " + std::to_string(count) + " steps; rendering " + std::to_string(first) +
                      ":" + std::to_string(last));
    // The readable rule is chosen on step 0, so that every job of a render draws alike.
    std::optional<optimize::ReadableSetting> readable;
    auto chooseReadableRule = [&] {
        const render::RenderOptions options = view.renderOptions(current.field());
        const core::Camera at =
            view.pictureCamera(current.scene(), request.camera, *request.method, options.width, options.height);
        readable = optimize::loosestReadable(current.scene(), at, request.method,
                                             optimize::readableRulePictureSize(options.width, options.height),
                                             request.minCoherence);
        core::logInfo(readableSettingLine(*readable));
        request.method = readable->method;
    };
    if (request.minCoherence > 0.0 && first > 0) {
        current.show(series.load(0), progress);
        chooseReadableRule();
    }
    for (std::size_t k = first; k <= last; ++k) {
        const core::SeriesStep& step = series.steps()[k];
        if (progress) progress->setContext("frame " + std::to_string(k + 1) + "/" + std::to_string(count));
        const std::string volume = current.show(series.load(k), progress);
        if (k == 0 && request.minCoherence > 0.0) chooseReadableRule();
        render::RenderOptions options = view.renderOptions(current.field());
        options.method = request.method;
        if (request.scale) options.shading.scale = *request.scale;
        options.scalarName = seriesStepTitle(series, step, current.field().name);
        if (k == first && options.legend) {
            const core::ColorBarContent look{options.shading.colormap, options.shading.scale, "", options.units};
            legendMargin = seriesLegendMargin(series, look, current.field().name, options.width, options.height,
                                              options.legendSide, request.scale ? std::vector<core::ColorScale>{}
                                                                                : request.stepScales);
        }
        options.legendMinimumMargin = legendMargin;
        width = options.width;
        height = options.height;
        // One camera for every frame: framed on the first step's picture (a job's part: fixed, as
        // parseFrameRange's caller demands).
        if (k == first)
            camera = view.pictureCamera(current.scene(), request.camera, *options.method, options.width, options.height);
        const render::RenderResult result = render::renderImage(current.scene(), camera, options, progress);

        const std::string png = framePath(request.png, k, count);
        files.write(png, [&](const std::string& temporary) {
            core::writePng(result.figure, temporary, options.shading.transparentBackground);
        });
        const std::string exr = request.exr.empty() ? "" : framePath(request.exr, k, count);
        if (!exr.empty())
            files.write(exr, [&](const std::string& temporary) {
                core::writeExr(result.image, result.layers, temporary, current.field().normalization);
            });
        const render::RenderStats& s = result.stats;
        if (s.nanPixels > 0)
            core::logWarning(step.label + ": " + std::to_string(s.nanPixels) +
                             " pixels show NaN scalar values (drawn in magenta)");
        const double coherence = optimize::mappingCoherence(result.layers).value();
        frames.push_back({{"step", k},
                          {"time", step.time},
                          {"label", step.label},
                          {"file", step.path},
                          {"scalar", current.field().name},
                          {"legend", options.scalarName},
                          {"output", png},
                          {"exr", exr.empty() ? nlohmann::json() : nlohmann::json(exr)},
                          {"volume", volume},
                          {"volume_cache",  // null: no cache folder could be written
                           current.volumePath().empty() ? nlohmann::json() : nlohmann::json(current.volumePath())},
                          {"range", {options.shading.scale.range.lo, options.shading.scale.range.hi}},
                          {"seconds", s.seconds},
                          {"pixels_direct", s.pixelsDirect},
                          {"pixels_indirect", s.pixelsIndirect},
                          {"pixels_background", s.pixelsBackground},
                          {"nan_pixels", s.nanPixels},
                          {"coherence", coherence}});
        if (request.measure) {
            frames.back()["measures"] = pictureMeasuresJson(current.scene(), camera, options.method, options.height,
                                                            options.shading.scale.range, coherence, result.layers);
            core::logInfo(step.label + ": " + measuresLine(frames.back()["measures"]));
        }
        core::logInfo("frame " + std::to_string(k + 1) + "/" + std::to_string(count) + " (" + step.label +
                      "): volume " + volume + ", " + std::to_string(s.seconds) + " s render");
    }
    const std::string cameraPath = request.cameraOut.empty() ? request.png + ".camera.json" : request.cameraOut;
    files.write(cameraPath, [&](const std::string& temporary) {
        core::writeCameraJson(camera, temporary, current.field().normalization);
    });
    files.commit();

    nlohmann::json video;
    if (request.video) {
        const std::optional<std::string> ffmpeg = findFfmpeg();
        const std::string path = videoPath(request.png);
        const std::string framesWritten = count == 1 ? "the frame is written" : "the " + std::to_string(count) +
                                                                                    " frames are written";
        if (!ffmpeg) {
            core::logInfo("ffmpeg is not on PATH: no video (" + framesWritten + ")");
        } else if (const std::string failure = writeVideo(*ffmpeg, request.png, count, request.fps, path);
                   !failure.empty()) {
            core::logWarning(path + ": no video (" + failure + "); " + framesWritten);
        } else {
            video = path;
        }
    }
    if (const std::string path = videoPath(request.png); video.is_null() && std::filesystem::exists(path))
        core::logWarning(path + ": an earlier run's video, not made again from these frames (left as it was)");
    std::size_t stale = 0;  // frames numbered past this series' last, left by a longer one
    while (std::filesystem::exists(framePath(request.png, count + stale, count))) ++stale;
    if (stale > 0)
        core::logWarning(framePath(request.png, count, count) +
                         (stale > 1 ? " .. " + framePath(request.png, count + stale - 1, count) : std::string()) +
                         ": an earlier run's frame" + (stale > 1 ? "s" : "") + " past this series' " +
                         std::to_string(count) + " (left as " + (stale > 1 ? "they were" : "it was") + ")");

    const glm::dvec2 angles = camera.angles();
    nlohmann::json stats = {{"series", series.source()},
                            {"steps", count},
                            {"range", request.scale ? nlohmann::json{request.scale->range.lo, request.scale->range.hi} : nlohmann::json()},
                            {"volumes_loaded", current.volumesLoaded()},
                            {"width", width},
                            {"height", height},
                            {"theta", angles.x},
                            {"phi", angles.y},
                            {"fov_y_deg", camera.fovYDeg},
                            {"framed", view.framed()},
                            {"volume_resolution", request.volume.resolution},
                            {"camera", cameraPath},
                            {"video", video},
                            {"frames", frames}};
    const nlohmann::json method = render::methodToJson(*request.method);
    for (const auto& [key, value] : method.items()) stats[key] = value;
    if (readable) stats["readable_rule"] = readableSettingJson(*readable);
    const std::string written = last == first ? "1 frame " + framePath(request.png, first, count)
                                              : std::to_string(last - first + 1) + " frames " +
                                                    framePath(request.png, first, count) + " .. " +
                                                    framePath(request.png, last, count);
    core::logInfo("wrote " + written + " (" + std::to_string(width) + "x" +
                  std::to_string(height) + ", " + request.method->name() + ", " + view.describeFraming(camera) + ", " +
                  std::to_string(current.volumesLoaded()) + " volume" + (current.volumesLoaded() == 1 ? "" : "s") +
                  (video.is_null() ? "" : ", video " + video.get<std::string>()) + ")");
    return stats;
}

}  // namespace ivis::app
