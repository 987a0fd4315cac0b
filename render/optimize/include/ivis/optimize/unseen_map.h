/// @file unseen_map.h
/// @brief Where a picture leaves the surface unseen: the surface drawn from the picture's side and
///        from the opposite side, grey where some pixel of the picture shows its voxel and red where
///        none does (surface visibility, measure 1 of docs/measures.md, drawn instead of counted).
#pragma once

#include <ivis/core/camera.h>
#include <ivis/core/image.h>
#include <ivis/optimize/surface_voxels.h>
#include <ivis/render/render_scene.h>

#include <cstdint>
#include <vector>

namespace ivis::optimize {

/// @brief Two square panels of @a size pixels side by side: the surface of @a scene seen along
///        @a camera's view (left) and from the opposite side (right), each framed to the object,
///        grey (lit from the eye) where its surface voxel is among @a seen, red where it is a
///        surface voxel of @a voxels that no pixel showed.
/// @param seen sorted keys of the voxels the picture's points fall in (EnergyValue::seenVoxels)
/// @throw ValueError for a size below 8
core::Image unseenMap(const render::RenderScene& scene, const core::Camera& camera, const SurfaceVoxels& voxels,
                      const std::vector<std::uint64_t>& seen, int size);

}  // namespace ivis::optimize
