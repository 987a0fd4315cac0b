/// @file cli_series_fixture.h
/// @brief The CLI tests of time series: a fixture rendering a series into the output folder, and
///        PATH set for the life of an object (the program looks for ffmpeg there).
#pragma once

#include "cli_fixture.h"

#include <ivis/core/content_hash.h>
#include <ivis/core/surface_source.h>

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <string>

namespace ivis::app {

/// The artery's time series (.pvd), its PLY and one of its steps (@a time as "0200").
inline std::string pvd() { return sharedMesh("vtk/artery_series/artery.pvd"); }
inline std::string artery() { return sharedMesh("vampy_artery_cfd_pressure.ply"); }
inline std::string arteryStep(const char* time) { return sharedMesh(std::string("vtk/artery_series/artery_t") + time + ".vtp"); }

/// Sets PATH for the life of the object (the program under test looks for ffmpeg there).
class ScopedPath {
public:
    explicit ScopedPath(const std::string& path) : mOld(std::getenv("PATH") ? std::getenv("PATH") : "")
    {
        setenv("PATH", path.c_str(), 1);
    }
    ~ScopedPath() { setenv("PATH", mOld.c_str(), 1); }

private:
    std::string mOld;
};

class CliSeries : public Cli {
protected:
    /// `render SOURCES --volume-res 48 --res RES -o OUT/f.png --stats-json OUT/s.json EXTRA`.
    std::string renderSeries(const std::string& sources, const std::string& extra = "",
                             const std::string& res = "48x48") const
    {
        return "render " + sources + " --volume-res 48 --res " + res + " --cache-dir " + quoted(output("")) + " -o " +
               quoted(output("f.png")) + " --stats-json " +
               quoted(output("s.json")) + " " + extra;
    }
    nlohmann::json stats() const { return nlohmann::json::parse(test::readFile(output("s.json"))); }
    /// The volume cache name of @a source's geometry at N = 48 for the default method, whose far field
    /// reaches 1 (vdb/cache_folder.h defaultVolumePath).
    static std::string cacheName(const std::string& stem, const std::string& mesh, const std::string& scalar)
    {
        core::SurfaceLoadOptions options;
        options.read.scalarName = scalar;
        return stem + "." + core::toHex(core::meshHash(core::loadSurface(mesh, options).mesh)) + ".res48.reach1.vdb";
    }
};

}  // namespace ivis::app
