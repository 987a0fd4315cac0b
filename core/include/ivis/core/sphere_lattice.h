/// @file sphere_lattice.h
/// @brief Directions spread evenly over the unit sphere: a Fibonacci lattice.
#pragma once

#include <glm/vec3.hpp>

namespace ivis::core {

/// @brief Unit direction @a index (0 to @a count - 1) of a Fibonacci lattice of @a count directions,
///        even in area: from near +y (the polar axis, on which none lies) down to near -y, each turned
///        by the golden angle about y from the one before.
glm::dvec3 fibonacciDirection(int index, int count);

}  // namespace ivis::core
