/// @file shading.h
/// @brief Colours a pixel mapping: the scalar through a colour map, a key light with ambient and
///        soft shadows for direct pixels; indirect ones lit the same way from their arriving ray
///        and dimmed so that they read as the back side.
#pragma once

#include <ivis/core/camera.h>
#include <ivis/core/color_scale.h>
#include <ivis/core/colormap.h>
#include <ivis/render/render_scene.h>
#include <ivis/render/screen_map.h>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <string>

namespace ivis::render {

/// @brief The key light's direction in a camera's frame, normalised after weighting its right, up
///        and forward vectors: above left of the camera (the viewer's shader reads them too).
inline constexpr double kKeyLightRight = -0.35, kKeyLightUp = 0.55, kKeyLightForward = -0.75;

/// @brief Look of the rendered pixels (colours are linear RGB).
struct ShadingOptions {
    std::string colormap = "viridis";
    core::ColorScale scale;               ///< scalar values to colour-map positions
    float ambient = 0.3f;                 ///< light reaching every direct pixel
    float indirectBrightness = 0.75f;     ///< lit indirect pixels: colour x this, so they read as behind
    bool shadeIndirect = true;            ///< light indirect pixels from their arriving ray (else the bar's colour)
    bool shadows = true;                  ///< shadow rays sphere-traced through the level set
    bool transparentBackground = false;
    glm::vec3 background{1.0f};
    glm::vec3 nanColour{1.0f, 0.0f, 1.0f};  ///< data present but NaN at a vertex
    glm::vec3 noDataColour{0.72f};          ///< caps, or a mesh without scalar
};

/// @brief Shades pixel mappings for one view.
class Shader {
public:
    /// @brief Binds the scene, the view (for the key light) and the options; indirect pixels are
    ///        shadowed only when @a method's rays arrive from outside the object.
    Shader(const RenderScene& scene, const core::CameraFrame& frame, const ShadingOptions& options, const Method& method);

    /// @brief Premultiplied linear RGBA of one mapping; sets @a isNan when the scalar was NaN data.
    glm::vec4 shade(const PixelMapping& mapping, DistanceField::Sampler& sampler, bool& isNan) const;

    /// @brief Unit direction toward the key light (upper left, from the camera's side).
    const glm::vec3& toLight() const { return mToLight; }

private:
    /// The key light of a camera looking along @a arrival (upright like the view's camera).
    glm::vec3 toLightAlong(const glm::vec3& arrival) const;
    /// Ambient plus diffuse light at a point whose @a normal faces the viewer, shadowed when @a shadows.
    float lighting(const glm::vec3& position, const glm::vec3& normal, const glm::vec3& toLight, bool shadows,
                   DistanceField::Sampler& sampler) const;
    /// Surface colour of a point: colour map of its scalar, or the NaN / no-data colours.
    glm::vec3 albedo(const SurfacePoint& point, bool& isNan) const;

    const RenderScene& mScene;
    ShadingOptions mOptions;
    const core::Colormap& mColormap;
    glm::vec3 mToLight;
    glm::vec3 mUp;     ///< the camera's up vector
    glm::vec3 mRight;  ///< the camera's right vector
    bool mIndirectShadows;
    core::Bounds3 mSurfaceBox;  ///< a box around the surface, for shadowFactor
};

}  // namespace ivis::render
