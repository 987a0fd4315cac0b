#include <ivis/optimize/picture_measure.h>

#include <ivis/core/errors.h>
#include <ivis/render/pixel_mapping.h>

#include <glm/vec3.hpp>

#include <utility>
#include <vector>

namespace ivis::optimize {

EnergyValue measurePicture(const EnergyEvaluator& evaluator, const core::ImageLayers& layers)
{
    const SurfaceVoxels* surface = evaluator.surfaceVoxels();
    if (!surface) throw ValueError("a picture's layers give the visibility measures, not the scalar energy");
    const core::Channel& region = layers.channel("region");
    const core::Channel &x = layers.channel("P.X"), &y = layers.channel("P.Y"), &z = layers.channel("P.Z");
    EnergyValue value;
    std::vector<std::uint64_t> directKeys, allKeys;
    for (std::size_t i = 0; i < region.size(); ++i) {
        const bool direct = region[i] == float(render::Region::Direct);
        if (!direct && region[i] != float(render::Region::Indirect)) continue;
        const std::uint64_t key = surface->keyOf(glm::vec3(x[i], y[i], z[i]));
        (direct ? value.pixelsDirect : value.pixelsIndirect)++;
        if (direct) directKeys.push_back(key);
        allKeys.push_back(key);
    }
    const SurfaceShare all = surface->shareSeen(allKeys);
    value.energy = all.area;
    value.voxelVisibility = all.voxels;
    value.front = surface->shareSeen(directKeys).area;
    if (const VisibilityGrid* literal = evaluator.literalGrid()) value.paperLiteral = literal->fractionVisited(allKeys);
    if (const RevealMeasure* reveal = evaluator.revealMeasure()) value.reveal = reveal->measure(directKeys, allKeys);
    value.seenVoxels = std::move(allKeys);
    return value;
}

}  // namespace ivis::optimize
