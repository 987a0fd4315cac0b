#include <ivis/core/surface_field.h>

#include <ivis/core/errors.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace ivis::core {

void showStepData(SurfaceField& field, SurfaceField&& step)
{
    field.values = std::move(step.values);
    field.valuesOn = step.valuesOn;
    field.name = std::move(step.name);
    field.sourcePath = std::move(step.sourcePath);
    field.arrays = std::move(step.arrays);
    field.triangleCells = std::move(step.triangleCells);
}

Similarity normalizingTransform(const Bounds3& box)
{
    const glm::dvec3 size = box.hi - box.lo;
    const double extent = std::max({size.x, size.y, size.z});
    if (!(extent > 0.0) || !std::isfinite(extent)) throw ValueError("zero or non-finite extent");
    return {0.5 * (box.lo + box.hi), 2.0 / extent};
}

namespace {

/// Maps the positions by @a step and composes it into field.normalization, so that
/// meshFromNormalized still reaches the file's units.
void transformBy(SurfaceField& field, const Similarity& step)
{
    for (glm::vec3& p : field.mesh.positions) p = glm::vec3(step.normalizedFromMesh(glm::dvec3(p)));
    Similarity& total = field.normalization;
    total.center += step.center / total.scale;
    total.scale *= step.scale;
}

}  // namespace

void normalize(SurfaceField& field)
{
    Similarity step;
    try {
        step = normalizingTransform(bounds(field.mesh));
    } catch (const ValueError& e) {
        throw ValueError("normalize: mesh '" + field.sourcePath + "' has " + e.what());
    }
    transformBy(field, step);
}

void normalizeBy(SurfaceField& field, const Similarity& frame)
{
    // The frame maps the file's units; the positions are file units mapped by field.normalization.
    const Similarity& total = field.normalization;
    Similarity step;
    step.center = (frame.center - total.center) * total.scale;
    step.scale = frame.scale / total.scale;
    transformBy(field, step);
}

float scalarAt(const SurfaceField& field, std::size_t triangle, const glm::vec3& barycentric)
{
    if (!field.hasScalar() || field.mesh.isCap(triangle)) return std::numeric_limits<float>::quiet_NaN();
    const std::array<float, 3> v = cornerScalars(field, triangle);
    if (field.valuesOn == Association::Cell) return v[0];
    return barycentric.x * v[0] + barycentric.y * v[1] + barycentric.z * v[2];
}

std::array<float, 3> cornerScalars(const SurfaceField& field, std::size_t triangle)
{
    if (field.valuesOn == Association::Cell) {
        const float v = field.values[triangle];
        return {v, v, v};
    }
    const auto& t = field.mesh.triangles[triangle];
    return {field.values[t[0]], field.values[t[1]], field.values[t[2]]};
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

nlohmann::json meshUnitsJson(const Similarity& similarity)
{
    const glm::dvec3& c = similarity.center;
    return {{"center", {c.x, c.y, c.z}}, {"scale", similarity.scale}, {"mesh_from_normalised", "p / scale + center"}};
}

}  // namespace ivis::core
