#include "python_view.h"
#include "python_json.h"

#include "../view_file.h"

#include <ivis/core/camera_json.h>
#include <ivis/core/errors.h>
#include <ivis/render/method_json.h>

#include <pybind11/stl.h>

namespace py = pybind11;

namespace ivis::python {
namespace {

const char* sideName(core::LegendSide side)
{
    return side == core::LegendSide::Left ? "left" : side == core::LegendSide::Bottom ? "bottom" : "right";
}

}  // namespace

py::dict readView(const std::string& path)
{
    const app::ViewFile view = app::readViewFile(path);
    if (!view.scalarFile.empty())
        throw InputError(path + ": the view colours by a scalar file (" + view.scalarFile +
                         "), which render() does not read; give its values as the mesh's point_data, or render it "
                         "with `inversevis render --view`");
    py::dict arguments;
    arguments["camera"] = fromJson(core::cameraFileJson(view.camera, view.meshUnits));
    arguments["size"] = py::make_tuple(view.width, view.height);
    const nlohmann::json method = render::methodToJson(*view.method);
    for (const auto& [key, value] : method.items()) arguments[py::str(key)] = fromJson(value);
    arguments["scalar"] = view.scalar.empty() ? py::object(py::none()) : py::object(py::str(view.scalar));
    arguments["cell_to_point"] = view.cellToPoint;
    arguments["hotspots"] = view.hotSpots;
    arguments["cap_holes"] = view.capHoles;
    arguments["colormap"] = view.colormap;
    arguments["range"] = py::make_tuple(view.scale.range.lo, view.scale.range.hi);
    arguments["log"] = view.scale.log;
    arguments["invert"] = view.scale.invert;
    arguments["units"] = view.units;
    arguments["legend"] = view.legend;
    arguments["legend_side"] = sideName(view.legendSide);
    arguments["outline"] = view.outline;
    arguments["shadows"] = view.shadows;
    arguments["shade_indirect"] = view.shadeIndirect;
    arguments["spp"] = view.samplesPerPixel;
    arguments["transparent"] = view.transparent;
    return arguments;
}

}  // namespace ivis::python
