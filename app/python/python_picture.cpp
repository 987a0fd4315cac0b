#include "python_picture.h"

#include "python_call.h"
#include "python_mesh.h"

#include "../json_output.h"
#include "../probe_report.h"
#include "../view_file.h"

#include <ivis/core/errors.h>
#include <ivis/core/file_extension.h>
#include <ivis/core/image_io.h>
#include <ivis/optimize/coherence.h>

#include <cstring>

namespace py = pybind11;

namespace ivis::python {
namespace {

/// @a image's pixels as a height x width x 3 uint8 array, sRGB (as its PNG holds them).
py::array rgbArray(const core::Image& image)
{
    const std::vector<std::uint8_t> pixels = core::srgbPixels(image, false);
    py::array_t<std::uint8_t> out({py::ssize_t(image.height()), py::ssize_t(image.width()), py::ssize_t(3)});
    std::memcpy(out.mutable_data(), pixels.data(), pixels.size());
    return std::move(out);
}

}  // namespace

py::array Picture::rgba() const
{
    const core::Image& figure = result.figure;
    const std::vector<std::uint8_t> pixels = core::srgbPixels(figure, transparent);
    py::array_t<std::uint8_t> out({py::ssize_t(figure.height()), py::ssize_t(figure.width()), py::ssize_t(4)});
    std::uint8_t* data = out.mutable_data();
    const std::size_t count = std::size_t(figure.width()) * figure.height();
    if (transparent) {
        std::memcpy(data, pixels.data(), 4 * count);
    } else {
        for (std::size_t i = 0; i < count; ++i) {
            std::memcpy(data + 4 * i, pixels.data() + 3 * i, 3);
            data[4 * i + 3] = 255;
        }
    }
    return std::move(out);
}

py::dict Picture::layers(const py::object& self) const
{
    py::dict layers;
    const py::ssize_t height = result.layers.height(), width = result.layers.width();
    for (const auto& [name, values] : result.layers.channels()) {
        py::array layer(py::dtype::of<float>(), {height, width},
                        {py::ssize_t(sizeof(float)) * width, py::ssize_t(sizeof(float))}, values.data(), self);
        // Read-only: a write changed the picture's layers but not what probe() and the maps read.
        layer.attr("flags").attr("writeable") = false;
        layers[py::str(name)] = layer;
    }
    return layers;
}

void Picture::save(const std::string& path) const
{
    const std::string extension = core::lowerCaseExtension(path);
    if (extension == ".png")
        core::writePng(result.figure, path, transparent);
    else if (extension == ".exr")
        core::writeExr(result.image, result.layers, path, meshUnits);
    else
        throw ValueError(path + ": a picture is saved as .png or .exr");
}

void Picture::saveView(const std::string& path) const
{
    if (core::lowerCaseExtension(path) != ".json") throw ValueError(path + ": a view file is saved as .json");
    app::writeViewFile(app::viewOfPicture(camera, look, load, meshUnits), path);
}

void Picture::saveViews(const std::string& path) const
{
    if (views.empty()) throw ValueError("save_views: this picture has no several views (optimize(views=N), N > 1)");
    if (core::lowerCaseExtension(path) != ".png") throw ValueError(path + ": the several views' figure is saved as .png");
    core::writePng(viewsFigure, path, transparent);
}

nlohmann::json Picture::probe(long long x, long long y) const
{
    const int width = result.image.width(), height = result.image.height();
    if (x < 0 || y < 0 || x >= width || y >= height)
        throw ValueError("probe(" + std::to_string(x) + ", " + std::to_string(y) + "): outside the " +
                         std::to_string(width) + "x" + std::to_string(height) + " picture (x 0 to " +
                         std::to_string(width - 1) + ", y 0 to " + std::to_string(height - 1) + ")");
    nlohmann::json probed;
    runReleased(
        [&](core::Interrupter& interrupter) {
            const std::shared_ptr<const Scene> scene = mesh->scene(load, volume, &interrupter);
            const app::ProbeReport report = app::probeReport(*scene->render, look.method, camera, width, height,
                                                             glm::ivec2(int(x), int(y)), look.adaptive);
            probed = app::probeJson(report, scene->field);
        },
        py::none());
    return probed;
}

py::array Picture::tearMap() const
{
    std::vector<char> torn;
    optimize::mappingCoherence(result.layers, optimize::kCoherenceDistance, &torn);
    return rgbArray(optimize::tearMap(result.image, torn));
}

py::array Picture::unseenMap() const
{
    core::Image unseen;
    runReleased(
        [&](core::Interrupter& interrupter) {
            const std::shared_ptr<const Scene> scene = mesh->scene(load, volume, &interrupter);
            const double coherence = optimize::mappingCoherence(result.layers).value();
            app::pictureMeasuresJson(*scene->render, camera, look.method, look.height, look.shading.scale.range,
                                     coherence, result.layers, &unseen);
        },
        py::none());
    return rgbArray(unseen);
}

py::bytes Picture::png() const
{
    const std::vector<std::uint8_t> bytes = core::encodePng(result.figure, transparent);
    return py::bytes(reinterpret_cast<const char*>(bytes.data()), bytes.size());
}

}  // namespace ivis::python
