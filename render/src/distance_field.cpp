#include <ivis/render/distance_field.h>

#include <cmath>

namespace ivis::render {

DistanceField::DistanceField(const vdb::SurfaceVolume& volume)
    : mVolume(volume),
      mFar(volume.farPhi ? DenseGrid(*volume.farPhi, *volume.farGradient) : DenseGrid(*volume.phi, *volume.gradient)),
      mHasFineBand(bool(volume.farPhi)),
      mVoxelSize(float(volume.lattice().voxelSize())),
      mInvVoxelSize(1.0f / mVoxelSize),
      mOrigin(float(volume.lattice().worldFromIndex(0.0))),
      // A point whose fine cell is complete is within the band (phi is 1-Lipschitz), and the far
      // blend is within a small fraction of its voxel of the exact distance: beyond this margin
      // no fine cell can be complete, and trying one is wasted.
      mFineTrustBelow(volume.phi->background() + 0.25f * mFar.voxelSize()),
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
    gradient = glm::vec3(sample.y, sample.z, sample.w);
    return sample.x;
}

int DistanceField::Sampler::nearestTriangle(const glm::vec3& p)
{
    const glm::vec3 q = (p - glm::vec3(mField.mOrigin)) * mField.mInvVoxelSize;
    const openvdb::Coord ijk(int(std::lround(q.x)), int(std::lround(q.y)), int(std::lround(q.z)));
    return mTriangle.getValue(ijk);
}

}  // namespace ivis::render
