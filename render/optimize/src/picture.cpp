#include <ivis/optimize/picture.h>

#include <ivis/core/log.h>
#include <ivis/core/number_text.h>
#include <ivis/render/framing.h>

#include <string>

namespace ivis::optimize {

core::Camera framedCamera(const render::RenderScene& scene, const core::Camera& camera, const render::Method& method,
                          int width, int height)
{
    bool fits = true;
    const core::Camera framed = render::frameView(scene, camera, method, double(width) / height, &fits);
    if (!fits)
        core::logWarning(method.name() + "'s picture from theta " + core::shortNumber(camera.angles().x) + " phi " +
                         core::shortNumber(camera.angles().y) + " does not fit the widest framed field of view; it is "
                         "cut at the frame");
    return framed;
}

Picture makePicture(const render::RenderScene& scene, const PictureRequest& request, core::Interrupter* interrupter)
{
    render::RenderOptions options = request.options;
    auto cameraFor = [&](const render::Method& method) {
        return request.framed ? framedCamera(scene, request.camera, method, options.width, options.height)
                              : request.camera;
    };
    Picture picture;
    picture.camera = cameraFor(*options.method);
    if (request.minCoherence > 0.0 && !options.method->info().readableRuleParameter.empty()) {
        const glm::ivec2 judged = readableRulePictureSize(options.width, options.height);
        picture.readable = loosestReadable(scene, picture.camera, options.method, judged, request.minCoherence);
        options.method = picture.readable->method;
        picture.camera = cameraFor(*options.method);  // the rule draws other rays: the picture's extent moves
    }
    picture.method = options.method;
    picture.result = render::renderImage(scene, picture.camera, options, interrupter);
    return picture;
}

}  // namespace ivis::optimize
