#include <ivis/render/method.h>

namespace ivis::render {

std::string ParameterSpec::option() const
{
    std::string option = "--" + key;
    for (char& c : option)
        if (c == '_') c = '-';
    return option;
}

const ParameterSpec* MethodInfo::parameter(const std::string& key) const
{
    for (const ParameterSpec& spec : parameters)
        if (spec.key == key) return &spec;
    return nullptr;
}

void IndirectMap::mapMany(const glm::dvec2* positions, std::size_t count, DistanceField::Sampler& sampler,
                          PixelMapping* mappings) const
{
    for (std::size_t i = 0; i < count; ++i) mappings[i] = map(positions[i].x, positions[i].y, sampler);
}

std::unique_ptr<IndirectMap> Method::indirectMap(const RenderScene& /*scene*/, const core::CameraFrame& /*frame*/) const
{
    return nullptr;
}

PictureExtent Method::pictureExtent(const RenderScene& scene, const core::Camera& camera) const
{
    return offsetMeshExtent(scene.vertices(), camera, 0.0);
}

}  // namespace ivis::render
