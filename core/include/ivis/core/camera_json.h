/// @file camera_json.h
/// @brief A camera as JSON: {"eye":[x,y,z],"target":[...],"up":[...],"fov_y_deg":f,
///        "orthographic":b,"ortho_half_height":f,"window_centre":[x,y]} (plus "theta_deg"/"phi_deg"
///        for reference), the format of --camera and --camera-out files and of a view file's
///        "camera".
#pragma once

#include <ivis/core/camera.h>
#include <ivis/core/similarity.h>

#include <nlohmann/json.hpp>

namespace ivis::core {

/// @brief The camera's JSON object.
nlohmann::json cameraToJson(const Camera& camera);

/// @brief What writeCameraJson writes: cameraToJson and the mesh's normalising transform
///        @a meshUnits ("mesh_units").
nlohmann::json cameraFileJson(const Camera& camera, const Similarity& meshUnits);

/// @brief The camera of a JSON object: "eye" is required, missing other keys keep their defaults.
/// @throw std::invalid_argument (or nlohmann::json's errors) for bad values; callers name the file
Camera cameraFromJson(const nlohmann::json& json);

}  // namespace ivis::core
