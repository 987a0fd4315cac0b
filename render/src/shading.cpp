#include <ivis/render/shading.h>

#include <ivis/render/curved_ray.h>
#include <ivis/render/shadow.h>

#include <glm/geometric.hpp>

#include <cmath>

namespace ivis::render {

Shader::Shader(const RenderScene& scene, const core::CameraFrame& frame, const ShadingOptions& options,
               const Method& method)
    : mScene(scene),
      mOptions(options),
      mColormap(core::colormap(options.colormap)),
      mToLight(glm::normalize(glm::vec3(kKeyLightRight * frame.right() + kKeyLightUp * frame.upVector() +
                                        kKeyLightForward * frame.forward()))),
      mUp(frame.upVector()),
      mRight(frame.right()),
      mIndirectShadows(options.shadows && method.indirectRaysArriveFromOutside()),
      mSurfaceBox(hullBounds(scene.bounds(), 0.0f, scene.distance().voxelSize()))
{
}

glm::vec3 Shader::toLightAlong(const glm::vec3& arrival) const
{
    // The key light placed for a camera looking along the arrival, upright like the real one.
    glm::vec3 right = glm::cross(arrival, mUp);
    right = glm::length(right) > 1e-3f ? glm::normalize(right) : mRight;
    const glm::vec3 up = glm::cross(right, arrival);
    return glm::normalize(float(kKeyLightRight) * right + float(kKeyLightUp) * up + float(kKeyLightForward) * arrival);
}

float Shader::lighting(const glm::vec3& position, const glm::vec3& normal, const glm::vec3& toLight, bool shadows,
                       DistanceField::Sampler& sampler) const
{
    float diffuse = std::max(0.0f, glm::dot(normal, toLight));
    if (diffuse > 0.0f && shadows) diffuse *= shadowFactor(sampler, position, normal, toLight, mSurfaceBox);
    return mOptions.ambient + (1.0f - mOptions.ambient) * diffuse;
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
    return mColormap.at(mOptions.scale.position(value));
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
        // Lit as a camera looking along the arriving ray would light it, so the back side's
        // folds and ridges show; dimmed so that it reads as behind. Unshaded, the colour bar's own
        // colour, to be read against it.
        const float light = mOptions.shadeIndirect
                                ? lighting(mapping.point.position, normal, toLightAlong(mapping.arrival),
                                           mIndirectShadows, sampler)
                                : 1.0f;
        const float brightness = mOptions.shadeIndirect ? mOptions.indirectBrightness : 1.0f;
        return glm::vec4(base * brightness * light, 1.0f);
    }
    return glm::vec4(base * lighting(mapping.point.position, normal, mToLight, mOptions.shadows, sampler), 1.0f);
}

}  // namespace ivis::render
