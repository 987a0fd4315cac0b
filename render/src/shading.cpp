#include <ivis/render/shading.h>

#include <ivis/render/shadow.h>

#include <glm/geometric.hpp>

#include <cmath>

namespace ivis::render {

Shader::Shader(const RenderScene& scene, const core::CameraFrame& frame, const ShadingOptions& options)
    : mScene(scene),
      mOptions(options),
      mColormap(core::colormap(options.colormap)),
      mToLight(glm::normalize(glm::vec3(-0.35 * frame.right() + 0.55 * frame.upVector() - 0.75 * frame.forward())))
{
}

glm::vec3 Shader::albedo(const SurfacePoint& point, bool& isNan) const
{
    isNan = false;
    const core::SurfaceField& field = mScene.field();
    if (!field.hasScalar() || field.mesh.isCap(std::size_t(point.triangle))) return mOptions.noDataColour;
    const float value = scalarAt(field, point);
    if (std::isnan(value)) {
        isNan = true;
        return mOptions.nanColour;
    }
    return mColormap.at(mOptions.range.normalized(value));
}

glm::vec4 Shader::shade(const PixelMapping& mapping, DistanceField::Sampler& sampler, bool& isNan) const
{
    isNan = false;
    if (mapping.region == Region::Background)
        return mOptions.transparentBackground ? glm::vec4(0.0f) : glm::vec4(mOptions.background, 1.0f);

    const glm::vec3 base = albedo(mapping.point, isNan);
    glm::vec3 normal = shadingNormal(mScene.mesh(), mScene.normals(), mapping.point);
    if (glm::dot(normal, mapping.arrival) > 0.0f) normal = -normal;  // the side the point is seen from

    if (mapping.region == Region::Indirect) {
        const float facing = -glm::dot(normal, mapping.arrival);
        return glm::vec4(base * mOptions.indirectBrightness * (0.7f + 0.3f * facing), 1.0f);
    }
    float diffuse = std::max(0.0f, glm::dot(normal, mToLight));
    if (diffuse > 0.0f && mOptions.shadows)
        diffuse *= shadowFactor(sampler, mapping.point.position, normal, mToLight);
    return glm::vec4(base * (mOptions.ambient + (1.0f - mOptions.ambient) * diffuse), 1.0f);
}

}  // namespace ivis::render
