/// @file surface_source.h
/// @brief Turns a mesh argument (a file path or "scene:<name>") into a normalised SurfaceField.
#pragma once

#include <ivis/core/mesh_reader.h>
#include <ivis/core/surface_field.h>

#include <optional>
#include <string>
#include <vector>

namespace ivis::core {

/// @brief Prefix that selects a generated scene instead of a file: "scene:vessel-tree".
inline constexpr const char* kScenePrefix = "scene:";

/// @brief How to load a surface.
struct SurfaceLoadOptions {
    MeshReadOptions read;   ///< scalar selection (files only)
    bool capHoles = false;  ///< close boundary loops with caps tagged as non-data
    int hotSpots = 0;       ///< when > 0, the scalar is this many generated hot spots (core::placeHotSpots)
    bool defaultArray = true;  ///< with no scalar chosen, show the file's default array (sdf shows none)
    std::optional<Similarity> frame;  ///< normalise by this transform instead of the surface's own (normalizeBy)
};

/// @brief Reads the file (or generates the scene), logs the reader's notes and dropped degenerate
///        triangles, shows the file's default array (core::defaultArray) when it carries arrays
///        and none is chosen (and says so), caps holes when asked, normalises into [-1,1]^3 and, when asked, puts hot
///        spots on it as its scalar ("hotspots", in [0, 1]; cap vertices included, caps are never
///        coloured).
/// @throw InputError for bad files or scene names, and for a time series (a .pvd, whose message
///        names its first file, or a --scalar pattern: core::SurfaceSeries loads series), each
///        message naming the source
SurfaceField loadSurface(const std::string& source, const SurfaceLoadOptions& options = {});

/// @brief loadSurface's work after it reads a mesh file: @a field and @a report as readMesh gave
///        them for @a source (with @a options.read), for a file read once and shown again (the steps
///        of a --scalar pattern, core::SurfaceSeries).
/// @param notes when given, the lines loadSurface would log are added to it instead, to be said later
SurfaceField loadReadSurface(const std::string& source, SurfaceField field, const MeshReadReport& report,
                             const SurfaceLoadOptions& options, std::vector<std::string>* notes = nullptr);

/// @brief True when @a source is a time series (a ParaView collection, `.pvd`).
bool isTimeSeries(const std::string& source);

/// @brief A short name for a source, usable in output file names ("armadillo_50k", "vessel-tree").
std::string sourceStem(const std::string& source);

}  // namespace ivis::core
