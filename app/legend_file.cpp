#include "legend_file.h"
#include "json_output.h"

#include <ivis/core/color_bar.h>
#include <ivis/core/file_extension.h>
#include <ivis/core/image_io.h>
#include <ivis/core/log.h>

namespace ivis::app {

void writeLegendFile(const std::string& path, const render::RenderOptions& options)
{
    const render::ShadingOptions& shading = options.shading;
    const core::ColorBarContent content{shading.colormap, shading.scale, options.scalarName, options.units};
    if (core::lowerCaseExtension(path) == ".svg") {
        writeTextFile(core::colorBarSvg(content, options.width, options.height, options.legendSide), path);
    } else {
        const glm::vec4 background = shading.transparentBackground ? glm::vec4(0.0f) : glm::vec4(shading.background, 1.0f);
        const core::Image image = core::colorBarImage(content, options.width, options.height, options.legendSide, background);
        core::writePng(image, path, shading.transparentBackground);
    }
    core::logInfo("wrote " + path);
}

}  // namespace ivis::app
