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
    InverseVis,  ///< curved rays from the hull onto the hidden surface
    InverseVisAdaptive  ///< InverseVis with alpha varying across the ring (not in the paper)
};

/// @brief Method from its command-line name; throws InputError listing the names.
Method parseMethod(const std::string& name);
/// @brief Command-line name of a method ("front", "backfaces", "neugebauer", "mirror", "inversevis",
///        "inversevis-adaptive").
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

/// @brief Alpha of the adaptive InverseVis as a function of where a pixel lies across the ring:
///        alpha(c) = a0 + a1 c + a2 c^2, clamped to [0, maxAlpha], with c = r . grad phi / |grad phi|
///        at the hull seed (0 where the view ray grazes the hull, growing toward the silhouette).
struct AlphaProfile {
    /// a0, a1, a2; the default bends the rays near the silhouette furthest round the back.
    std::array<float, 3> coefficients{0.0f, 3.0f, 3.0f};
    float maxAlpha = 4.0f;  ///< above ~4 the curved rays escape
    int retries = 2;        ///< a ray that does not land is relaunched with half its alpha this often

    /// @brief alpha for the seed alignment @a c.
    float at(float c) const
    {
        const float alpha = coefficients[0] + c * (coefficients[1] + c * coefficients[2]);
        return alpha < 0.0f ? 0.0f : alpha > maxAlpha ? maxAlpha : alpha;
    }
};

/// @brief A method and every parameter it reads.
struct MethodParams {
    Method method = Method::InverseVis;
    CurvedRayParams curved;
    AlphaProfile profile;  ///< read by InverseVisAdaptive instead of curved.alpha
    RingParams ring;
    MirrorParams mirror;

    /// @brief True for the methods that trace curved rays from the hull.
    bool curvedRays() const { return method == Method::InverseVis || method == Method::InverseVisAdaptive; }
};

}  // namespace ivis::render
