/// @file child_measurement.h
/// @brief Runs a piece of work in a forked child to measure its wall time and peak memory alone.
#pragma once

#include <functional>
#include <string>

namespace ivis::bench {

/// @brief Time and peak resident memory of one measured run.
struct Measurement {
    double seconds = 0.0;
    long long peakRssBytes = 0;
    double value = 0.0;  ///< a number the work reported back (e.g. an active voxel count)
};

/// @brief Forks, runs @a work in the child (which times itself and returns a number), and reports
///        the child's own wall time, peak RSS (from wait4) and returned number.
/// @throw std::runtime_error when the child fails
Measurement measureInChild(const std::string& label, const std::function<double()>& work);

}  // namespace ivis::bench
