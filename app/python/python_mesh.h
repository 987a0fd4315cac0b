/// @file python_mesh.h
/// @brief The Python module's Mesh: a surface as read from a file (or given as numpy arrays) with
///        its arrays, the scalar to show chosen per call, and the volumes and scenes of its calls
///        kept for the next (each volume in the command line's cache too).
#pragma once

#include <ivis/core/mesh_reader.h>
#include <ivis/core/surface_source.h>
#include <ivis/render/render_scene.h>
#include <ivis/vdb/surface_volume.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace ivis::python {

/// @brief A render scene and what it refers to: the surface showing one scalar, and a volume.
struct Scene {
    core::SurfaceField field;                          ///< normalised, showing the chosen scalar
    std::shared_ptr<const vdb::SurfaceVolume> volume;
    std::unique_ptr<render::RenderScene> render;
    std::string volumePath;                            ///< the volume's cache file ("" when none)
};

/// @brief A surface of the Python module.
/// @note Thread-safe: renders of one mesh from several threads share its scenes.
class Mesh {
public:
    /// @brief Reads @a source: a mesh file of any format the command line reads, or scene:<name>.
    /// @throw InputError naming the file and the problem
    static std::shared_ptr<Mesh> read(const std::string& source);
    /// @brief A mesh of @a vertices (n x 3, float32 or float64) and @a faces (m x 3, int32 or int64),
    ///        numpy arrays or nested lists (converted), with point arrays (n or n x k) and cell arrays
    ///        (m or m x k) by name.
    /// @throw pybind11::value_error / type_error naming the bad argument; InputError for non-finite
    ///        coordinates or indices out of range
    static std::shared_ptr<Mesh> fromArrays(const pybind11::object& vertices, const pybind11::object& faces,
                                            const pybind11::dict& pointData, const pybind11::dict& cellData);

    /// @brief Where it came from: the file, scene:<name>, or "Mesh" for arrays.
    const std::string& source() const { return mSource; }
    /// @brief Whether it is a generated scene (its own scalar, no file's arrays).
    bool generated() const { return mSource.rfind(core::kScenePrefix, 0) == 0; }
    /// @brief Its vertices in its own units (n x 3 float32) and triangles (m x 3 int64), copied.
    pybind11::array vertices() const;
    pybind11::array faces() const;
    /// @brief How many vertices (those some triangle uses) and triangles it has.
    std::size_t vertexCount() const { return mRaw.mesh.positions.size(); }
    std::size_t triangleCount() const { return mRaw.mesh.triangles.size(); }
    /// @brief Its arrays' values by name, copied: of @a association Point one row per vertex (as
    ///        vertices()), of Cell one row per triangle (as faces(): each its file cell's value); (n,)
    ///        for one component, (n, k) for k. A generated scene's point data is its own scalar.
    pybind11::dict data(core::Association association) const;
    /// @brief Its arrays, as `inversevis info` lists them; a generated scene's own scalar as its one.
    std::vector<core::ArrayInfo> arrays() const;

    /// @brief The scene showing what @a load chooses (its scalar by name, "" for the file's default
    ///        array; cell values averaged onto the vertices; generated hot spots; holes capped), with a volume of @a options (from the command line's cache, else built and
    ///        written there), made on first use and kept.
    std::shared_ptr<const Scene> scene(const core::SurfaceLoadOptions& load, const vdb::VolumeOptions& options,
                                       core::Interrupter* interrupter);
    /// @brief The surface showing what @a load chooses, normalised, as `render MESH --scalar NAME
    ///        --cell-to-point --hotspots N --cap-holes` loads it.
    /// @throw ValueError for choices that exclude each other (named as render()'s keywords);
    ///        InputError for an array the mesh lacks
    core::SurfaceField shown(const core::SurfaceLoadOptions& load) const;

private:
    std::string mSource;
    core::SurfaceField mRaw;  ///< as read: its own units, no scalar shown (a generated scene: as generated)
    core::MeshReadReport mReport;
    std::mutex mMutex;
    struct Volume {
        std::shared_ptr<const vdb::SurfaceVolume> volume;
        std::string path;  ///< its cache file ("" when none)
    };
    std::map<std::string, Volume> mVolumes;  ///< by the volume options' key
    std::map<std::string, std::shared_ptr<const Scene>> mScenes;
};

}  // namespace ivis::python
