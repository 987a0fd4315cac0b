#include "python_render.h"

#include "python_call.h"
#include "python_errors.h"

#include "../json_output.h"

#include <ivis/core/camera_json.h>
#include <ivis/core/color_bar.h>
#include <ivis/core/colormap.h>
#include <ivis/core/errors.h>
#include <ivis/optimize/coherence.h>
#include <ivis/optimize/picture.h>
#include <ivis/render/method_json.h>
#include <ivis/render/method_registry.h>
#include <ivis/render/picture_extent.h>

#include <pybind11/stl.h>

#include <cmath>
#include <utility>

namespace py = pybind11;

namespace ivis::python {
render::ParameterValues parameterValues(const py::dict& parameters, const std::string& method,
                                        const std::string& function)
{
    const render::MethodInfo& info = render::methodInfo(method);  // an unknown name fails here
    render::ParameterValues values;
    for (const auto& [key, value] : parameters) {
        const std::string name = key.cast<std::string>();
        if (!info.parameter(name)) {  // a mistyped option (colourmap=) is not a parameter of the method
            std::string known;
            for (const render::ParameterSpec& spec : info.parameters) known += (known.empty() ? "" : ", ") + spec.key;
            throw py::type_error(function + "() got an unexpected keyword argument '" + name +
                                 "' (neither one of its arguments nor a parameter of " + method +
                                 (known.empty() ? ", which has none)" : ": " + known + ")"));
        }
        if (py::isinstance<py::bool_>(value)) throw py::type_error(name + " must be a number or numbers, not a bool");
        if (py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value)) {
            values[name] = {value.cast<float>()};
            continue;
        }
        try {
            values[name] = value.cast<std::vector<float>>();
        } catch (const py::cast_error&) {
            throw py::type_error(name + " must be a number or a sequence of numbers, got " +
                                 py::str(value.get_type().attr("__name__")).cast<std::string>());
        }
    }
    return values;
}

render::MethodPtr methodWith(const std::string& name, const render::ParameterValues& values)
{
    const render::MethodInfo& info = render::methodInfo(name);  // an unknown name fails here
    std::vector<std::string> options;
    for (const render::ParameterSpec& spec : info.parameters) options.push_back(spec.option());
    try {
        return render::makeMethod(name, values);
    } catch (const InputError& e) {
        throw InputError(asKeywords(e.what(), options));
    } catch (const ValueError& e) {
        throw ValueError(asKeywords(e.what(), options));
    }
}

vdb::VolumeOptions volumeFor(const render::MethodPtr& method, int resolution)
{
    vdb::VolumeOptions options;
    options.resolution = resolution;
    if (method->reachNeeded() > vdb::kMaxFarFieldReach)
        throw ValueError(method->name() + " needs a volume reaching " + std::to_string(method->reachNeeded()) +
                         ", beyond the largest (" + std::to_string(vdb::kMaxFarFieldReach) + ")");
    options.farFieldReach = render::reachNeededBy({method}, options.farFieldReach);
    vdb::validate(options);
    return options;
}

PictureLook pictureLook(const RenderRequest& request)
{
    // Every argument is checked before anything is read or built.
    PictureLook look;
    look.values = parameterValues(request.parameters, request.method, request.function);
    const render::MethodPtr method = methodWith(request.method, look.values);
    render::RenderOptions& options = look.options;
    std::tie(options.width, options.height) = request.size;
    if (options.width < 1 || options.height < 1 || options.width > 32768 || options.height > 32768)
        throw ValueError("size (" + std::to_string(options.width) + ", " + std::to_string(options.height) +
                         "): width and height must be 1 to 32768");
    if (request.samplesPerPixel < 1 || request.samplesPerPixel > 1024)
        throw ValueError("spp " + std::to_string(request.samplesPerPixel) + " is out of range (1 to 1024)");
    options.samplesPerPixel = request.samplesPerPixel;
    options.method = method;
    options.adaptive.enabled = !request.fullTrace;
    core::colormap(request.colormap);  // an unknown name fails here, listing the names
    options.shading.colormap = request.colormap;
    options.shading.shadows = request.shadows;
    options.shading.transparentBackground = request.transparent;
    options.legend = request.legend;
    options.legendSide = core::legendSideFromName(request.legendSide);
    options.units = request.units;
    options.outline = request.outline;
    options.shading.shadeIndirect = request.shadeIndirect;
    if (request.range) look.scale.range = core::scalarRangeFromUser(request.range->first, request.range->second);
    look.scale.percentiles = request.rangePercentile;
    look.scale.symmetric = request.symmetric;
    look.scale.log = request.log;
    look.scale.invert = request.invert;
    try {
        look.scale.validate();
    } catch (const ValueError& e) {
        throw ValueError(asKeywords(e.what(), {"--range-percentile", "--range", "--symmetric", "--log"}));
    }
    if (!(request.minCoherence >= 0.0 && request.minCoherence <= 1.0))  // NaN too
        throw ValueError("min_coherence " + std::to_string(request.minCoherence) + " must lie in [0, 1]");
    look.volume = volumeFor(method, request.volumeResolution);
    const std::pair<bool, const char*> colourKeywords[] = {
        {request.colormap != core::kDefaultColormap, "colormap"}, {request.range.has_value(), "range"},
        {request.rangePercentile.has_value(), "range_percentile"}, {request.symmetric, "symmetric"},
        {request.log, "log"}, {request.invert, "invert"}, {!request.units.empty(), "units"},
        {request.legendSide != "right", "legend_side"}};
    for (const auto& [given, keyword] : colourKeywords)
        if (given) look.colourKeywords.push_back(keyword);
    return look;
}

void PictureLook::checkColourKeywords(const Mesh& mesh, const core::SurfaceField& field) const
{
    if (field.hasScalar() || colourKeywords.empty()) return;
    throw InputError(mesh.source() + ": " + colourKeywords.front() +
                     "= colours a scalar, and the mesh shows none (give scalar= or hotspots=)");
}

void PictureLook::colourBy(const Mesh& mesh, const core::SurfaceField& field)
{
    checkColourKeywords(mesh, field);
    try {
        options.shading.scale = scale.resolve(field.values, mesh.source());
    } catch (const ValueError& e) {
        throw ValueError(asKeywords(e.what(), {"--log"}));
    }
    options.scalarName = field.name;
}

std::shared_ptr<Picture> renderMesh(const std::shared_ptr<Mesh>& drawn, const RenderRequest& request,
                                    const py::object& progress)
{
    Mesh& mesh = *drawn;
    PictureLook look = pictureLook(request);
    const render::RenderOptions& options = look.options;
    const render::MethodPtr method = options.method;
    const render::ParameterValues& values = look.values;
    optimize::PictureRequest picture;
    picture.framed = !request.fov && !request.camera;
    if (request.camera) {
        std::string text;
        try {  // allow_nan=False: a NaN or infinity is refused here, as a camera file cannot hold one
            const py::object dumps = py::module_::import("json").attr("dumps");
            text = dumps(*request.camera, py::arg("allow_nan") = false).cast<std::string>();
        } catch (const py::error_already_set& e) {
            throw ValueError(std::string("camera: not a camera (a camera file's JSON, as Picture.camera): ") +
                             (e.matches(PyExc_ValueError) ? "its numbers must be finite" : e.what()));
        }
        try {
            picture.camera = core::cameraFromJson(nlohmann::json::parse(text));
        } catch (const std::exception& e) {
            throw ValueError(std::string("camera: not a camera (a camera file's JSON, as Picture.camera): ") + e.what());
        }
    } else {
        for (const auto& [value, keyword] : {std::pair{request.theta, "theta"}, std::pair{request.phi, "phi"},
                                             std::pair{request.fov.value_or(core::kDefaultFovYDeg), "fov"}})
            if (!std::isfinite(value))  // as `render --theta nan` refuses it (it said "camera eye and target must differ")
                throw ValueError(std::string(keyword) + " " + std::to_string(value) + " must be finite");
        picture.camera = core::Camera::fromAngles(request.theta, request.phi, core::kCameraDistance,
                                                  request.fov.value_or(core::kDefaultFovYDeg));
        picture.camera.orthographic = request.orthographic;
    }
    picture.camera.validate();
    if (picture.framed && double(options.width) <= render::kFramingMargin * options.height)
        throw ValueError("a framed picture of " + std::to_string(options.width) + "x" + std::to_string(options.height) +
                         " needs a wider picture");
    const std::string& rule = method->info().readableRuleParameter;
    // As `render --min-coherence` with such a method refuses it (the default and 0 ask for nothing).
    if (rule.empty() && request.minCoherence != optimize::kDefaultMinCoherence && request.minCoherence != 0.0)
        throw ValueError("min_coherence: " + method->name() +
                         " has no rule for drawing rays to loosen (inversevis-wrap: stable_shift)");
    picture.minCoherence = rule.empty() || values.count(rule) ? 0.0 : request.minCoherence;

    auto made = std::make_shared<Picture>();
    runReleased(
        [&](core::Interrupter& interrupter) {
            const std::shared_ptr<const Scene> scene = mesh.scene(request.load, look.volume, &interrupter);
            look.colourBy(mesh, scene->field);
            picture.options = look.options;
            optimize::Picture result = optimize::makePicture(*scene->render, picture, &interrupter);
            made->result = std::move(result.result);
            made->camera = result.camera;
            made->look = picture.options;
            made->look.method = result.method;
            made->load = request.load;
            made->mesh = drawn;
            made->volume = look.volume;
            made->meshUnits = scene->field.normalization;
            made->method = render::methodToJson(*result.method);
            made->measures = {{"coherence", optimize::mappingCoherence(made->result.layers).value()},
                              {"seconds", made->result.stats.seconds},
                              {"pixels_direct", made->result.stats.pixelsDirect},
                              {"pixels_indirect", made->result.stats.pixelsIndirect},
                              {"volume_cache", scene->volumePath}};
            if (result.readable) made->measures["readable_rule"] = optimize::readableSettingJson(*result.readable);
            if (request.measure) {
                const nlohmann::json measured = app::pictureMeasuresJson(
                    *scene->render, result.camera, result.method, look.options.height,
                    look.options.shading.scale.range, made->measures["coherence"].get<double>(), made->result.layers);
                for (const auto& [key, value] : measured.items()) made->measures[key] = value;
            }
        },
        progress);
    made->transparent = request.transparent;
    return made;
}

}  // namespace ivis::python
