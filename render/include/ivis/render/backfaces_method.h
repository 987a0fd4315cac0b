/// @file backfaces_method.h
/// @brief The `backfaces` method: only the faces turned away from the camera (paper Fig. 1b); the pixels that miss stay background.
#pragma once

#include <ivis/render/method.h>

namespace ivis::render {

/// @brief Description of `backfaces` (no parameters).
const MethodInfo& backfacesMethodInfo();

}  // namespace ivis::render
