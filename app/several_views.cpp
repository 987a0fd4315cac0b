#include "several_views.h"

#include <ivis/core/color_bar.h>
#include <ivis/optimize/coherence.h>
#include <ivis/optimize/picture.h>
#include <ivis/optimize/picture_measure.h>
#include <ivis/optimize/view_set.h>
#include <ivis/render/method_json.h>

#include <algorithm>
#include <cstdio>

namespace ivis::app {
namespace {

/// The pictures side by side, @a gap pixels of @a background between them, top-aligned.
core::Image sideBySide(const std::vector<const core::Image*>& pictures, int gap, const glm::vec4& background)
{
    int width = gap * int(pictures.size() - 1), height = 0;
    for (const core::Image* picture : pictures) {
        width += picture->width();
        height = std::max(height, picture->height());
    }
    core::Image figure(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) figure.at(x, y) = background;
    int left = 0;
    for (const core::Image* picture : pictures) {
        for (int y = 0; y < picture->height(); ++y)
            for (int x = 0; x < picture->width(); ++x) figure.at(left + x, y) = picture->at(x, y);
        left += picture->width() + gap;
    }
    return figure;
}

/// "0.959" for a share.
std::string figure3(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", value);
    return text;
}

}  // namespace

SeveralViews renderSeveralViews(const render::RenderScene& scene, const optimize::AnnealingResult& result,
                                const optimize::EnergyEvaluator& evaluator, const optimize::EnergyEvaluator& measure,
                                const optimize::AnnealingOptions& annealing, bool framed,
                                const render::RenderOptions& options, const core::Camera& bestCamera,
                                const render::RenderResult& bestPicture, int count)
{
    SeveralViews set;
    for (const optimize::ReadableView& chosen : optimize::chooseReadableViewSet(result, evaluator, annealing, count)) {
        ChosenView& current = set.views.emplace_back();
        if (chosen.index == result.best) {  // as the annealing made it readable and the command drew it
            current.camera = bestCamera;
            current.method = options.method;
            current.picture = bestPicture;
            continue;
        }
        const core::Camera& camera = result.visited[chosen.index].camera;
        current.method = chosen.method;
        current.camera = framed ? optimize::framedCamera(scene, camera, *current.method, options.width, options.height) : camera;
        render::RenderOptions look = options;
        look.method = current.method;
        current.picture = render::renderImage(scene, current.camera, look);
    }

    std::vector<std::uint64_t> together;
    std::vector<const core::Image*> pictures;
    set.json["views"] = nlohmann::json::array();
    std::string each;
    for (const ChosenView& current : set.views) {
        const optimize::EnergyValue value = optimize::measurePicture(measure, current.picture.layers);
        const double coherence = optimize::mappingCoherence(current.picture.layers).value();
        const glm::dvec2 angles = current.camera.angles();
        set.json["views"].push_back({{"theta", angles.x},
                                     {"phi", angles.y},
                                     {"fov_y_deg", current.camera.fovYDeg},
                                     {"params", render::methodToJson(*current.method)},
                                     {"visibility", value.energy},
                                     {"coherence", coherence}});
        each += (each.empty() ? "" : ", ") + figure3(value.energy) + " at coherence " + figure3(coherence);
        together.insert(together.end(), value.seenVoxels.begin(), value.seenVoxels.end());
        pictures.push_back(&current.picture.image);
    }
    const optimize::SurfaceShare share = measure.surfaceVoxels()->shareSeen(together);
    set.json["union"] = {{"visibility", share.area}, {"voxel_visibility", share.voxels}};
    set.line = std::to_string(set.views.size()) + " views: together surface visibility " + figure3(share.area) +
               " (by voxel count " + figure3(share.voxels) + "); each " + each;

    const render::ShadingOptions& shading = options.shading;
    const glm::vec4 background = shading.transparentBackground ? glm::vec4(0.0f) : glm::vec4(shading.background, 1.0f);
    set.figure = sideBySide(pictures, std::max(4, options.width / 50), background);
    if (options.legend && scene.field().hasScalar())
        set.figure = core::withColorBar(set.figure, {shading.colormap, shading.scale, options.scalarName, options.units},
                                        options.legendSide, background, options.legendMinimumMargin);
    return set;
}

}  // namespace ivis::app
