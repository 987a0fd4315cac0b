#include "series_survey.h"

#include <ivis/core/content_hash.h>
#include <ivis/core/errors.h>
#include <ivis/core/log.h>
#include <ivis/core/number_text.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ivis::app {

std::string seriesStepTitle(const core::SurfaceSeries& series, const core::SeriesStep& step, const std::string& name)
{
    if (!step.array.empty() || name.empty()) return name;
    if (!series.timed()) return name + ", " + step.label;
    return name + ", t = " + core::shortNumber(step.time);
}

int seriesLegendMargin(const core::SurfaceSeries& series, const core::ColorBarContent& look, const std::string& name,
                       int width, int height, core::LegendSide side, const std::vector<core::ColorScale>& stepScales)
{
    int margin = 0;
    for (std::size_t k = 0; k < series.steps().size(); ++k) {
        const core::SeriesStep& step = series.steps()[k];
        core::ColorBarContent content = look;
        content.title = seriesStepTitle(series, step, step.array.empty() ? name : step.array);
        if (k < stepScales.size()) content.scale = stepScales[k];
        margin = std::max(margin, core::colorBarMargin(content, width, height, side));
    }
    return margin;
}

SeriesSurvey surveySeries(core::SurfaceSeries& series, const core::ColorScaleRequest* eachStep,
                          const std::atomic<bool>* cancel)
{
    const core::ScopedLogLevel silent(core::LogLevel::Silent);  // the frames load the steps again and say their notes
    SeriesSurvey survey;
    float lo = std::numeric_limits<float>::infinity(), hi = -lo, lowestPositive = hi;
    const std::size_t steps = series.steps().size();
    for (std::size_t k = 0; k < steps; ++k) {
        if (cancel && *cancel) throw Cancelled("survey of " + series.source() + " cancelled");
        const core::SurfaceField field = series.load(k);
        survey.meshHashes.push_back(core::meshHash(field.mesh));
        survey.scalar = survey.scalar || field.hasScalar();
        const std::size_t stride = std::max<std::size_t>(1, field.values.size() * steps / kSurveySampleSize);
        if (eachStep) survey.stepScales.push_back(eachStep->resolve(field.values, field.sourcePath));
        for (std::size_t i = 0; i < field.values.size(); ++i) {
            const float v = field.values[i];
            if (!std::isfinite(v)) continue;
            lo = std::min(lo, v);
            hi = std::max(hi, v);
            if (v > 0.0f) lowestPositive = std::min(lowestPositive, v);
            if (i % stride == 0) survey.sample.push_back(v);
        }
    }
    if (lo <= hi) {
        survey.range = {lo, hi};
        survey.sample.insert(survey.sample.end(), {lo, hi});
    }
    if (std::isfinite(lowestPositive)) survey.sample.push_back(lowestPositive);
    return survey;
}

}  // namespace ivis::app
