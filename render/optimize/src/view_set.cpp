#include <ivis/optimize/view_set.h>

#include <ivis/core/errors.h>
#include <ivis/optimize/readable_rule.h>

#include <algorithm>

namespace ivis::optimize {

std::vector<std::size_t> chooseViewSet(const std::vector<VisitedView>& views, std::size_t first,
                                       const SurfaceVoxels& surface, int count)
{
    if (count < 1) throw ValueError("a view set needs at least one view");
    if (first >= views.size()) throw ValueError("the first view of a view set is not among the visited views");
    std::vector<std::uint64_t> seen;  // sorted keys of the voxels the chosen views show
    auto add = [&](std::size_t v) {
        const std::vector<std::uint64_t>& keys = views[v].value.seenVoxels;
        std::vector<std::uint64_t> merged;
        std::set_union(seen.begin(), seen.end(), keys.begin(), keys.end(), std::back_inserter(merged));
        seen.swap(merged);
    };
    std::vector<std::size_t> chosen{first};
    add(first);
    while (int(chosen.size()) < count) {
        double bestGain = 0.0;
        std::size_t best = views.size();
        for (std::size_t v = 0; v < views.size(); ++v) {
            if (std::find(chosen.begin(), chosen.end(), v) != chosen.end()) continue;
            double gain = 0.0;
            for (std::uint64_t key : views[v].value.seenVoxels)
                if (!std::binary_search(seen.begin(), seen.end(), key)) gain += surface.areaIn(key);
            if (gain > bestGain) bestGain = gain, best = v;
        }
        if (best == views.size()) break;
        chosen.push_back(best);
        add(best);
    }
    return chosen;
}

std::vector<ReadableView> chooseReadableViewSet(const AnnealingResult& result, const EnergyEvaluator& evaluator,
                                                const AnnealingOptions& options, int count)
{
    if (!evaluator.surfaceVoxels())
        throw ValueError("several views are chosen by the surface they show together: they need the visibility energy");
    std::vector<ReadableView> set;
    for (std::size_t index : chooseViewSet(result.visited, result.best, *evaluator.surfaceVoxels(), count)) {
        const VisitedView& view = result.visited[index];
        render::MethodPtr method = view.method;
        if (index != result.best && options.readableResolution > 0 && !method->info().readableRuleParameter.empty())
            method = loosestReadable(evaluator.scene(), view.camera, method,
                                     {options.readableResolution, options.readableResolution}, options.minCoherence)
                         .method;
        set.push_back({index, method});
    }
    return set;
}

}  // namespace ivis::optimize
