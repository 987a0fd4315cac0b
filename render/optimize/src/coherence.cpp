#include <ivis/optimize/coherence.h>

#include <ivis/core/errors.h>
#include <ivis/render/screen_map.h>

#include <glm/geometric.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

namespace ivis::optimize {

namespace {

/// mappingCoherence over @a landed(i) and @a point(i), rows in parallel. Each pixel that starts a
/// counted pair marks which of its pairs tore (1: with its right neighbour, 2: with its lower one);
/// a pixel is torn where its own marks or its left neighbour's 1 or its upper neighbour's 2 are set.
template <typename Landed, typename Point>
Coherence countCoherentPairs(const Landed& landed, const Point& point, int width, int height, double maxDistance,
                             std::vector<char>* torn, int stride)
{
    if (stride < 1) throw ValueError("coherence needs a positive stride");
    const double limitSquared = maxDistance * maxDistance;
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    std::vector<char> marks(torn ? pixels : 0, 0);
    auto coherent = [&](std::size_t a, std::size_t b) {
        const glm::dvec3 d = glm::dvec3(point(a)) - glm::dvec3(point(b));
        return glm::dot(d, d) <= limitSquared;
    };
    const int rows = (height + stride - 1) / stride;
    const Coherence result = tbb::parallel_reduce(
        tbb::blocked_range<int>(0, rows, 16), Coherence{},
        [&](const tbb::blocked_range<int>& range, Coherence sum) {
            for (int r = range.begin(); r != range.end(); ++r) {
                const int y = r * stride;
                for (int x = 0; x < width; x += stride) {
                    const std::size_t i = std::size_t(y) * width + x;
                    if (!landed(i)) continue;
                    const std::size_t right = i + 1, below = i + std::size_t(width);
                    if (x + 1 < width && landed(right)) {
                        ++sum.pairs;
                        if (coherent(i, right)) ++sum.coherent;
                        else if (torn) marks[i] |= 1;
                    }
                    if (y + 1 < height && landed(below)) {
                        ++sum.pairs;
                        if (coherent(i, below)) ++sum.coherent;
                        else if (torn) marks[i] |= 2;
                    }
                }
            }
            return sum;
        },
        [](Coherence a, const Coherence& b) {
            a.pairs += b.pairs;
            a.coherent += b.coherent;
            return a;
        });
    if (torn) {
        torn->assign(pixels, 0);
        tbb::parallel_for(tbb::blocked_range<int>(0, height, 16), [&](const tbb::blocked_range<int>& range) {
            for (int y = range.begin(); y != range.end(); ++y)
                for (int x = 0; x < width; ++x) {
                    const std::size_t i = std::size_t(y) * width + x;
                    (*torn)[i] = marks[i] != 0 || (x > 0 && (marks[i - 1] & 1)) ||
                                 (y > 0 && (marks[i - std::size_t(width)] & 2));
                }
        });
    }
    return result;
}

}  // namespace

Coherence mappingCoherence(const std::vector<char>& indirect, const std::vector<glm::vec3>& points, int width,
                           int height, double maxDistance, std::vector<char>* torn, int stride)
{
    return countCoherentPairs([&](std::size_t i) { return indirect[i] != 0; },
                              [&](std::size_t i) { return points[i]; }, width, height, maxDistance, torn, stride);
}

Coherence mappingCoherence(const core::ImageLayers& layers, double maxDistance, std::vector<char>* torn)
{
    const core::Channel& region = layers.channel("region");
    const core::Channel &x = layers.channel("P.X"), &y = layers.channel("P.Y"), &z = layers.channel("P.Z");
    const float indirect = float(render::Region::Indirect);
    return countCoherentPairs([&](std::size_t i) { return region[i] == indirect; },
                              [&](std::size_t i) { return glm::vec3(x[i], y[i], z[i]); }, layers.width(),
                              layers.height(), maxDistance, torn, 1);
}

core::Image tearMap(const core::Image& picture, const std::vector<char>& torn)
{
    if (torn.size() != std::size_t(picture.width()) * std::size_t(picture.height()))
        throw ValueError("a tear map needs one mark per pixel of the picture");
    core::Image map(picture.width(), picture.height());
    for (int y = 0; y < picture.height(); ++y)
        for (int x = 0; x < picture.width(); ++x) {
            const glm::vec4& c = picture.at(x, y);
            const float grey = 0.25f + 0.5f * (0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b);
            map.at(x, y) = torn[std::size_t(y) * picture.width() + x] ? glm::vec4(1.0f, 0.0f, 0.0f, 1.0f)
                                                                         : glm::vec4(glm::vec3(grey), c.a);
        }
    return map;
}

Coherence measureCoherence(const render::RenderScene& scene, const core::Camera& camera,
                           const render::MethodPtr& method, int resolution)
{
    const core::CameraFrame frame(camera, resolution, resolution);
    const render::ScreenMap screen(scene, frame, method);
    const std::size_t pixels = std::size_t(resolution) * resolution;
    std::vector<char> indirect(pixels, 0);
    std::vector<glm::vec3> points(pixels);
    tbb::parallel_for(0, resolution, [&](int y) {
        render::DistanceField::Sampler sampler = scene.distance().sampler();
        std::vector<glm::dvec2> positions(static_cast<std::size_t>(resolution));
        for (int x = 0; x < resolution; ++x) positions[std::size_t(x)] = {x + 0.5, y + 0.5};
        std::vector<render::PixelMapping> row(positions.size());
        screen.mapMany(positions.data(), positions.size(), sampler, row.data());
        for (int x = 0; x < resolution; ++x) {
            const render::PixelMapping& m = row[std::size_t(x)];
            const std::size_t i = std::size_t(y) * resolution + x;
            indirect[i] = m.region == render::Region::Indirect;
            points[i] = m.point.position;
        }
    });
    return mappingCoherence(indirect, points, resolution, resolution);
}

}  // namespace ivis::optimize
