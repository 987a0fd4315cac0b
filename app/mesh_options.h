/// @file mesh_options.h
/// @brief Command-line options shared by every subcommand that loads a mesh.
#pragma once

#include <ivis/core/surface_source.h>
#include <ivis/render/method.h>
#include <ivis/vdb/surface_volume.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace ivis::app {

/// @brief The mesh argument and how to load it and build its volume.
struct MeshOptions {
    std::string source;  ///< file path or scene:<name>
    core::SurfaceLoadOptions load;
    vdb::VolumeOptions volume;
    std::string distance = "auto";  ///< auto | signed | unsigned
    CLI::Option* reachOption = nullptr;  ///< --reach, once registered

    /// @brief Registers MESH, --scalar, --scalar-file, --cell-to-point, --hotspots, --cap-holes and the volume's
    ///        options (--volume-res, --band, --reach, --distance).
    /// @param sources when given, the command takes one or more meshes into it instead of one MESH
    /// @param sourcesNote what the meshes are, for the help
    void addTo(CLI::App& command, std::vector<std::string>* sources = nullptr,
               const std::string& sourcesNote = "one or more");
    /// @brief Shows the scalar a view file chose (--scalar NAME, --scalar-file FILE or --hotspots N,
    ///        and --cell-to-point) unless this command line chose one itself.
    /// @return whether the picture shows the view file's scalar (false: the command line chose another)
    bool useViewScalar(const std::string& scalarName, const std::string& scalarFile, bool cellToPoint, int hotSpots);
    /// @brief The loading and volume settings keyed by their flags ({"--volume-res": 200, ...});
    ///        --reach null unless given (each method's own, raiseReachFor's).
    nlohmann::json settingsJson() const;
    /// @brief Volume options with the distance mode parsed.
    vdb::VolumeOptions volumeOptions() const;
    /// @brief Unless --reach was given, raises the far field's reach to the most that @a methods'
    ///        rays need (render::reachNeededBy).
    /// @throw ValueError naming the method's hull offset when that is beyond vdb::kMaxFarFieldReach
    void raiseReachFor(const std::vector<render::MethodPtr>& methods);
    /// @brief raiseReachFor(@a methods), then checks that each fits (checkMethodFitsVolume).
    void fitReachTo(const std::vector<render::MethodPtr>& methods);
};

/// @brief Help of every --cache-dir option.
inline constexpr const char* kCacheDirHelp =
    "Folder for volume caches, shared by every command and the viewer (default: $XDG_CACHE_HOME/inversevis, "
    "else ~/.cache/inversevis, else the current folder)";

}  // namespace ivis::app
