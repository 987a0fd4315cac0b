#include <ivis/optimize/reveal.h>

#include <ivis/core/errors.h>

#include <algorithm>
#include <cmath>

namespace ivis::optimize {
namespace {

/// Share of the area of @a important inside the voxels of @a region that lies in the sorted
/// @a seen (1 for a region without area).
double areaShareSeen(const SurfaceVoxels& important, const std::vector<std::uint64_t>& region,
                     const std::vector<std::uint64_t>& seen)
{
    double total = 0.0, inSeen = 0.0;
    for (std::uint64_t key : region) {
        const double area = important.areaIn(key);
        total += area;
        if (std::binary_search(seen.begin(), seen.end(), key)) inSeen += area;
    }
    return total > 0.0 ? inSeen / total : 1.0;
}

/// True when @a value's importance over @a range exceeds 0.5 (NaN: never).
bool importantValue(const core::ScalarRange& range, float value) { return !std::isnan(value) && range.normalized(value) > 0.5f; }

/// A SampleFilter keeping the samples of @a field whose importance exceeds 0.5.
SampleFilter importantSamples(const core::SurfaceField& field, const core::ScalarRange& range)
{
    if (!field.hasScalar()) throw InputError(field.sourcePath + ": the reveal measure needs a scalar field");
    return [&field, range](std::size_t triangle, const glm::vec3& barycentric) {
        return importantValue(range, core::scalarAt(field, triangle, barycentric));
    };
}

}  // namespace

RevealMeasure::RevealMeasure(const core::SurfaceField& field, const core::ScalarRange& range, int resolution)
    : mRange(range), mImportant(field.mesh, resolution, importantSamples(field, range)), mRegions(mImportant.regions()),
      mRegionOfVoxel(mImportant.count(), -1)
{
    const std::vector<std::uint64_t>& keys = mImportant.keys();
    for (std::size_t r = 0; r < mRegions.size(); ++r)
        for (std::uint64_t key : mRegions[r])
            mRegionOfVoxel[std::size_t(std::lower_bound(keys.begin(), keys.end(), key) - keys.begin())] = int(r);
}

bool RevealMeasure::important(float value) const { return importantValue(mRange, value); }

int RevealMeasure::regionAt(const glm::vec3& p) const
{
    const std::uint64_t key = mImportant.keyOf(p);
    const std::vector<std::uint64_t>& keys = mImportant.keys();
    const auto found = std::lower_bound(keys.begin(), keys.end(), key);
    return found != keys.end() && *found == key ? mRegionOfVoxel[std::size_t(found - keys.begin())] : -1;
}

RevealValue RevealMeasure::measure(std::vector<std::uint64_t>& direct, std::vector<std::uint64_t>& all) const
{
    RevealValue value;
    value.direct = mImportant.shareSeen(direct).area;
    value.total = mImportant.shareSeen(all).area;
    for (const auto& region : mRegions) value.perRegion.push_back(areaShareSeen(mImportant, region, all));
    return value;
}

}  // namespace ivis::optimize
