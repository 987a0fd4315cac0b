#include <ivis/vdb/box_lattice.h>

namespace ivis::vdb {

openvdb::math::Transform::Ptr BoxLattice::transform() const
{
    auto transform = openvdb::math::Transform::createLinearTransform(voxelSize());
    transform->postTranslate(openvdb::Vec3d(worldFromIndex(0.0)));
    return transform;
}

}  // namespace ivis::vdb
