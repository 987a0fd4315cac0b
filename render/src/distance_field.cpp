#include <ivis/render/distance_field.h>

#include <cmath>

namespace ivis::render {

DistanceField::DistanceField(const vdb::SurfaceVolume& volume)
    : mVolume(volume),
      mFar(volume.farPhi ? *volume.farPhi : *volume.phi),
      mHasFineBand(bool(volume.farPhi)),
      mVoxelSize(float(volume.lattice().voxelSize())),
      mInvVoxelSize(1.0f / mVoxelSize),
      mOrigin(float(volume.lattice().worldFromIndex(0.0))),
      mFineTrustBelow(volume.phi->background() + mFar.voxelSize()),
      mReach(float(volume.reach()))
{
}

DistanceField::Sampler::Sampler(const DistanceField& field)
    : mField(field), mPhi(field.mVolume.phi->getConstAccessor()), mTriangle(field.mVolume.triangle->getConstAccessor())
{
}

bool DistanceField::Sampler::fineCell(const glm::vec3& p, float corners[8], glm::vec3& t)
{
    const glm::vec3 q = (p - glm::vec3(mField.mOrigin)) * mField.mInvVoxelSize;
    if (!(q.x >= 0.0f && q.y >= 0.0f && q.z >= 0.0f)) return false;  // outside the box: no band there
    const openvdb::Coord base(int(q.x), int(q.y), int(q.z));            // truncation = floor for q >= 0
    t = q - glm::vec3(float(base.x()), float(base.y()), float(base.z()));
    const auto* leaf = mPhi.probeConstLeaf(base);
    const bool insideLeaf = leaf && (base.x() & 7) != 7 && (base.y() & 7) != 7 && (base.z() & 7) != 7;
    for (int i = 0; i < 8; ++i) {
        const openvdb::Coord ijk = base.offsetBy(i & 1, (i >> 1) & 1, (i >> 2) & 1);
        if (insideLeaf) {
            const openvdb::Index offset = leaf->coordToOffset(ijk);
            if (!leaf->isValueOn(offset)) return false;
            corners[i] = leaf->getValue(offset);
        } else if (!mPhi.probeValue(ijk, corners[i])) {
            return false;
        }
    }
    return true;
}

float DistanceField::Sampler::finePhi(const glm::vec3& p, float far)
{
    float corners[8];
    glm::vec3 t;
    return fineCell(p, corners, t) ? detail::trilinear(corners, t, nullptr) : far;
}

float DistanceField::Sampler::finePhiAndGradient(const glm::vec3& p, float far, glm::vec3& gradient)
{
    float corners[8];
    glm::vec3 t;
    if (!fineCell(p, corners, t)) return far;
    const float value = detail::trilinear(corners, t, &gradient);
    gradient *= mField.mInvVoxelSize;
    return value;
}

int DistanceField::Sampler::nearestTriangle(const glm::vec3& p)
{
    const glm::vec3 q = (p - glm::vec3(mField.mOrigin)) * mField.mInvVoxelSize;
    const openvdb::Coord ijk(int(std::lround(q.x)), int(std::lround(q.y)), int(std::lround(q.z)));
    return mTriangle.getValue(ijk);
}

}  // namespace ivis::render
