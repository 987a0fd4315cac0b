/// @file pvd_reader.h
/// @brief Reads a ParaView collection (.pvd): the files of a time series, in time order.
/// @note Every failure throws InputError whose message is one line "<pvd path>: <problem>".
#pragma once

#include <string>
#include <vector>

namespace ivis::core {

/// @brief One time step of a collection.
struct TimeStep {
    double time = 0.0;  ///< the DataSet's timestep attribute; without any in the collection, its index
    bool timed = true;  ///< false when the collection gives no DataSet a timestep
    std::string path;   ///< the step's file, relative to the working folder (the .pvd's folder joined)
};

/// @brief The DataSets of the collection @a path sorted by time (steps with equal times keep
///        their order in the file), or in the file's order when none has a timestep; each file
///        must exist.
/// @throw InputError for a missing or malformed .pvd, a DataSet without a file or with a
///        timestep that is not a number, a timestep on some DataSets only, several parts of one
///        time step, a file that does not exist, or no DataSet at all
std::vector<TimeStep> readPvd(const std::string& path);

namespace detail {
/// @brief readPvd on @a text, the bytes of the file @a path (what the fuzz target feeds).
std::vector<TimeStep> parsePvd(const std::string& path, std::string text);
}  // namespace detail

}  // namespace ivis::core
