#include <ivis/render/distance_field.h>

#include <ivis/core/errors.h>

#include <algorithm>
#include <cmath>

namespace ivis::render {
namespace {

/// Far values up to which the fine band is used: the band's half-width less a fine cell's
/// diagonal, and at least one fine voxel.
float fineBandReach(const vdb::SurfaceVolume& volume)
{
    const float voxel = float(volume.lattice().voxelSize());
    return std::max(volume.phi->background() - std::sqrt(3.0f) * voxel, voxel);
}

/// @a volume, checked to hold the grids a distance field copies (releaseSampledGrids frees them).
const vdb::SurfaceVolume& sampledVolume(const vdb::SurfaceVolume& volume)
{
    IVIS_CHECK(!volume.released());
    return volume;
}

}  // namespace

DistanceField::DistanceField(const vdb::SurfaceVolume& volume)
    : mVolume(sampledVolume(volume)),
      mFar(volume.farPhi ? DenseGrid(*volume.farPhi, *volume.farGradient) : DenseGrid(*volume.phi, *volume.gradient)),
      mBand(volume.farPhi ? BandBricks(*volume.phi, *volume.gradient) : BandBricks()),
      mHasFineBand(bool(volume.farPhi)),
      mVoxelSize(float(volume.lattice().voxelSize())),
      mInvVoxelSize(1.0f / mVoxelSize),
      mOrigin(float(volume.lattice().worldFromIndex(0.0))),
      // Every corner of the fine cell of a point closer than the band minus the cell's diagonal is
      // in the band (phi is 1-Lipschitz), so below mFineUntil the band serves continuously; the far
      // field takes over across [mFineFrom, mFineUntil] instead of at the band's voxel-shaped edge,
      // whose jump of phi and gradient scattered the landings of neighbouring rays.
      mFineFrom(0.5f * fineBandReach(volume)),
      mFineUntil(fineBandReach(volume)),
      mReach(float(volume.reach()))
{
}

DistanceField::Sampler::Sampler(const DistanceField& field)
    : mField(field),
      mTriangle(field.mVolume.triangle->getConstAccessor())
{
}

int DistanceField::Sampler::nearestTriangle(const glm::vec3& p)
{
    const glm::vec3 q = (p - glm::vec3(mField.mOrigin)) * mField.mInvVoxelSize;
    const openvdb::Coord ijk(int(std::lround(q.x)), int(std::lround(q.y)), int(std::lround(q.z)));
    return mTriangle.getValue(ijk);
}

}  // namespace ivis::render
