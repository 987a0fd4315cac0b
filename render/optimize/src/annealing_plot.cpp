#include <ivis/optimize/annealing_plot.h>

#include <ivis/core/colormap.h>
#include <ivis/core/errors.h>
#include <ivis/core/font.h>

#include <algorithm>
#include <cmath>

namespace ivis::optimize {
namespace {

/// Fills a disc (or a ring of the given width) of colour @a colour.
void drawDisc(core::Image& image, double cx, double cy, double radius, const glm::vec3& colour, double ringWidth = 0.0)
{
    for (int y = int(cy - radius) - 1; y <= int(cy + radius) + 1; ++y)
        for (int x = int(cx - radius) - 1; x <= int(cx + radius) + 1; ++x) {
            const double r = std::hypot(x + 0.5 - cx, y + 0.5 - cy);
            if (r <= radius && (ringWidth <= 0.0 || r >= radius - ringWidth)) image.blendOver(x, y, colour);
        }
}

}  // namespace

core::Image plotVisitedViews(const AnnealingResult& result, int size)
{
    if (size < 64) throw ValueError("plot size must be at least 64 pixels");
    core::Image image(2 * size, size, glm::vec4(1.0f));
    const double radius = 0.42 * size;
    const double centres[2] = {0.5 * size, 1.5 * size};
    // Two shaded hemispheres.
    for (int side = 0; side < 2; ++side)
        for (int y = 0; y < size; ++y)
            for (int x = side * size; x < (side + 1) * size; ++x) {
                const double u = (x + 0.5 - centres[side]) / radius, v = (y + 0.5 - 0.5 * size) / radius;
                const double rr = u * u + v * v;
                if (rr <= 1.0) image.blendOver(x, y, glm::vec3(float(0.75 + 0.2 * std::sqrt(1.0 - rr))));
            }
    double lo = 1e30, hi = -1e30;
    for (const VisitedView& v : result.visited) {
        lo = std::min(lo, v.value.energy);
        hi = std::max(hi, v.value.energy);
    }
    const core::Colormap& map = core::colormap("viridis");
    auto place = [&](const VisitedView& v, double& px, double& py) {
        const double t = v.thetaDeg * M_PI / 180.0, p = v.phiDeg * M_PI / 180.0;
        const double x = std::sin(t) * std::sin(p), y = std::cos(t), z = std::sin(t) * std::cos(p);
        const int side = z >= 0.0 ? 0 : 1;
        px = centres[side] + (side == 0 ? x : -x) * radius;  // the back is seen from behind
        py = 0.5 * size - y * radius;
    };
    for (const VisitedView& v : result.visited) {
        double px, py;
        place(v, px, py);
        const float t = hi > lo ? float((v.value.energy - lo) / (hi - lo)) : 0.5f;
        drawDisc(image, px, py, size / 70.0, map.at(t));
    }
    double bx, by;
    place(result.bestView(), bx, by);
    drawDisc(image, bx, by, size / 35.0, glm::vec3(0.9f, 0.05f, 0.05f), size / 150.0 + 1.0);
    const int fontPixels = std::max(12, size / 25);
    const core::Font& font = core::Font::standard();
    font.draw(image, int(centres[0] - radius), fontPixels * 3 / 2, "front (+z)", glm::vec3(0.15f), fontPixels);
    font.draw(image, int(centres[1] - radius), fontPixels * 3 / 2, "back (−z)", glm::vec3(0.15f), fontPixels);
    return image;
}

}  // namespace ivis::optimize
