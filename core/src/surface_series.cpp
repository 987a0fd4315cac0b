#include <ivis/core/surface_series.h>

#include <ivis/core/errors.h>
#include <ivis/core/log.h>
#include <ivis/core/number_text.h>
#include <ivis/core/pvd_reader.h>
#include <ivis/core/show_array.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace ivis::core {
namespace {

/// Refuses a scalar file for a series: each step shows its own array.
void refuseScalarFile(const MeshReadOptions& read)
{
    if (!read.scalarFile.empty())  // every step would show the one file's values
        throw InputError(read.scalarFile + ": --scalar-file gives one mesh's values; each step of a series "
                                           "shows its own array (--scalar NAME)");
}

/// The refusal of a --scalar pattern on a series of files.
InputError patternOnFilesError(const std::string& scalar)
{
    return InputError("--scalar '" + scalar + "': a pattern picks the steps among the arrays of one file; every "
                      "step of a series of files shows one array (--scalar NAME)");
}

}  // namespace

bool isSeries(const std::vector<std::string>& sources, const SurfaceLoadOptions& options)
{
    return sources.size() > 1 || (sources.size() == 1 && isTimeSeries(sources.front())) ||
           isArrayPattern(options.read.scalarName);
}

SurfaceSeries::SurfaceSeries(const std::vector<std::string>& sources, SurfaceLoadOptions options)
    : mOptions(std::move(options))
{
    IVIS_CHECK(!sources.empty());
    for (const std::string& source : sources)
        if (sources.size() > 1 && isTimeSeries(source))
            throw InputError(source + ": a .pvd is a series by itself; give it alone, not among other files");
    refuseScalarFile(mOptions.read);
    const std::string& scalar = mOptions.read.scalarName;
    const bool pattern = isArrayPattern(scalar);
    if (pattern && (sources.size() > 1 || isTimeSeries(sources.front()))) throw patternOnFilesError(scalar);
    mSource = sources.front();

    if (pattern) {
        if (sources.front().rfind(kScenePrefix, 0) == 0)
            throw InputError(sources.front() + ": generated scenes carry their own scalar; a --scalar pattern picks "
                                               "arrays of a mesh file");
        MeshReadOptions arraysOnly = mOptions.read;
        arraysOnly.scalarName.clear();
        mPatternRead = readMesh(sources.front(), arraysOnly, &mPatternReport);
        for (const std::string& name : arraysMatching(mPatternRead, scalar))
            mSteps.push_back({sources.front(), name, double(mSteps.size()), name});
    } else if (isTimeSeries(sources.front())) {
        const std::vector<TimeStep> steps = readPvd(sources.front());
        mTimed = steps.front().timed;
        for (const TimeStep& step : steps)
            mSteps.push_back({step.path, "", step.time, std::filesystem::path(step.path).filename().string()});
    } else {
        for (const std::string& source : sources)
            mSteps.push_back({source, "", double(mSteps.size()), std::filesystem::path(source).filename().string()});
    }
    if (!pattern) mDefaultArray = defaultArrayUnder(mOptions);
}

std::string SurfaceSeries::defaultArrayUnder(const SurfaceLoadOptions& options) const
{
    const bool chosen = !options.read.scalarName.empty() || options.hotSpots > 0;
    if (chosen || mSteps.front().path.rfind(kScenePrefix, 0) == 0) return "";
    const SurfaceField first = readMesh(mSteps.front().path, options.read);
    if (first.arrays.empty() && !options.read.cellToPoint) return "";
    return qualifiedArrayName(defaultArray(first, options.read.cellToPoint));
}

void SurfaceSeries::chooseScalar(const SurfaceLoadOptions& options)
{
    if (!mSteps.front().array.empty())
        throw InputError(mSource + ": the steps of a --scalar pattern are its arrays; no other array can be shown");
    refuseScalarFile(options.read);
    if (isArrayPattern(options.read.scalarName)) throw patternOnFilesError(options.read.scalarName);
    std::string defaultName = defaultArrayUnder(options);  // before anything changes: it may throw
    mOptions.read = options.read;
    mOptions.hotSpots = options.hotSpots;
    mDefaultArray = std::move(defaultName);
}

SurfaceField SurfaceSeries::load(std::size_t index)
{
    IVIS_CHECK(index < mSteps.size());
    const SeriesStep& step = mSteps[index];
    const bool heard = logLevel() <= LogLevel::Info;  // whether the notes of this load are printed
    if (!step.array.empty()) {
        // A pattern's steps are arrays of one file, read once and loaded once, its notes kept
        // until a load whose notes are printed; then each step shows its array.
        if (mPatternFile.mesh.triangles.empty()) {
            showArray(mPatternRead, step.array, mOptions.read.cellToPoint);
            mPatternFile = loadReadSurface(step.path, std::move(mPatternRead), mPatternReport, mOptions, &mPatternNotes);
            mPatternRead = SurfaceField();
        }
        if (heard && !mFirstNotesSaid) {
            for (const std::string& note : mPatternNotes) logInfo(note);
            mFirstNotesSaid = true;
        }
        SurfaceField field = mPatternFile;
        showArray(field, step.array, mOptions.read.cellToPoint);
        return field;
    }
    // The first step shows its default array as loadSurface shows it, and says so, until a load
    // whose notes are printed has said it; the other steps, and the first after that, name it.
    SurfaceLoadOptions options = mOptions;
    const bool namesDefault = (index > 0 || mFirstNotesSaid) && !mDefaultArray.empty();
    if (namesDefault) options.read.scalarName = mDefaultArray;
    options.frame = frame();
    SurfaceField field;
    try {
        field = loadSurface(step.path, options);
    } catch (const InputError& e) {
        // The user named no array: say which step lacks the one shown and where it came from.
        const std::string missing = step.path + ": no array '" + mDefaultArray + "'; ";
        if (!namesDefault || std::string(e.what()).rfind(missing, 0) != 0) throw;
        const std::size_t colon = mDefaultArray.find(':');
        throw InputError(step.path + ": step " + std::to_string(index) + " has no " + mDefaultArray.substr(0, colon) +
                         " array '" + mDefaultArray.substr(colon + 1) +
                         "', which the first step shows by default (--scalar chooses one every step has); " +
                         std::string(e.what()).substr(missing.size()));
    }
    const Bounds3 box = bounds(field.mesh);
    double reach = 0.0;
    for (int a = 0; a < 3; ++a) reach = std::max({reach, std::abs(box.lo[a]), std::abs(box.hi[a])});
    if (reach > kSeriesFrameReach)
        throw InputError(step.path + ": its geometry reaches " + shortNumber(reach) +
                         " of the first step's half size from that step's centre; every step of a series is drawn in "
                         "the first step's frame, which holds geometry that moves or grows by up to half of it");
    if (index == 0 && heard) mFirstNotesSaid = true;
    return field;
}

const Similarity& SurfaceSeries::frame()
{
    if (!mFrame) {
        const std::string& first = mSteps.front().path;
        if (first.rfind(kScenePrefix, 0) == 0) {
            mFrame = loadSurface(first, {}).normalization;
        } else {
            SurfaceField field = readMesh(first, {});
            normalize(field);
            mFrame = field.normalization;
        }
    }
    return *mFrame;
}

}  // namespace ivis::core
