/// @file picture.h
/// @brief One finished picture of a method, as `inversevis render` makes it and the Python module
///        too: the camera framed to the method's picture, the readable rule chosen where the
///        method has one (readable_rule.h), then the render.
#pragma once

#include <ivis/core/interrupter.h>
#include <ivis/optimize/readable_rule.h>
#include <ivis/render/renderer.h>

#include <optional>

namespace ivis::optimize {

/// @brief What to make a picture of, beside its scene.
struct PictureRequest {
    render::RenderOptions options;  ///< the method (its rule as given), size, look
    core::Camera camera;            ///< the eye and target asked for
    bool framed = true;             ///< fit the field of view to the method's picture (render::frameView)
    /// The readable rule's least coherence, where the method has a rule for drawing its rays that was
    /// not given (MethodInfo::readableRuleParameter); 0: the method's own rule.
    double minCoherence = kDefaultMinCoherence;
};

/// @brief A made picture: the render, the camera and the method it was made with.
struct Picture {
    render::RenderResult result;
    core::Camera camera;                     ///< framed when asked
    render::MethodPtr method;                ///< with the stable_shift the readable rule chose
    std::optional<ReadableSetting> readable;  ///< what the readable rule chose, where it ran
};

/// @brief @a camera framed for @a method's picture of @a width x @a height (render::frameView),
///        with a warning when even the widest framed field of view cuts it.
core::Camera framedCamera(const render::RenderScene& scene, const core::Camera& camera, const render::Method& method,
                          int width, int height);

/// @brief The picture of @a request: framed, its rule chosen (judged at readableRulePictureSize),
///        rendered.
/// @throw Cancelled when @a interrupter asks; ValueError for bad options
Picture makePicture(const render::RenderScene& scene, const PictureRequest& request,
                    core::Interrupter* interrupter = nullptr);

}  // namespace ivis::optimize
