/// @file python_view.h
/// @brief inversevis.read_view: a view file (`render --view-out`, the viewer's "save view",
///        Picture.save_view) as render()'s keyword arguments.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

namespace ivis::python {

/// @brief The view file @a path as the keyword arguments of render() that draw its picture:
///        camera, size, method and its parameters, scalar, colormap, range, log, invert, units,
///        legend, legend_side, outline, shadows, shade_indirect, spp, transparent.
/// @throw InputError naming the file for an unreadable view, or one needing what render() does
///        not take (a scalar file, cell arrays averaged onto the vertices, hot spots)
pybind11::dict readView(const std::string& path);

}  // namespace ivis::python
