#include "legend_file.h"
#include "json_output.h"

#include <ivis/core/color_bar.h>
#include <ivis/core/errors.h>
#include <ivis/core/image_io.h>
#include <ivis/core/log.h>

#include <filesystem>

namespace ivis::app {

void checkLegendFileName(const std::string& path)
{
    const std::string extension = std::filesystem::path(path).extension().string();
    if (extension != ".svg" && extension != ".png") throw InputError(path + ": --legend-only writes .svg or .png");
}

void writeLegendFile(const std::string& path, const render::RenderOptions& options)
{
    const render::ShadingOptions& shading = options.shading;
    const core::ColorBarContent content{shading.colormap, shading.scale, options.scalarName, options.units};
    checkLegendFileName(path);
    if (std::filesystem::path(path).extension() == ".svg") {
        writeTextFile(core::colorBarSvg(content, options.width, options.height, options.legendSide), path);
    } else {
        const glm::vec4 background = shading.transparentBackground ? glm::vec4(0.0f) : glm::vec4(shading.background, 1.0f);
        const core::Image image = core::colorBarImage(content, options.width, options.height, options.legendSide, background);
        core::writePng(image, path, shading.transparentBackground);
    }
    core::logInfo("wrote " + path);
}

}  // namespace ivis::app
