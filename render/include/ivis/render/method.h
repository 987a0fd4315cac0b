/// @file method.h
/// @brief The visualisation methods and their parameters.
#pragma once

#include <ivis/render/curved_ray.h>

#include <glm/vec3.hpp>

#include <array>
#include <string>
#include <vector>

namespace ivis::render {

/// @brief How the pixels that miss the surface are used.
enum class Method {
    Front,       ///< plain rendering (paper Fig. 1a)
    Backfaces,   ///< only faces turned away from the camera (paper Fig. 1b)
    Neugebauer,  ///< ring map of Neugebauer et al. 2009 plus a back-side disc on the left
    Mirror,      ///< quadratic height-field mirror behind the object
    InverseVis   ///< curved rays from the hull onto the hidden surface
};

/// @brief Method from its command-line name; throws InputError listing the names.
Method parseMethod(const std::string& name);
/// @brief Command-line name of a method ("front", "backfaces", "neugebauer", "mirror", "inversevis").
const char* toString(Method method);
/// @brief All method names, in enum order.
std::vector<std::string> methodNames();

/// @brief Ring map parameters (lengths in units of the image half-height).
struct RingParams {
    glm::vec3 centre{0.0f};      ///< projection centre c (normalised coordinates)
    float ringWidth = 0.3f;      ///< r2 - r1
    float silhouetteGap = 0.02f; ///< r1 = silhouette radius around c_D + this gap
    float backRadius = 0.3f;     ///< radius of the back-side disc on the left
};

/// @brief Quadratic mirror z = zm + w1 x^2 + w2 y^2 + w3 xy + w4 x + w5 y in eye space.
struct MirrorParams {
    /// w1..w5; the default is a shallow bowl: a flat mirror shows nothing and has zero gradient.
    std::array<float, 5> w{0.3f, 0.3f, 0.0f, 0.0f, 0.0f};
    float distanceBehind = 1.0f;  ///< mirror apex behind the object's centre (normalised units)
    int maxSteps = 300;           ///< sphere-tracing steps from the mirror
};

/// @brief A method and every parameter it reads.
struct MethodParams {
    Method method = Method::InverseVis;
    CurvedRayParams curved;
    RingParams ring;
    MirrorParams mirror;
};

}  // namespace ivis::render
