#include <ivis/optimize/hot_spot_shape.h>

#include <ivis/render/pixel_mapping.h>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace ivis::optimize {
namespace {

/// Perimeter of the convex hull of @a points (Andrew's monotone chain; @a points is reordered).
double hullPerimeter(std::vector<glm::ivec2>& points)
{
    std::sort(points.begin(), points.end(), [](const glm::ivec2& a, const glm::ivec2& b) {
        return a.x != b.x ? a.x < b.x : a.y < b.y;
    });
    points.erase(std::unique(points.begin(), points.end()), points.end());
    if (points.size() < 2) return 0.0;
    auto turn = [](const glm::ivec2& o, const glm::ivec2& a, const glm::ivec2& b) {
        return std::int64_t(a.x - o.x) * (b.y - o.y) - std::int64_t(a.y - o.y) * (b.x - o.x);
    };
    std::vector<glm::ivec2> hull(2 * points.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {  // lower chain
        while (k >= 2 && turn(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
        hull[k++] = points[i];
    }
    for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {  // upper chain
        while (k >= lower && turn(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
        hull[k++] = points[i];
    }
    double perimeter = 0.0;
    for (std::size_t i = 0; i + 1 < k; ++i) perimeter += std::hypot(double(hull[i + 1].x - hull[i].x), double(hull[i + 1].y - hull[i].y));
    return perimeter;
}

/// The shape of the pixels of @a width x @a height whose @a label equals @a which.
HotSpotShape shapeOf(const std::vector<int>& label, int which, int width, int height)
{
    HotSpotShape shape;
    auto at = [&](int x, int y) { return x >= 0 && y >= 0 && x < width && y < height && label[std::size_t(y) * width + x] == which; };
    std::vector<char> visited(label.size(), 0);
    std::vector<std::size_t> largest, component;
    for (std::size_t seed = 0; seed < label.size(); ++seed) {
        if (label[seed] != which) continue;
        ++shape.pixels;
        if (visited[seed]) continue;
        visited[seed] = 1;
        component.assign(1, seed);
        for (std::size_t next = 0; next < component.size(); ++next) {
            const int x = int(component[next] % std::size_t(width)), y = int(component[next] / std::size_t(width));
            for (const glm::ivec2 step : {glm::ivec2(1, 0), glm::ivec2(-1, 0), glm::ivec2(0, 1), glm::ivec2(0, -1)}) {
                if (!at(x + step.x, y + step.y)) continue;
                const std::size_t index = std::size_t(y + step.y) * width + std::size_t(x + step.x);
                if (!visited[index]) {
                    visited[index] = 1;
                    component.push_back(index);
                }
            }
        }
        if (component.size() > largest.size()) largest.swap(component);
    }
    if (largest.empty()) return shape;
    shape.largestShare = double(largest.size()) / double(shape.pixels);
    std::vector<int> inLargest(label.size(), 0);
    for (std::size_t index : largest) inLargest[index] = 1;
    auto inside = [&](int x, int y) { return x >= 0 && y >= 0 && x < width && y < height && inLargest[std::size_t(y) * width + x]; };
    std::size_t outline = 0;
    std::vector<glm::ivec2> corners;
    for (std::size_t index : largest) {
        const int x = int(index % std::size_t(width)), y = int(index / std::size_t(width));
        const int open = !inside(x + 1, y) + !inside(x - 1, y) + !inside(x, y + 1) + !inside(x, y - 1);
        outline += std::size_t(open);
        if (open)
            for (const glm::ivec2 corner : {glm::ivec2(x, y), glm::ivec2(x + 1, y), glm::ivec2(x, y + 1), glm::ivec2(x + 1, y + 1)})
                corners.push_back(corner);
    }
    shape.outlineRatio = double(outline) / hullPerimeter(corners);
    return shape;
}

}  // namespace

std::vector<HotSpotShape> hotSpotShapes(const RevealMeasure& reveal, const core::ImageLayers& layers)
{
    const core::Channel& region = layers.channel("region");
    const core::Channel &x = layers.channel("P.X"), &y = layers.channel("P.Y"), &z = layers.channel("P.Z");
    const core::Channel& scalar = layers.channel("scalar");
    std::vector<int> label(region.size(), -1);
    for (std::size_t i = 0; i < region.size(); ++i) {
        const bool shown = region[i] == float(render::Region::Direct) || region[i] == float(render::Region::Indirect);
        if (shown && reveal.important(scalar[i])) label[i] = reveal.regionAt(glm::vec3(x[i], y[i], z[i]));
    }
    std::vector<HotSpotShape> shapes;
    for (std::size_t r = 0; r < reveal.regionCount(); ++r)
        shapes.push_back(shapeOf(label, int(r), layers.width(), layers.height()));
    return shapes;
}

nlohmann::json hotSpotShapesJson(const std::vector<HotSpotShape>& shapes)
{
    nlohmann::json json = nlohmann::json::array();
    for (const HotSpotShape& shape : shapes)
        json.push_back({{"pixels", shape.pixels}, {"largest_share", shape.largestShare}, {"outline_ratio", shape.outlineRatio}});
    return json;
}

}  // namespace ivis::optimize
