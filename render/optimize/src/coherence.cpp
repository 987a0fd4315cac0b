#include <ivis/optimize/coherence.h>

#include <ivis/core/errors.h>
#include <ivis/render/screen_map.h>

#include <glm/geometric.hpp>
#include <tbb/parallel_for.h>

namespace ivis::optimize {

Coherence mappingCoherence(const std::vector<char>& indirect, const std::vector<glm::vec3>& points, int width,
                           int height, double maxDistance, std::vector<char>* torn, int stride)
{
    if (stride < 1) throw ValueError("coherence needs a positive stride");
    Coherence result;
    const double limitSquared = maxDistance * maxDistance;
    if (torn) torn->assign(indirect.size(), 0);
    auto count = [&](std::size_t a, std::size_t b) {
        if (!indirect[a] || !indirect[b]) return;
        ++result.pairs;
        const glm::dvec3 d = glm::dvec3(points[a]) - glm::dvec3(points[b]);
        if (glm::dot(d, d) <= limitSquared) {
            ++result.coherent;
        } else if (torn) {
            (*torn)[a] = (*torn)[b] = 1;
        }
    };
    for (int y = 0; y < height; y += stride)
        for (int x = 0; x < width; x += stride) {
            const std::size_t i = std::size_t(y) * width + x;
            if (x + 1 < width) count(i, i + 1);
            if (y + 1 < height) count(i, i + std::size_t(width));
        }
    return result;
}

Coherence mappingCoherence(const core::ImageLayers& layers, double maxDistance, std::vector<char>* torn)
{
    const core::Channel& region = layers.channel("region");
    const core::Channel &x = layers.channel("P.X"), &y = layers.channel("P.Y"), &z = layers.channel("P.Z");
    std::vector<char> indirect(region.size());
    std::vector<glm::vec3> points(region.size());
    for (std::size_t i = 0; i < region.size(); ++i) {
        indirect[i] = region[i] == float(render::Region::Indirect);
        points[i] = {x[i], y[i], z[i]};
    }
    return mappingCoherence(indirect, points, layers.width(), layers.height(), maxDistance, torn);
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
