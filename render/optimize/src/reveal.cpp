#include <ivis/optimize/reveal.h>

#include <ivis/core/errors.h>

#include <algorithm>
#include <cmath>

namespace ivis::optimize {
namespace {

/// Share of the sorted @a region's keys found in the sorted @a seen (1 for an empty region).
double shareSeen(const std::vector<std::uint64_t>& region, const std::vector<std::uint64_t>& seen)
{
    if (region.empty()) return 1.0;
    std::size_t count = 0;
    for (std::uint64_t key : region) count += std::binary_search(seen.begin(), seen.end(), key) ? 1 : 0;
    return double(count) / double(region.size());
}

/// A SampleFilter keeping the samples of @a field whose importance exceeds 0.5.
SampleFilter importantSamples(const core::SurfaceField& field, const core::ScalarRange& range)
{
    if (!field.hasScalar()) throw InputError(field.sourcePath + ": the reveal measure needs a scalar field");
    return [&field, range](std::size_t triangle, const glm::vec3& barycentric) {
        const float value = core::scalarAt(field, triangle, barycentric);
        return !std::isnan(value) && range.normalized(value) > 0.5f;
    };
}

}  // namespace

RevealMeasure::RevealMeasure(const core::SurfaceField& field, const core::ScalarRange& range, int resolution)
    : mImportant(field.mesh, resolution, importantSamples(field, range)), mRegions(mImportant.regions())
{
}

RevealValue RevealMeasure::measure(std::vector<std::uint64_t>& direct, std::vector<std::uint64_t>& all) const
{
    RevealValue value;
    value.direct = mImportant.fractionSeen(direct);
    value.total = mImportant.fractionSeen(all);
    for (const auto& region : mRegions) value.perRegion.push_back(shareSeen(region, all));
    return value;
}

}  // namespace ivis::optimize
