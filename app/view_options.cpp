#include "view_options.h"

#include "cli_checks.h"

#include <ivis/core/errors.h>
#include <ivis/core/surface_source.h>
#include <ivis/optimize/picture.h>

#include <cstdio>

namespace ivis::app {

void ViewOptions::addTo(CLI::App& command)
{
    mCommand = &command;
    command.add_option("--theta", theta, "Camera polar angle from +y (degrees)")
        ->check(finiteRange(-1e6, 1e6))
        ->capture_default_str();
    command.add_option("--phi", phi, "Camera azimuth around y from +z toward +x (degrees)")
        ->check(finiteRange(-1e6, 1e6))
        ->capture_default_str();
    auto* fovOption = command.add_option("--fov", fovYDeg,
                                         "Vertical field of view (degrees); default: fitted to each picture, the "
                                         "object and the method's whole indirect region with a margin");
    command.add_flag("--ortho", orthographic, "Orthographic projection (framed by its half height)")->excludes(fovOption);
    // A camera file, or a view file, is the whole camera: an angle or field of view beside it was ignored.
    auto* cameraOption = command.add_option("--camera", cameraFile,
                       "Camera JSON (eye, target, up, fov_y_deg), instead of the angles; its field of view is kept")
        ->check(existingFile())
        ->excludes("--theta")
        ->excludes("--phi")
        ->excludes(fovOption)
        ->excludes("--ortho");
    command.add_option("--view", viewFile,
                       "View file (optimize's and render's --view-out, the viewer's 'save view'): its camera, method "
                       "and parameters, scalar, colour map, scale, units and legend; flags given as well override it")
        ->check(existingFile())
        ->excludes(cameraOption)
        ->excludes("--theta")
        ->excludes("--phi")
        ->excludes("--fov")
        ->excludes("--ortho");
    command
        .add_option("--res", resolution,
                    "Picture size WxH (the colour bar's margin is added beside it; --no-legend for exactly WxH)")
        ->capture_default_str();
    // Checked here: the renderer's own check came after the volume was built and the rule chosen.
    command.add_option("--spp", samplesPerPixel, "Samples per pixel (supersampling)")
        ->check(CLI::Range(1, 1024))
        ->capture_default_str();
    command.add_flag("--full-trace", fullTrace,
                     "Trace every pixel's curved ray (slower) instead of tracing a lattice refined where the landings "
                     "are not smooth and interpolating between (docs/rendering.md, \"Adaptive image sampling\")");
    method.addTo(command);
    std::string names;
    for (const std::string& name : core::colormapNames()) names += (names.empty() ? "" : ", ") + name;
    command.add_option("--colormap", colormap, "Colour map: " + names)->capture_default_str();
    command.add_option("--range", range, "Scalar range lo hi (default: the data's)")->expected(2)->allow_extra_args(false);
    command.add_option("--range-percentile", rangePercentile,
                       "Scalar range from the data's LO-th and HI-th percentiles (0..100), for heavy-tailed data")
        ->expected(2)
        ->allow_extra_args(false);
    command.add_flag("--symmetric", symmetric, "Range centred on 0 ([-m, m], m the larger end), for signed data");
    command.add_flag("--log,!--linear", logScale,
                     "Logarithmic colour scale (the range's low end must be positive; --linear: a linear one)");
    command.add_flag("--invert,!--no-invert", invert, "Colour map reversed (--no-invert: not reversed)");
    command.add_option("--units", units, "Units shown on the colour bar (any Unicode, e.g. dyn/cm²)");
    auto* legendOption =
        command.add_option("--legend", legendSide, "Side of the colour bar's margin: right, left or bottom")
            ->capture_default_str();
    command.add_flag("--no-legend", noLegend, "No colour bar")->excludes(legendOption);
    // Each with its opposite, so that a view file's choice can be turned either way.
    command.add_flag("--no-outline,!--outline", noOutline, "No outline around the directly visible object (--outline: one)");
    command.add_flag("--no-shadows,!--shadows", noShadows, "No shadow rays (--shadows: shadow rays)");
    command.add_flag("--unshaded-indirect,!--shaded-indirect", unshadedIndirect,
                     "Show the indirect part in flat colour (read its colours against the bar) instead of lit from the "
                     "arriving rays (--shaded-indirect: lit)");
    command.add_flag("--transparent,!--opaque", transparent, "Transparent background (PNG alpha; --opaque: none)");
}

bool ViewOptions::given(const char* name) const
{
    const CLI::Option* option = mCommand ? mCommand->get_option_no_throw(name) : nullptr;  // the viewer lacks some
    return option && option->count() > 0;
}

void ViewOptions::showViewScalar(MeshOptions& mesh, const std::string& source)
{
    const ViewFile* v = view();
    if (!v) return;
    // A scene's view names no array; another mesh's does, which a scene cannot show (loadSurface
    // would blame --scalar, which the user never gave).
    if (source.rfind(core::kScenePrefix, 0) == 0 && (!v->scalar.empty() || !v->scalarFile.empty() || v->cellToPoint))
        throw InputError(viewFile + ": shows " +
                         (v->scalar.empty() ? "a scalar file" : "the array '" + v->scalar + "'") +
                         " of the mesh it was saved from; " + source +
                         " carries its own scalar (render that mesh, or take the view's camera alone: --camera "
                         "with the picture's .camera.json)");
    mesh.load.capHoles = mesh.load.capHoles || v->capHoles;  // the geometry it was drawn from
    showsViewScalar = mesh.useViewScalar(v->scalar, v->scalarFile, v->cellToPoint, v->hotSpots);
}

const ViewFile* ViewOptions::view() const
{
    if (viewFile.empty()) return nullptr;
    if (!mView) mView = std::make_shared<const ViewFile>(readViewFile(viewFile));
    return mView.get();
}

core::Camera ViewOptions::camera() const
{
    if (const ViewFile* v = view()) return v->camera;
    if (!cameraFile.empty()) {
        if (!mCameraFileCamera) mCameraFileCamera = core::readCameraJson(cameraFile);
        return *mCameraFileCamera;
    }
    core::Camera camera =
        core::Camera::fromAngles(theta, phi, core::kCameraDistance, fovYDeg.value_or(core::kDefaultFovYDeg));
    camera.orthographic = orthographic;
    camera.validate();
    return camera;
}

core::Camera ViewOptions::pictureCamera(const render::RenderScene& scene, const core::Camera& camera,
                                        const render::Method& method, int width, int height) const
{
    return framed() ? optimize::framedCamera(scene, camera, method, width, height) : camera;
}

std::string ViewOptions::describeFraming(const core::Camera& camera) const
{
    char text[96];
    if (camera.orthographic) std::snprintf(text, sizeof text, "half height %.3f", camera.orthoHalfHeight);
    else std::snprintf(text, sizeof text, "field of view %.1f degrees", camera.fovYDeg);
    return std::string(text) + (framed() ? ", framed" : ", fixed");
}

core::ColorScaleRequest ViewOptions::colorScaleRequest() const
{
    core::ColorScaleRequest request;
    if (range.size() == 2) request.range = core::scalarRangeFromUser(range[0], range[1]);
    if (rangePercentile.size() == 2) request.percentiles = std::pair{rangePercentile[0], rangePercentile[1]};
    request.symmetric = symmetric;
    request.log = logScale;
    request.invert = invert;
    if (const ViewFile* v = view()) {  // the view's scale, but for what the command line says
        if (!given("--range") && !given("--range-percentile") && !given("--symmetric") && !rangeOfEachPicture &&
            showsViewScalar)
            request.range = v->scale.range;
        if (!given("--log")) request.log = v->scale.log;
        if (!given("--invert")) request.invert = v->scale.invert;
        if (request.log && !given("--log")) {
            try {
                request.validate();
            } catch (const ValueError& e) {
                throw ValueError(std::string(e.what()) + " (the --view file's log scale; --linear for a linear one)");
            }
        }
    }
    request.validate();
    return request;
}

bool parsePictureSize(const std::string& text, int& width, int& height)
{
    auto side = [](const std::string& digits, int& value) {
        if (digits.empty() || digits.size() > 5 || digits.find_first_not_of("0123456789") != std::string::npos)
            return false;
        value = std::stoi(digits);  // at most 99999: no overflow
        return value >= 1 && value <= 32768;
    };
    const std::size_t x = text.find('x');
    return x != std::string::npos && side(text.substr(0, x), width) && side(text.substr(x + 1), height);
}

render::RenderOptions ViewOptions::renderOptions() const
{
    render::RenderOptions options;
    if (!parsePictureSize(resolution, options.width, options.height))
        throw InputError("--res '" + resolution + "': expected WIDTHxHEIGHT, e.g. 1000x1000 (1 to 32768 each)");
    options.samplesPerPixel = samplesPerPixel;
    options.adaptive.enabled = !fullTrace;
    options.method = method.create(view() ? view()->method.get() : nullptr);
    options.shading.colormap = colormap;
    core::colormap(colormap);  // validates the name
    const core::ColorScaleRequest request = colorScaleRequest();
    options.shading.scale.log = request.log;
    options.shading.scale.invert = request.invert;
    if (request.range) options.shading.scale.range = *request.range;
    options.legendSide = core::legendSideFromName(legendSide);
    options.shading.shadows = !noShadows;
    options.shading.shadeIndirect = !unshadedIndirect;
    options.shading.transparentBackground = transparent;
    options.outline = !noOutline;
    options.legend = !noLegend;
    options.units = units;
    if (const ViewFile* v = view()) {  // what the command line does not say, the view file does
        if (!given("--res")) {
            options.width = v->width;
            options.height = v->height;
        }
        if (!given("--colormap")) options.shading.colormap = v->colormap;
        if (!given("--units") && showsViewScalar) options.units = v->units;  // the file's scalar's units
        if (!given("--legend")) options.legendSide = v->legendSide;
        if (!given("--no-legend") && !given("--legend")) options.legend = v->legend;  // a side given shows it
        if (!given("--no-outline")) options.outline = v->outline;
        if (!given("--no-shadows")) options.shading.shadows = v->shadows;
        if (!given("--unshaded-indirect")) options.shading.shadeIndirect = v->shadeIndirect;
        if (!given("--spp")) options.samplesPerPixel = v->samplesPerPixel;
        if (!given("--transparent")) options.shading.transparentBackground = v->transparent;
    }
    if (framed() && double(options.width) <= render::kFramingMargin * options.height)
        throw InputError("a framed picture of " + std::to_string(options.width) + "x" + std::to_string(options.height) +
                         " needs a width above " + std::to_string(int(100 * render::kFramingMargin)) +
                         "% of its height (its margin); widen it or fix the field of view (--fov)");
    return options;
}

void ViewOptions::checkColourFlags(bool hasScalar, const std::string& source) const
{
    if (hasScalar) return;
    for (const char* flag :
         {"--colormap", "--range", "--range-percentile", "--symmetric", "--log", "--invert", "--units", "--legend"})
        if (given(flag)) {
            // A flag and its opposite are one option: name the one given.
            const std::string name = flag == std::string("--log") && !logScale       ? "--linear"
                                     : flag == std::string("--invert") && !invert ? "--no-invert"
                                                                                   : flag;
            throw InputError(source + ": " + name + " colours a scalar, and the mesh shows none (give --scalar, "
                             "--scalar-file or --hotspots)");
        }
}

render::RenderOptions ViewOptions::renderOptions(const core::SurfaceField& field) const
{
    checkColourFlags(field.hasScalar(), field.sourcePath);
    render::RenderOptions options = renderOptions();
    options.shading.scale = colorScaleRequest().resolve(field.values, field.sourcePath);
    options.scalarName = field.name;
    return options;
}

}  // namespace ivis::app
