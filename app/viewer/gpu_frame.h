/// @file gpu_frame.h
/// @brief What one frame of the GPU renderer shows: camera, size, method and look.
#pragma once

#include <ivis/core/camera.h>
#include <ivis/render/method_registry.h>
#include <ivis/render/shading.h>

namespace ivis::app {

/// @brief What one frame shows.
struct GpuFrame {
    core::Camera camera;
    int width = 0;   ///< pixels of the offscreen target
    int height = 0;
    render::MethodPtr method = render::defaultMethod();
    render::ShadingOptions shading;  ///< colormap name is applied by setColormap()
    bool outline = true;             ///< dark outline around the direct part (render::RenderOptions::outline)
};

}  // namespace ivis::app
