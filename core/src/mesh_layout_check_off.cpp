#include "mesh_layout_check_formats.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>

namespace ivis::core::detail {

std::size_t checkOff(const std::string& path, const std::string& data, std::vector<glm::dvec3>& points)
{
    const auto truncated = [&] { failInput(path, "not a valid OFF mesh (the file is truncated)"); };
    TextCursor in(data);
    const std::string_view header = in.line();
    std::size_t i = header.compare(0, 2, "ST") == 0 ? 2 : 0;
    const bool colors = i < header.size() && header[i] == 'C';
    i += colors;
    const bool normals = i < header.size() && header[i] == 'N';
    i += normals;
    if (i < header.size() && (header[i] == '4' || header[i] == 'n')) {
        failInput(path, "not a valid OFF mesh (only 3D vertices are supported)");
    }
    if (header.compare(i, 3, "OFF") != 0) failInput(path, "not a valid OFF mesh");
    if (header.find("BINARY", i) != std::string_view::npos) failInput(path, "binary OFF is not supported");

    std::array<std::uint32_t, 3> counts{};  // vertices, faces, edges
    for (std::uint32_t& count : counts) {
        const std::optional<std::uint32_t> n = parseCount(in.token());
        if (!n) failInput(path, "not a valid OFF mesh (bad vertex/face/edge counts)");
        count = *n;
    }
    for (std::uint32_t v = 0; v < counts[0]; ++v) {
        glm::dvec3& point = points.emplace_back();
        for (int k = 0; k < (normals ? 6 : 3); ++k) {
            const std::string_view token = in.token();
            if (token.empty()) truncated();
            if (k < 3) {
                point[k] = checkCoordinate(path, token, "vertex " + std::to_string(v));
            } else if (!isDecimal(token)) {
                failInput(path, "vertex " + std::to_string(v) + " has an invalid normal '" +
                                    std::string(token) + "'");
            }
        }
        in.line();
    }
    for (std::uint32_t f = 0; f < counts[1]; ++f) {
        const std::string_view length = in.token();
        if (length.empty()) truncated();
        const std::optional<std::uint32_t> n = parseCount(length);
        if (!n) {
            failInput(path, "not a valid OFF mesh (face " + std::to_string(f) + " has length '" +
                                std::string(length) + "')");
        }
        for (std::uint32_t k = 0; k < *n; ++k) {
            const std::string_view index = in.token();
            if (index.empty()) truncated();
            if (!isInteger(index)) {
                failInput(path, "face " + std::to_string(f) + " has an invalid index '" +
                                    std::string(index) + "'");
            }
        }
        if (colors) in.line();
    }
    return counts[1];
}

}  // namespace ivis::core::detail
