/// @file view_options.h
/// @brief Command-line options for the camera, the image, the method and the look of a render.
#pragma once

#include <ivis/core/camera.h>
#include <ivis/core/color_scale.h>
#include <ivis/core/surface_field.h>
#include "mesh_options.h"
#include "method_options.h"
#include "view_file.h"

#include <ivis/render/renderer.h>

#include <CLI/CLI.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ivis::app {

/// @brief Reads "WIDTHxHEIGHT" (decimal digits only, each 1 to 32768) into @a width and @a height.
/// @return false for anything else (a sign, a space, a number that would overflow)
bool parsePictureSize(const std::string& text, int& width, int& height);

/// @brief Camera, image size, method parameters and shading, as given on the command line.
struct ViewOptions {
    double theta = 90.0;
    double phi = 0.0;
    std::optional<double> fovYDeg;  ///< --fov; none: each picture's field of view is framed
    bool orthographic = false;
    std::string cameraFile;
    std::string viewFile;  ///< --view: camera, method, scalar and look from a view file (flags override)
    std::string resolution = "1000x1000";
    int samplesPerPixel = 1;
    bool fullTrace = false;  ///< --full-trace: every pixel's curved ray traced, no adaptive image sampling
    MethodOptions method;
    std::string colormap = "viridis";
    std::vector<double> range;
    std::vector<double> rangePercentile;
    bool symmetric = false;
    bool logScale = false;
    bool invert = false;
    std::string units;
    std::string legendSide = "right";
    bool noLegend = false;
    bool noOutline = false;
    bool noShadows = false;
    bool unshadedIndirect = false;
    bool transparent = false;
    bool rangeOfEachPicture = false;  ///< each picture's range from its data, never the view file's (--range-per-frame)
    /// Whether the picture shows the --view file's scalar (showViewScalar): the file's range and
    /// units are that scalar's, so another one takes its range from its own data and shows no
    /// units (as the viewer's other arrays).
    bool showsViewScalar = true;
    bool viewIsStart = false;  ///< the --view file's camera is a search's start (optimize): each view is framed


    /// @brief Registers every option on @a command (which must outlive this object's use).
    void addTo(CLI::App& command);
    /// @brief With --view, has @a mesh (of @a source, its first file or scene) show the file's scalar
    ///        unless the command line chose one (MeshOptions::useViewScalar), and records in
    ///        showsViewScalar whether it shows it; caps its holes where the view's picture did.
    /// @throw InputError naming the view file when it shows an array and @a source is a generated scene
    void showViewScalar(MeshOptions& mesh, const std::string& source);
    /// @brief The view file of --view (read once), or null.
    /// @throw InputError naming the file when it is bad
    const ViewFile* view() const;
    /// @brief The camera: from --camera FILE, else from --theta/--phi/--fov/--ortho (75 degrees
    ///        until framed without --fov).
    core::Camera camera() const;
    /// @brief True when each picture's field of view is fitted to it (neither --fov nor --camera,
    ///        nor --view unless viewIsStart).
    bool framed() const { return !fovYDeg && cameraFile.empty() && (viewFile.empty() || viewIsStart); }
    /// @brief @a camera for a @a width x @a height picture of @a method: its field of view fitted
    ///        to the picture (render::frameView) when framed(), else unchanged. Warns when the
    ///        picture needs more than the widest framed field of view.
    core::Camera pictureCamera(const render::RenderScene& scene, const core::Camera& camera,
                               const render::Method& method, int width, int height) const;
    /// @brief "field of view 52.3 degrees, framed" (or "fixed"; orthographic: its half height).
    std::string describeFraming(const core::Camera& camera) const;
    /// @brief The colour-scale flags (--range, --range-percentile, --symmetric, --log, --invert);
    ///        with --view, the file's range, log and invert for those the flags do not give (its
    ///        range only while showsViewScalar, and not with rangeOfEachPicture).
    /// @throw ValueError when they contradict each other
    core::ColorScaleRequest colorScaleRequest() const;
    /// @brief Render options from the flags alone, every value checked, so that a bad flag fails
    ///        before a mesh is read; the scalar range is --range's (the default when not given).
    /// @throw InputError / ValueError for malformed values (e.g. --res 10y10)
    render::RenderOptions renderOptions() const;
    /// @brief Render options for @a field (its values fix the colour scale, unless --range is
    ///        given, and its name titles the colour bar).
    /// @throw InputError / ValueError for malformed values (e.g. --res 10y10), and InputError for
    ///        a colour flag (--colormap, --range, ..., --legend) given for a field without a scalar
    render::RenderOptions renderOptions(const core::SurfaceField& field) const;
    /// @brief Refuses a colour flag (--colormap, --range, ..., --legend) given for the mesh
    ///        @a source when it shows no scalar (@a hasScalar false): it would do nothing.
    /// @throw InputError naming @a source and the flag
    void checkColourFlags(bool hasScalar, const std::string& source) const;
    /// @brief True when the method's parameter @a key is given: by its option, or by the --view
    ///        file's method (unless --method names another).
    bool givesParameter(const std::string& key) const
    {
        return method.givenParameter(key) || (view() && method.keeps(*view()->method));
    }
    /// @brief True when a camera is given: --camera, --view, --theta or --phi.
    bool givesCamera() const { return !cameraFile.empty() || !viewFile.empty() || given("--theta") || given("--phi"); }
    /// @brief True when option @a name (of the command these options were added to) was given.
    bool given(const char* name) const;

private:
    CLI::App* mCommand = nullptr;
    mutable std::shared_ptr<const ViewFile> mView;  ///< --view's file, once read
    mutable std::optional<core::Camera> mCameraFileCamera;  ///< --camera's file, once read
};

}  // namespace ivis::app
