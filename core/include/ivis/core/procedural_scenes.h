/// @file procedural_scenes.h
/// @brief Generated test shapes and the embedded default scene, each with a smooth scalar field.
/// @note All scenes are returned already normalised into [-1,1]^3 (identity normalization).
#pragma once

#include <ivis/core/surface_field.h>

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace ivis::core {

/// @brief Unit-radius icosphere with @a subdivisions loop-free midpoint subdivisions; scalar:
///        two Gaussian hot spots (width 0.2), front (0.5,0.3,0.81) and back (-0.64,-0.57,-0.52).
/// @throw ValueError unless 0 <= subdivisions <= 8
SurfaceField makeSphere(int subdivisions = 4);

/// @brief Torus around the y axis (major radius 0.7, minor 0.3 before normalisation);
///        scalar: smooth angular pattern with a hot spot on the z < 0 side.
/// @throw ValueError for fewer than 3 segments either way
SurfaceField makeTorus(int majorSegments = 96, int minorSegments = 48);

/// @brief Branching vessel tree: smoothly blended tubes with an aneurysm bulge, OPEN at every
///        inlet and outlet; scalar "wss" smooth with hot spots on the back (z < 0) side.
/// @param gridResolution cells across the box used to polygonise the implicit surface (96: about
///        70k triangles in under 0.1 s on two cores)
/// @throw ValueError unless 32 <= gridResolution <= 1024
SurfaceField makeVesselTree(int gridResolution = 96);

/// @brief Names accepted by makeScene: "sphere", "torus", "vessel-tree".
std::vector<std::string> sceneNames();

/// @brief Refuses a name that is not one of sceneNames().
/// @throw InputError "unknown scene 'NAME' (known: ...)"
void checkSceneName(const std::string& name);

/// @brief Builds a named scene ("vessel-tree" is the embedded default).
/// @throw InputError for an unknown name, listing the known ones
SurfaceField makeScene(const std::string& name);

namespace detail {

/// @brief One open end of the vessel tree: the plane its tube is cut by, in normalised units.
struct VesselEnd {
    glm::dvec3 center{0.0};  ///< vessel axis point on the cut plane
    glm::dvec3 normal{0.0};  ///< unit, pointing out of the vessel along its axis
    double radius = 0.0;     ///< tube radius at the cut
};

/// @brief The inlet (first) and the outlets of makeVesselTree; each boundary loop of the tree
///        lies on one of these planes, whatever the grid resolution.
std::vector<VesselEnd> vesselTreeEnds();

}  // namespace detail
}  // namespace ivis::core
