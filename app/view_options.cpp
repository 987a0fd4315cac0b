#include "view_options.h"

#include <ivis/core/errors.h>
#include <ivis/core/log.h>
#include <ivis/render/framing.h>

#include <cstdio>

namespace ivis::app {

void ViewOptions::addTo(CLI::App& command)
{
    command.add_option("--theta", theta, "Camera polar angle from +y (degrees)")->capture_default_str();
    command.add_option("--phi", phi, "Camera azimuth around y from +z toward +x (degrees)")->capture_default_str();
    command.add_option("--fov", fovYDeg,
                       "Vertical field of view (degrees); default: fitted to each picture, the object and the "
                       "method's whole indirect region with a margin");
    command.add_flag("--ortho", orthographic, "Orthographic projection");
    command.add_option("--camera", cameraFile,
                       "Camera JSON (eye, target, up, fov_y_deg), instead of the angles; its field of view is kept")
        ->check(CLI::ExistingFile);
    command.add_option("--res", resolution, "Image size WxH")->capture_default_str();
    command.add_option("--spp", samplesPerPixel, "Samples per pixel (supersampling)")->capture_default_str();
    method.addTo(command);
    std::string names;
    for (const std::string& name : core::colormapNames()) names += (names.empty() ? "" : ", ") + name;
    command.add_option("--colormap", colormap, "Colour map: " + names)->capture_default_str();
    command.add_option("--range", range, "Scalar range lo hi (default: the data's)")->expected(2);
    command.add_option("--units", units, "Units shown on the colour bar");
    command.add_flag("--no-legend", noLegend, "No colour bar");
    command.add_flag("--no-outline", noOutline, "No outline around the directly visible object");
    command.add_flag("--no-shadows", noShadows, "No shadow rays");
    command.add_flag("--unshaded-indirect", unshadedIndirect,
                     "Show the indirect part in flat colour (read its colours against the bar) instead of lit from the arriving rays");
    command.add_flag("--transparent", transparent, "Transparent background (PNG alpha)");
}

core::Camera ViewOptions::camera() const
{
    if (!cameraFile.empty()) return core::readCameraJson(cameraFile);
    core::Camera camera =
        core::Camera::fromAngles(theta, phi, core::kCameraDistance, fovYDeg.value_or(core::kDefaultFovYDeg));
    camera.orthographic = orthographic;
    camera.validate();
    return camera;
}

core::Camera ViewOptions::pictureCamera(const render::RenderScene& scene, const core::Camera& camera,
                                        const render::Method& method, int width, int height) const
{
    if (!framed()) return camera;
    bool fits = true;
    const core::Camera framedCamera = render::frameView(scene, camera, method, double(width) / height, &fits);
    if (!fits)
        core::logWarning(method.name() + "'s picture from theta " + std::to_string(camera.angles().x) + " phi " +
                         std::to_string(camera.angles().y) + " does not fit the widest framed field of view; it is "
                         "cut at the frame");
    return framedCamera;
}

std::string ViewOptions::describeFraming(const core::Camera& camera) const
{
    char text[96];
    if (camera.orthographic) std::snprintf(text, sizeof text, "half height %.3f", camera.orthoHalfHeight);
    else std::snprintf(text, sizeof text, "field of view %.1f degrees", camera.fovYDeg);
    return std::string(text) + (framed() ? ", framed" : ", fixed");
}

render::RenderOptions ViewOptions::renderOptions() const
{
    render::RenderOptions options;
    char extra = 0;
    if (std::sscanf(resolution.c_str(), "%dx%d%c", &options.width, &options.height, &extra) != 2 ||
        options.width < 1 || options.height < 1 || options.width > 32768 || options.height > 32768)
        throw InputError("--res '" + resolution + "': expected WIDTHxHEIGHT, e.g. 1000x1000 (1 to 32768 each)");
    options.samplesPerPixel = samplesPerPixel;
    options.method = method.create();
    options.shading.colormap = colormap;
    core::colormap(colormap);  // validates the name
    if (range.size() == 2) options.shading.range = core::scalarRangeFromUser(range[0], range[1]);
    options.shading.shadows = !noShadows;
    options.shading.shadeIndirect = !unshadedIndirect;
    options.shading.transparentBackground = transparent;
    options.outline = !noOutline;
    options.legend = !noLegend;
    options.units = units;
    return options;
}

render::RenderOptions ViewOptions::renderOptions(const core::SurfaceField& field) const
{
    render::RenderOptions options = renderOptions();
    if (range.size() != 2) options.shading.range = core::scalarRangeFromData(field.values);
    options.scalarName = field.name;
    return options;
}

}  // namespace ivis::app
