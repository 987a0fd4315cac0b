#include <ivis/optimize/series_importance.h>

#include <ivis/core/content_hash.h>
#include <ivis/core/errors.h>

#include <cmath>
#include <vector>

namespace ivis::optimize {

core::SurfaceField meanImportanceField(core::SurfaceSeries& series, const core::ScalarRange& range)
{
    const std::size_t count = series.steps().size();
    core::SurfaceField mean = series.load(0);
    const std::uint64_t geometry = core::meshHash(mean.mesh);
    std::vector<double> sum(mean.values.size(), 0.0);
    for (std::size_t k = 0; k < count; ++k) {
        const core::SurfaceField step = k == 0 ? mean : series.load(k);
        if (core::meshHash(step.mesh) != geometry || step.valuesOn != mean.valuesOn ||
            step.values.size() != sum.size())
            throw InputError(series.steps()[k].path + ": step " + std::to_string(k) + " (" + series.steps()[k].label +
                             ") has other geometry or values than the first step; one optimisation serves a series "
                             "of one geometry (render takes any series)");
        for (std::size_t i = 0; i < sum.size(); ++i)
            if (!std::isnan(step.values[i])) sum[i] += range.normalized(step.values[i]);
    }
    for (std::size_t i = 0; i < sum.size(); ++i) mean.values[i] = float(sum[i] / double(count));
    if (mean.hasScalar()) mean.name = "mean importance of " + std::to_string(count) + " steps";
    return mean;
}

}  // namespace ivis::optimize
