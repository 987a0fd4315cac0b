/// @file coherence.h
/// @brief Mapping coherence (docs/measures.md, 2): among the 4-adjacent pairs of indirect
///        pixels that both landed, the share whose surface points lie within 0.1 normalised units
///        of each other. It counts tears: seams between overlapping hull regions, speckle, swirls.
#pragma once

#include <ivis/core/camera.h>
#include <ivis/core/image.h>
#include <ivis/render/method.h>
#include <ivis/render/render_scene.h>

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace ivis::optimize {

/// @brief The pairs counted by the measure.
struct Coherence {
    std::size_t pairs = 0;     ///< 4-adjacent pairs of landed indirect pixels
    std::size_t coherent = 0;  ///< of those, pairs whose points lie within the distance
    /// @brief coherent / pairs (1 when there is no pair: nothing is torn).
    double value() const { return pairs ? double(coherent) / double(pairs) : 1.0; }
};

/// @brief Neighbours closer than this count as coherent (normalised units).
inline constexpr double kCoherenceDistance = 0.1;
/// @brief Pixels per side of the picture the measure is defined on (docs/measures.md, 2).
inline constexpr int kCoherenceResolution = 1000;

/// @brief The measure over a P layer: @a indirect marks the landed indirect pixels and @a points
///        their surface points, both width x height in row order. @a torn, when given, receives
///        width x height marks of the pixels in a pair that is not coherent (the tears). With
///        @a stride above 1, an estimate from a sample of the pairs: the pixels of every stride-th
///        row and column with their right and lower neighbours (only those pixels are read).
/// @throw ValueError for a stride below 1
Coherence mappingCoherence(const std::vector<char>& indirect, const std::vector<glm::vec3>& points, int width,
                           int height, double maxDistance = kCoherenceDistance, std::vector<char>* torn = nullptr,
                           int stride = 1);

/// @brief The measure over a render's layers ("region" and "P.X", "P.Y", "P.Z", as renderImage
///        writes them); @a torn as above.
Coherence mappingCoherence(const core::ImageLayers& layers, double maxDistance = kCoherenceDistance,
                           std::vector<char>* torn = nullptr);

/// @brief @a picture in grey with the pixels of @a torn (mappingCoherence's marks) in red: where a
///        picture tears.
core::Image tearMap(const core::Image& picture, const std::vector<char>& torn);

/// @brief The measure of @a method's picture from @a camera at @a resolution^2 pixel centres.
Coherence measureCoherence(const render::RenderScene& scene, const core::Camera& camera,
                           const render::MethodPtr& method, int resolution);

}  // namespace ivis::optimize
