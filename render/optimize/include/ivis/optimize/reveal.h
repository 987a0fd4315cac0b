/// @file reveal.h
/// @brief Hot-spot reveal (docs/measures.md, 3): for a scalar field, the important surface
///        is where the importance exceeds 0.5; reveal is the share of its area inside seen voxels,
///        directly and in total, and per important region (26-connected groups of its voxels,
///        e.g. each hot spot of core::placeHotSpots).
#pragma once

#include <ivis/core/colormap.h>
#include <ivis/core/surface_field.h>
#include <ivis/optimize/surface_voxels.h>

#include <cstdint>
#include <vector>

namespace ivis::optimize {

/// @brief One reveal measurement.
struct RevealValue {
    double direct = 0.0;             ///< share of the important area inside voxels direct pixels see
    double total = 0.0;              ///< share inside voxels any pixel sees
    std::vector<double> perRegion;   ///< the same share of each region's area, largest region (in voxels) first
};

/// @brief The important surface voxels of a field and its regions.
class RevealMeasure {
public:
    /// @brief Samples and clips the surface as SurfaceVoxels does, keeping what of it has an
    ///        interpolated importance (@a range-normalised scalar; caps and NaN count 0) above 0.5.
    /// @throw InputError for a field without scalar
    RevealMeasure(const core::SurfaceField& field, const core::ScalarRange& range, int resolution = 200);

    /// @brief Reveal for the voxels seen directly (@a direct) and by all pixels (@a all); both
    ///        sorted and deduplicated in place.
    RevealValue measure(std::vector<std::uint64_t>& direct, std::vector<std::uint64_t>& all) const;
    /// @brief Number of important surface voxels.
    std::size_t count() const { return mImportant.count(); }
    /// @brief Number of important regions.
    std::size_t regionCount() const { return mRegions.size(); }
    /// @brief True when the scalar @a value is important (its normalised importance exceeds 0.5).
    bool important(float value) const;
    /// @brief Index of the important region whose voxels hold @a p, or -1 when none does.
    int regionAt(const glm::vec3& p) const;

private:
    core::ScalarRange mRange;
    SurfaceVoxels mImportant;
    std::vector<std::vector<std::uint64_t>> mRegions;
    std::vector<int> mRegionOfVoxel;  ///< the region of each of mImportant's keys
};

}  // namespace ivis::optimize
