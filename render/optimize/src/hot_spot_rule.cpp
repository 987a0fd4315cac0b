#include <ivis/optimize/hot_spot_rule.h>

#include <ivis/core/errors.h>
#include <ivis/core/sphere_lattice.h>
#include <ivis/optimize/picture_measure.h>
#include <ivis/optimize/readable_rule.h>
#include <ivis/optimize/viewpoint_annealing.h>
#include <ivis/render/method_registry.h>
#include <ivis/render/renderer.h>

#include <nlohmann/json.hpp>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

namespace ivis::optimize {

double hotSpotShortfall(const std::vector<double>& seen, const std::vector<HotSpotShape>& shapes)
{
    if (seen.empty() || seen.size() != shapes.size()) return 1.0;
    double shortfall = 0.0;
    for (std::size_t i = 0; i < seen.size(); ++i)
        for (const double part : {(kMinHotSpotSeen - seen[i]) / kMinHotSpotSeen,
                                  (kMinHotSpotShare - shapes[i].largestShare) / kMinHotSpotShare,
                                  (shapes[i].outlineRatio - kMaxHotSpotOutline) / kMaxHotSpotOutline}) {
            if (std::isnan(part)) return 1.0;
            shortfall = std::max(shortfall, part);
        }
    return shortfall;
}

bool hotSpotsReadAsOnePlace(const std::vector<double>& seen, const std::vector<HotSpotShape>& shapes)
{
    return !seen.empty() && seen.size() == shapes.size() && hotSpotShortfall(seen, shapes) == 0.0;
}

std::vector<HotSpotFacing> hotSpotFacings(const core::TriangleMesh& mesh, const RevealMeasure& reveal)
{
    std::vector<glm::dvec3> weighted(reveal.regionCount()), centroid(reveal.regionCount());
    std::vector<double> area(reveal.regionCount(), 0.0);
    for (const auto& t : mesh.triangles) {
        const glm::dvec3 a(mesh.positions[t[0]]), b(mesh.positions[t[1]]), c(mesh.positions[t[2]]);
        const glm::dvec3 centre = (a + b + c) / 3.0;
        const int region = reveal.regionAt(glm::vec3(centre));
        if (region < 0) continue;
        const glm::dvec3 normal = 0.5 * glm::cross(b - a, c - a);  // its length the triangle's area
        weighted[std::size_t(region)] += normal;
        const double triangleArea = glm::length(normal);
        centroid[std::size_t(region)] += triangleArea * centre;
        area[std::size_t(region)] += triangleArea;
    }
    std::vector<HotSpotFacing> facings(reveal.regionCount());
    for (std::size_t r = 0; r < facings.size(); ++r) {
        if (!(area[r] > 0.0)) continue;
        facings[r].centroid = centroid[r] / area[r];
        const double length = glm::length(weighted[r]);
        if (length >= kMinHotSpotFacing * area[r]) facings[r].normal = weighted[r] / length;
    }
    return facings;
}

bool someHotSpotFacesAway(const std::vector<HotSpotFacing>& facings, const core::Camera& camera)
{
    const double cosine = std::cos(glm::radians(kHotSpotFacingAwayDeg));
    return std::any_of(facings.begin(), facings.end(), [&](const HotSpotFacing& f) {
        const glm::dvec3 toSpot = f.centroid - camera.eye;
        const double length = glm::length(toSpot);
        return length > 0.0 && glm::dot(f.normal, toSpot) > cosine * length;
    });
}

std::vector<std::array<double, 2>> sideOnViews(const std::vector<HotSpotFacing>& facings, int count)
{
    // The direction each hot spot should lie square to: its mean normal; for one that faces no one
    // way, its direction from the hot spots' common centre (where it lies at the silhouette).
    glm::dvec3 centre(0.0);
    for (const HotSpotFacing& f : facings) centre += f.centroid / double(facings.size());
    std::vector<glm::dvec3> squareTo;
    for (const HotSpotFacing& f : facings) {
        const double fromCentre = glm::length(f.centroid - centre);
        if (f.normal != glm::dvec3(0.0)) squareTo.push_back(f.normal);
        else if (fromCentre > 0.0) squareTo.push_back((f.centroid - centre) / fromCentre);
        else squareTo.push_back(glm::dvec3(0.0));
    }
    const auto hasDirection = [](const glm::dvec3& d) { return d != glm::dvec3(0.0); };
    if (std::none_of(squareTo.begin(), squareTo.end(), hasDirection)) return {};
    // Each lattice direction's largest angle off square over the hot spots with a direction.
    std::vector<std::pair<double, std::array<double, 2>>> candidates;
    for (int i = 0; i < kSideOnLatticeViews; ++i) {
        core::Camera camera;
        camera.eye = core::kCameraDistance * core::fibonacciDirection(i, kSideOnLatticeViews);
        double offSquare = 0.0;
        for (std::size_t h = 0; h < facings.size(); ++h) {
            if (!hasDirection(squareTo[h])) continue;
            const double sine = std::abs(glm::dot(squareTo[h], glm::normalize(facings[h].centroid - camera.eye)));
            offSquare = std::max(offSquare, glm::degrees(std::asin(std::min(1.0, sine))));
        }
        if (offSquare > kSideOnDeg) continue;
        const glm::dvec2 angles = camera.angles();
        candidates.push_back({offSquare, {angles.x, angles.y}});
    }
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<std::array<double, 2>> views;
    for (const auto& candidate : candidates) {  // not a structured binding: C++17 lambdas cannot capture one
        const std::array<double, 2>& view = candidate.second;
        if (int(views.size()) >= count) break;
        if (std::none_of(views.begin(), views.end(), [&](const std::array<double, 2>& v) {
                return degreesBetweenViews(view[0], view[1], v[0], v[1]) < kHotSpotViewSeparationDeg;
            }))
            views.push_back(view);
    }
    return views;
}

std::vector<CandidateView> viewsRoundTheNearest(const VisitedView& nearest)
{
    std::vector<CandidateView> views;
    const std::string& parameter = nearest.method->info().readableRuleParameter;
    const std::vector<float> ladder = readableRuleLadder(*nearest.method);
    if (!ladder.empty() && ladder.front() < nearest.method->values().at(parameter).at(0))
        views.push_back({nearest.thetaDeg, nearest.phiDeg, render::withValues(*nearest.method, {{parameter, {ladder.front()}}})});
    for (int dTheta = -1; dTheta <= 1; ++dTheta)
        for (int dPhi = -1; dPhi <= 1; ++dPhi) {
            if (dTheta == 0 && dPhi == 0) continue;
            CandidateView view{nearest.thetaDeg + dTheta * kHotSpotNeighbourDeg,
                               nearest.phiDeg + dPhi * kHotSpotNeighbourDeg, nearest.method};
            wrapViewAngles(view.thetaDeg, view.phiDeg);
            views.push_back(view);
        }
    return views;
}

namespace {

/// The hot spots' shapes and reveal in @a method's @a size x @a size picture from @a camera.
std::pair<EnergyValue, std::vector<HotSpotShape>> hotSpotsIn(const EnergyEvaluator& measure, const core::Camera& camera,
                                                             const render::MethodPtr& method, int size)
{
    render::RenderOptions options;
    options.width = options.height = size;
    options.method = method;
    // Only the layers are judged: no shadow rays, outline or colour bar (the layers are the same).
    options.shading.shadows = false;
    options.outline = options.legend = false;
    const render::RenderResult picture = render::renderImage(measure.scene(), camera, options);
    return {measurePicture(measure, picture.layers), hotSpotShapes(*measure.revealMeasure(), picture.layers)};
}

}  // namespace

bool hotSpotsReadIn(const EnergyEvaluator& measure, const core::Camera& camera, const render::MethodPtr& method, int size)
{
    if (!measure.revealMeasure()) throw ValueError("judging hot spots needs a measure of the hot-spot reveal");
    const auto [value, shapes] = hotSpotsIn(measure, camera, method, size);
    return hotSpotsReadAsOnePlace(value.reveal.perRegion, shapes);
}

HotSpotChoice chooseHotSpotView(const std::vector<VisitedView>& visited, std::size_t best, const EnergyEvaluator& measure,
                                int views, core::Interrupter* interrupter, std::size_t from, double separationDeg)
{
    if (!measure.revealMeasure())
        throw ValueError("the hot-spot rule needs a measure of the hot-spot reveal (a scalar with important regions)");
    IVIS_CHECK(best < visited.size() && from <= visited.size());
    std::vector<std::size_t> order(visited.size() - from);
    std::iota(order.begin(), order.end(), from);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return (a == best) != (b == best) ? a == best : visited[a].value.energy > visited[b].value.energy;
    });
    const std::vector<HotSpotFacing> facings = hotSpotFacings(measure.scene().mesh(), *measure.revealMeasure());
    HotSpotChoice choice;
    std::vector<std::size_t> judged;
    for (const std::size_t index : order) {
        if (int(judged.size()) >= views) break;
        const VisitedView& view = visited[index];
        if (someHotSpotFacesAway(facings, view.camera)) continue;
        if (std::any_of(judged.begin(), judged.end(), [&](std::size_t j) {
                return degreesBetweenViews(view.thetaDeg, view.phiDeg, visited[j].thetaDeg, visited[j].phiDeg) <
                       separationDeg;
            }))
            continue;
        if (interrupter && interrupter->wasInterrupted()) throw Cancelled("hot-spot rule cancelled");
        judged.push_back(index);
        auto [value, shapes] = hotSpotsIn(measure, view.camera, view.method, kHotSpotPictureSize);
        const double shortfall = hotSpotShortfall(value.reveal.perRegion, shapes);
        if (choice.chosen && !(shortfall < choice.shortfall)) continue;  // no nearer than one judged before
        const double bestEnergy = visited[best].value.energy;
        choice.chosen = index;
        choice.reads = shortfall == 0.0;
        choice.shortfall = shortfall;
        choice.shapes = std::move(shapes);
        choice.energyRatio = bestEnergy > 0.0 ? view.value.energy / bestEnergy : 1.0;
        if (choice.reads) break;
    }
    choice.judged = int(judged.size());
    return choice;
}

HotSpotChoice betterHotSpotChoice(const HotSpotChoice& first, const HotSpotChoice& second)
{
    HotSpotChoice better = second.chosen && (!first.chosen || second.shortfall < first.shortfall) ? second : first;
    better.judged = first.judged + second.judged;
    return better;
}

nlohmann::json hotSpotChoiceJson(const HotSpotChoice& choice)
{
    return {{"judged", choice.judged},
            {"chosen_view", choice.chosen ? nlohmann::json(*choice.chosen) : nlohmann::json()},
            {"reads", choice.reads},
            {"shortfall", choice.shortfall},
            {"energy_ratio", choice.energyRatio},
            {"shapes", hotSpotShapesJson(choice.shapes)}};
}

}  // namespace ivis::optimize
