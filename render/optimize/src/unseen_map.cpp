#include <ivis/optimize/unseen_map.h>

#include <ivis/core/errors.h>
#include <ivis/render/framing.h>
#include <ivis/render/method_registry.h>

#include <glm/geometric.hpp>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace ivis::optimize {

core::Image unseenMap(const render::RenderScene& scene, const core::Camera& camera, const SurfaceVoxels& voxels,
                      const std::vector<std::uint64_t>& seen, int size)
{
    if (size < 8) throw ValueError("an unseen map needs at least 8 pixels per side");
    const render::MethodPtr front = render::makeMethod("front");
    core::Camera along = camera, opposite = camera;
    along.windowCentre = opposite.windowCentre = glm::dvec2(0.0);
    opposite.eye = 2.0 * camera.target - camera.eye;
    const core::Camera panels[2] = {render::frameView(scene, along, *front, 1.0),
                                    render::frameView(scene, opposite, *front, 1.0)};
    const std::vector<std::uint64_t>& surface = voxels.keys();
    core::Image map(2 * size, size);
    for (int panel = 0; panel < 2; ++panel) {
        const core::CameraFrame frame(panels[panel], size, size);
        tbb::parallel_for(0, size, [&](int y) {
            for (int x = 0; x < size; ++x) {
                const core::CameraRay ray = frame.ray(x + 0.5, y + 0.5);
                const glm::vec3 origin(ray.origin), direction(ray.direction);
                const core::RayHit hit = scene.bvh().intersect(origin, direction);
                glm::vec4& pixel = map.at(panel * size + x, y);
                if (!hit.hit()) {
                    pixel = glm::vec4(1.0f);
                    continue;
                }
                const float light = 0.1f + 0.5f * std::abs(glm::dot(hit.normal, direction));  // linear
                const std::uint64_t key = voxels.keyOf(origin + hit.t * direction);
                const bool unseen = std::binary_search(surface.begin(), surface.end(), key) &&
                                    !std::binary_search(seen.begin(), seen.end(), key);
                pixel = unseen ? glm::vec4(0.3f + light, 0.02f, 0.02f, 1.0f) : glm::vec4(glm::vec3(light), 1.0f);
            }
        });
    }
    return map;
}

}  // namespace ivis::optimize
