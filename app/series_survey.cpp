#include "series_survey.h"

#include <ivis/core/content_hash.h>
#include <ivis/core/log.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ivis::app {
namespace {

/// Silences the log for its life.
class SilentLog {
public:
    SilentLog() : mLevel(core::logLevel()) { core::setLogLevel(core::LogLevel::Silent); }
    ~SilentLog() { core::setLogLevel(mLevel); }
    SilentLog(const SilentLog&) = delete;
    SilentLog& operator=(const SilentLog&) = delete;

private:
    core::LogLevel mLevel;
};

}  // namespace

SeriesSurvey surveySeries(core::SurfaceSeries& series)
{
    const SilentLog silent;
    SeriesSurvey survey;
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    for (std::size_t k = 0; k < series.steps().size(); ++k) {
        const core::SurfaceField field = series.load(k);
        survey.meshHashes.push_back(core::meshHash(field.mesh));
        for (const float v : field.values) {
            if (!std::isfinite(v)) continue;
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    }
    if (lo <= hi) survey.range = {lo, hi};
    return survey;
}

}  // namespace ivis::app
