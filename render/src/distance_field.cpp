#include <ivis/render/distance_field.h>

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

}  // namespace

DistanceField::DistanceField(const vdb::SurfaceVolume& volume)
    : mVolume(volume),
      mFar(volume.farPhi ? DenseGrid(*volume.farPhi, *volume.farGradient) : DenseGrid(*volume.phi, *volume.gradient)),
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
      mPhi(field.mVolume.phi->getConstAccessor()),
      mGradient(field.mVolume.gradient->getConstAccessor()),
      mTriangle(field.mVolume.triangle->getConstAccessor())
{
}

bool DistanceField::Sampler::fineSample(const glm::vec3& p, glm::vec4& sample)
{
    const glm::vec3 q = (p - glm::vec3(mField.mOrigin)) * mField.mInvVoxelSize;
    if (!(q.x >= 0.0f && q.y >= 0.0f && q.z >= 0.0f)) return false;  // outside the box: no band there
    const openvdb::Coord base(int(q.x), int(q.y), int(q.z));            // truncation = floor for q >= 0
    const auto* phiLeaf = mPhi.probeConstLeaf(base);
    const auto* gradientLeaf = mGradient.probeConstLeaf(base);
    const bool insideLeaf = phiLeaf && gradientLeaf && (base.x() & 7) != 7 && (base.y() & 7) != 7 && (base.z() & 7) != 7;
    glm::vec4 corners[8];
    for (int i = 0; i < 8; ++i) {
        const openvdb::Coord ijk = base.offsetBy(i & 1, (i >> 1) & 1, (i >> 2) & 1);
        float phi;
        openvdb::Vec3s gradient;
        if (insideLeaf) {
            const openvdb::Index offset = phiLeaf->coordToOffset(ijk);
            if (!phiLeaf->isValueOn(offset)) return false;
            phi = phiLeaf->getValue(offset);
            gradient = gradientLeaf->getValue(offset);
        } else {
            if (!mPhi.probeValue(ijk, phi)) return false;
            gradient = mGradient.getValue(ijk);
        }
        corners[i] = glm::vec4(phi, gradient.x(), gradient.y(), gradient.z());
    }
    sample = detail::blend(corners, q - glm::vec3(float(base.x()), float(base.y()), float(base.z())), mField.mVoxelSize);
    return true;
}

float DistanceField::Sampler::finePhiAndGradient(const glm::vec3& p, float far, glm::vec3& gradient)
{
    glm::vec4 sample;
    if (!fineSample(p, sample)) return far;
    const float w = detail::fineWeight(far, mField.mFineFrom, mField.mFineUntil);
    gradient = w * glm::vec3(sample.y, sample.z, sample.w) + (1.0f - w) * gradient;
    return w * sample.x + (1.0f - w) * far;
}

int DistanceField::Sampler::nearestTriangle(const glm::vec3& p)
{
    const glm::vec3 q = (p - glm::vec3(mField.mOrigin)) * mField.mInvVoxelSize;
    const openvdb::Coord ijk(int(std::lround(q.x)), int(std::lround(q.y)), int(std::lround(q.z)));
    return mTriangle.getValue(ijk);
}

}  // namespace ivis::render
