/// @file cache_folder.h
/// @brief Where volumes are cached ($XDG_CACHE_HOME/inversevis by default) and how their files are
///        named, so that every program (the command line, the viewer, the Python module) finds the
///        same volume of a mesh.
#pragma once

#include <ivis/core/triangle_mesh.h>
#include <ivis/vdb/surface_volume.h>

#include <string>

namespace ivis::vdb {

/// @brief The folder of volume caches: @a cacheDir when given, else $XDG_CACHE_HOME/inversevis,
///        else $HOME/.cache/inversevis, else "."; created when missing and @a create is set.
/// @throw InputError naming the folder when it cannot be created, or (not created) when
///        @a cacheDir names no folder
std::string cacheFolder(const std::string& cacheDir, bool create = true);

/// @brief cacheFolder's folder, created when missing, once it can be written to.
/// @throw InputError naming the folder when it cannot be created or written
std::string writableCacheFolder(const std::string& cacheDir);

/// @brief The cache folder of a command that can do without one (render, optimize, evaluate, the
///        viewer; not sdf, whose output the cache is): cacheFolder's, or "" with a warning when
///        it cannot be created or written (a read-only home on a cluster), so that the volume is
///        built for the run and not kept.
std::string optionalCacheFolder(const std::string& cacheDir);

/// @brief Default cache file inside @a folder ("" for the folder "": no cache) for the normalised
///        mesh @a mesh of @a source built with @a options: "<stem>.<mesh hash>.res<N>.reach<R>.vdb",
///        with ".band<B>" before ".vdb" for a band other than the default and ".signed" or
///        ".unsigned" for a distance sign asked for, so that every geometry of a time series (and
///        every mesh of one name) keeps a cache of its own, and so does each far-field reach (the
///        curved-ray methods' volumes reach further than the others'), band and sign; where no such
///        file exists but one of another stem with the same rest of the name does (the same
///        geometry read from another file: the steps of a series), that one (the first by name).
std::string defaultVolumePath(const std::string& folder, const std::string& source, const core::TriangleMesh& mesh,
                              const VolumeOptions& options);

/// @brief Whether @a fileName is a name defaultVolumePath makes (or made before the reach and the
///        hash joined it), or the temporary name of one being written ("<name>.tmp.<pid>.<n>",
///        core::AtomicFile's): what `cache` lists and clears.
bool isVolumeCacheName(const std::string& fileName);

}  // namespace ivis::vdb
