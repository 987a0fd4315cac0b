/// @file python_picture.h
/// @brief The Python module's Picture: one rendered picture, its pixels and layers as numpy
///        arrays (no copy: views of the picture's own memory), its camera and measures, saved as
///        `inversevis render` writes it.
#pragma once

#include <ivis/core/camera.h>
#include <ivis/core/similarity.h>
#include <ivis/core/surface_source.h>
#include <ivis/render/renderer.h>
#include <ivis/vdb/surface_volume.h>

#include <nlohmann/json.hpp>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <memory>
#include <string>
#include <vector>

namespace ivis::python {

class Mesh;

/// @brief A rendered picture and what made it.
struct Picture {
    render::RenderResult result;
    bool transparent = false;     ///< the PNG carries alpha (as --transparent)
    core::Camera camera;          ///< the camera it was rendered with (framed when asked)
    core::Similarity meshUnits;   ///< the mesh's normalising transform (the EXR and camera files carry it)
    nlohmann::json method;        ///< the method and its parameters, as --stats-json lists them
    nlohmann::json measures;      ///< coherence, and what the readable rule chose
    nlohmann::json optimization;  ///< of optimize(): the search's best view, energies and visited views (null for render())
    render::RenderOptions look;   ///< what it was rendered with (size, method as drawn, colours, legend)
    core::SurfaceLoadOptions load;  ///< what it shows: the scalar asked for ("": the default), hot spots, caps
    std::shared_ptr<Mesh> mesh;     ///< the mesh drawn, whose scene probe() and unseen_map() trace again
    vdb::VolumeOptions volume;      ///< the volume it was drawn on
    std::vector<std::shared_ptr<Picture>> views;  ///< of optimize(views=N > 1): each view's picture, the best first
    core::Image viewsFigure;      ///< of optimize(views=N > 1): the views side by side with one colour bar

    /// @brief The PNG's pixels: height x width x 4 uint8, sRGB-encoded (alpha 255 unless transparent).
    pybind11::array rgba() const;
    /// @brief The EXR's layers by name ("depth", "region", "triangle", "P.X", ...), each a
    ///        height x width float32 view of the picture's memory (kept alive by @a self).
    pybind11::dict layers(const pybind11::object& self) const;
    /// @brief Writes a PNG (".png") or multi-layer EXR (".exr") as `render -o` / `--exr` do, through
    ///        a temporary name.
    /// @throw ValueError for another extension; InputError when it cannot be written
    void save(const std::string& path) const;
    /// @brief Writes its view file (camera, method, scalar, colours, look) as `render --view-out`
    ///        writes one, through a temporary name: `render --view` and the viewer show the picture.
    /// @throw InputError when it cannot be written
    void saveView(const std::string& path) const;
    /// @brief What pixel (@a x, @a y) of the picture (a column and row of its layers, from the top
    ///        left; rgba's colour bar margin not counted) shows, as `render --probe X,Y` reports it.
    ///        The GIL is released while its rays are traced again.
    /// @throw ValueError for a pixel outside the picture
    nlohmann::json probe(long long x, long long y) const;
    /// @brief The picture in grey with its tears in red, as `render --tear-map` writes it: height x
    ///        width x 3 uint8, sRGB.
    pybind11::array tearMap() const;
    /// @brief The surface seen from the picture's side and the opposite side, red where no pixel of
    ///        the picture shows it, as `render --unseen-map` writes it (it measures the picture again:
    ///        the GIL is released while it does): height x 2 height x 3 uint8, sRGB.
    pybind11::array unseenMap() const;
    /// @brief The PNG file's bytes, for a notebook.
    pybind11::bytes png() const;
    /// @brief Writes the several views' figure (optimize(views=N)) as PNG, as `optimize --views -o` writes it.
    /// @throw ValueError for a picture without several views or another extension; InputError when it cannot be written
    void saveViews(const std::string& path) const;
};

}  // namespace ivis::python
