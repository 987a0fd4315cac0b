/// @file ray_box.h
/// @brief The slab test: the parameter interval over which a ray lies inside an axis-aligned box.
/// @note Single precision throughout (the box is rounded to float first), as the renderer's rays.
#pragma once

#include <ivis/core/triangle_mesh.h>

#include <glm/vec3.hpp>

namespace ivis::core {

/// @brief Interval [tEnter, tExit] of t >= 0 for which origin + t direction lies in @a box.
/// @param origin, direction the ray, in the box's space; direction components below 1e-12 in
///        magnitude count as parallel to their slab
/// @param tEnter, tExit outputs: the interval (tExit starts at 1e30, so it is finite)
/// @return true when the ray passes through the box with tEnter < tExit
bool rayBoxInterval(const glm::vec3& origin, const glm::vec3& direction, const Bounds3& box, float& tEnter,
                    float& tExit);

}  // namespace ivis::core
