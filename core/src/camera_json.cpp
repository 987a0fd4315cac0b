#include <ivis/core/camera_json.h>

#include <ivis/core/atomic_file.h>
#include <ivis/core/errors.h>
#include <ivis/core/file_bytes.h>
#include <ivis/core/json_text.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <type_traits>

namespace ivis::core {
namespace {

/// The N-component vector under @a key ([x, y] or [x, y, z]), or @a fallback when there is none.
template <glm::length_t N>
glm::vec<N, double> readVector(const nlohmann::json& json, const char* key, const glm::vec<N, double>& fallback)
{
    if (!json.contains(key)) return fallback;
    const auto& v = json.at(key);
    if (!v.is_array() || v.size() != N || !std::all_of(v.begin(), v.end(), [](const auto& c) { return c.is_number(); }))
        throw std::invalid_argument(std::string("'") + key + "' must be " + (N == 2 ? "[x, y]" : "[x, y, z]") +
                                    " of numbers");
    glm::vec<N, double> vector;
    for (glm::length_t i = 0; i < N; ++i) vector[i] = v[i].get<double>();
    return vector;
}

/// The number (or, for a bool @a fallback, true or false) under @a key, or @a fallback when there is none.
template <typename T>
T readValue(const nlohmann::json& json, const char* key, T fallback)
{
    if (!json.contains(key)) return fallback;
    const nlohmann::json& v = json.at(key);
    if (std::is_same_v<T, bool> ? !v.is_boolean() : !v.is_number())
        throw std::invalid_argument(std::string("'") + key + "' must be " +
                                    (std::is_same_v<T, bool> ? "true or false" : "a number"));
    return v.get<T>();
}

}  // namespace

nlohmann::json cameraToJson(const Camera& camera)
{
    const glm::dvec2 angles = camera.angles();
    return {{"eye", {camera.eye.x, camera.eye.y, camera.eye.z}},
            {"target", {camera.target.x, camera.target.y, camera.target.z}},
            {"up", {camera.up.x, camera.up.y, camera.up.z}},
            {"fov_y_deg", camera.fovYDeg},
            {"orthographic", camera.orthographic},
            {"ortho_half_height", camera.orthoHalfHeight},
            {"window_centre", {camera.windowCentre.x, camera.windowCentre.y}},
            {"theta_deg", angles.x},
            {"phi_deg", angles.y}};
}

Camera cameraFromJson(const nlohmann::json& json)
{
    if (!json.is_object()) throw std::invalid_argument("expected a JSON object");
    if (json.contains("inversevis_view")) throw std::invalid_argument("a view file, not a camera file: give it with --view");
    if (!json.contains("eye")) throw std::invalid_argument("no 'eye', the camera's position");
    Camera camera;
    camera.eye = readVector(json, "eye", camera.eye);
    camera.target = readVector(json, "target", camera.target);
    camera.up = readVector(json, "up", camera.up);
    camera.fovYDeg = readValue(json, "fov_y_deg", camera.fovYDeg);
    camera.orthographic = readValue(json, "orthographic", camera.orthographic);
    camera.orthoHalfHeight = readValue(json, "ortho_half_height", camera.orthoHalfHeight);
    camera.windowCentre = readVector(json, "window_centre", camera.windowCentre);
    camera.validate();
    return camera;
}

Camera readCameraJson(const std::string& path)
{
    return detail::parseCameraJson(path, detail::readFileBytes(path));  // a folder or pipe named, not read
}

Camera detail::parseCameraJson(const std::string& path, const std::string& text)
{
    try {
        return cameraFromJson(nlohmann::json::parse(text));
    } catch (const std::exception& e) {
        throw InputError(path + ": bad camera file (" + jsonErrorWords(e) + ")");
    }
}

nlohmann::json cameraFileJson(const Camera& camera, const Similarity& meshUnits)
{
    nlohmann::json json = cameraToJson(camera);
    json["mesh_units"] = meshUnitsJson(meshUnits);
    return json;
}

void writeCameraJson(const Camera& camera, const std::string& path, const Similarity& meshUnits)
{
    const nlohmann::json json = cameraFileJson(camera, meshUnits);
    writeAtomically(path, [&](const std::string& temporary) {
        std::ofstream out(temporary);
        out << jsonText(json, 2) << "\n";
        if (!out) throw std::runtime_error("write failed");
    });
}

}  // namespace ivis::core
