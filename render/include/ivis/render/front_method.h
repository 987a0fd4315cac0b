/// @file front_method.h
/// @brief The `front` method: plain rendering of the faces the view rays hit (paper Fig. 1a); the pixels that miss stay background.
#pragma once

#include <ivis/render/method.h>

namespace ivis::render {

/// @brief Description of `front` (no parameters).
const MethodInfo& frontMethodInfo();

}  // namespace ivis::render
