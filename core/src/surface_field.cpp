#include <ivis/core/surface_field.h>

#include <ivis/core/errors.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ivis::core {

void normalize(SurfaceField& field)
{
    const Bounds3 box = bounds(field.mesh);
    const glm::dvec3 size = box.hi - box.lo;
    const double extent = std::max({size.x, size.y, size.z});
    if (!(extent > 0.0) || !std::isfinite(extent)) {
        throw ValueError("normalize: mesh '" + field.sourcePath + "' has zero or non-finite extent");
    }
    const Similarity step{0.5 * (box.lo + box.hi), 2.0 / extent};
    for (glm::vec3& p : field.mesh.positions) {
        p = glm::vec3(step.normalizedFromMesh(glm::dvec3(p)));
    }
    // Compose with any earlier normalisation so meshFromNormalized still reaches file units.
    Similarity& total = field.normalization;
    total.center += step.center / total.scale;
    total.scale *= step.scale;
}

std::pair<float, float> finiteRange(const std::vector<float>& values)
{
    float lo = std::numeric_limits<float>::infinity();
    float hi = -lo;
    for (float v : values) {
        if (!std::isfinite(v)) continue;
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    if (lo > hi) return {0.0f, 0.0f};
    return {lo, hi};
}

}  // namespace ivis::core
