#include <ivis/core/ray_box.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace ivis::core {

bool rayBoxInterval(const glm::vec3& origin, const glm::vec3& direction, const Bounds3& box, float& tEnter,
                    float& tExit)
{
    tEnter = 0.0f;
    tExit = 1e30f;
    for (int a = 0; a < 3; ++a) {
        const float lo = float(box.lo[a]), hi = float(box.hi[a]);
        if (std::abs(direction[a]) < 1e-12f) {
            if (origin[a] < lo || origin[a] > hi) return false;
            continue;
        }
        float t0 = (lo - origin[a]) / direction[a], t1 = (hi - origin[a]) / direction[a];
        if (t0 > t1) std::swap(t0, t1);
        tEnter = std::max(tEnter, t0);
        tExit = std::min(tExit, t1);
    }
    return tEnter < tExit;
}

}  // namespace ivis::core
