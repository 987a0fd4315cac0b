/// @file surface_series.h
/// @brief A time series of surfaces, one step after the other: the files of a ParaView collection
///        (.pvd), a list of files, or the arrays of one file whose names match a pattern
///        (`--scalar 'pressure_t*'`).
#pragma once

#include <ivis/core/surface_source.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace ivis::core {

/// @brief One step of a series: the file it reads and the array it shows.
struct SeriesStep {
    std::string path;   ///< the step's file (or scene)
    std::string array;  ///< the array a pattern matched; "" when the step shows the series' --scalar
    double time = 0.0;  ///< the .pvd's timestep; the step's index for a list of files or a pattern
    std::string label;  ///< the step's name: its file's name, or the array's for a pattern
};

/// @brief True when @a sources with @a options make a series: a .pvd, several sources, or an
///        array pattern (core::isArrayPattern) in --scalar.
bool isSeries(const std::vector<std::string>& sources, const SurfaceLoadOptions& options);

/// @brief How far from the first step's centre, in its normalised units (its longest half extent
///        1), a step's geometry may reach: room for walls that move or swell between steps, inside
///        the volume's box with the rays' hull round it.
inline constexpr double kSeriesFrameReach = 1.5;

/// @brief The steps of a series and each step's surface, loaded as loadSurface loads a file.
/// @note Every step shows the same array: the --scalar given, the pattern's match of the step, or,
///       when none is chosen, the array the first step shows by default, which the first load of
///       the first step made while info messages print says, once. A pattern's file, read once,
///       is read again by the first such load, so that its notes are said.
class SurfaceSeries {
public:
    /// @brief Lists the steps: a .pvd's (core::readPvd), each source's in the order given, or the
    ///        arrays of one file matching the pattern in natural order (core::arraysMatching).
    /// @throw InputError for a bad .pvd, a .pvd among several sources, a pattern with several
    ///        sources or a .pvd, a pattern on a generated scene, a pattern's file or (with no
    ///        array chosen) the first step's file that cannot be read, a pattern that matches no array
    SurfaceSeries(const std::vector<std::string>& sources, SurfaceLoadOptions options);

    /// @brief The steps in order.
    const std::vector<SeriesStep>& steps() const { return mSteps; }
    /// @brief True when the steps carry times of their own (a .pvd's timesteps), not their indices.
    bool timed() const { return mTimed; }
    /// @brief The source that names the series (its caches): the .pvd, the pattern's file, or the
    ///        first file.
    const std::string& source() const { return mSource; }

    /// @brief Step @a index's surface showing its array, normalised by the first step's transform
    ///        (every step in one frame, so that geometry that moves or grows between steps is seen to).
    /// @throw InputError naming the step's file for a file that cannot be read, lacks the array, or
    ///        whose geometry reaches beyond kSeriesFrameReach in the first step's frame
    SurfaceField load(std::size_t index);

    /// @brief Every later load shows the scalar @a options choose (their array, cell-to-point and
    ///        hot-spot options; the others stay the series'), as if the series had been opened with them.
    /// @throw InputError for the steps of a pattern (they are arrays), a scalar file or a pattern in
    ///        @a options, and (with no scalar chosen) a first step's file that cannot be read; the
    ///        series is then as it was
    void chooseScalar(const SurfaceLoadOptions& options);

private:
    /// The first step's normalising transform, which every step is normalised by (read once).
    const Similarity& frame();

    /// The array the first step shows by default under @a options ("" when they choose a scalar or
    /// there is none): every step then shows it.
    std::string defaultArrayUnder(const SurfaceLoadOptions& options) const;

    std::vector<SeriesStep> mSteps;
    std::string mSource;
    bool mTimed = false;
    SurfaceLoadOptions mOptions;
    SurfaceField mPatternRead;     ///< the pattern's file as read, until it is loaded
    MeshReadReport mPatternReport;  ///< what reading it reported
    SurfaceField mPatternFile;     ///< the pattern's file loaded (empty for a series of files)
    std::vector<std::string> mPatternNotes;  ///< what loading it said, said at the first heard load
    std::string mDefaultArray;  ///< with no array chosen, the first step's default array, shown by every step
    std::optional<Similarity> mFrame;  ///< frame(), once read
    bool mFirstNotesSaid = false;  ///< whether a heard load (info printing) said the first step's notes
};

}  // namespace ivis::core
