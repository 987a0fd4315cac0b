#include "mesh_layout_check_formats.h"

#include <cstdint>
#include <string>

namespace ivis::core::detail {

MeshLayout checkStl(const std::string& path, const std::string& data)
{
    if (data.size() >= 84) {
        std::uint32_t count = 0;
        for (int i = 3; i >= 0; --i) count = (count << 8) | static_cast<unsigned char>(data[80 + i]);
        if (84 + 50 * std::uint64_t(count) == data.size()) {
            // Each facet: a normal, three corners (little-endian floats), two attribute bytes.
            for (std::uint32_t f = 0; f < count; ++f)
                for (int k = 3; k < 12; ++k) {
                    std::uint32_t bits = 0;
                    const std::size_t at = 84 + 50 * std::size_t(f) + 4 * std::size_t(k);
                    for (int i = 3; i >= 0; --i) bits = (bits << 8) | static_cast<unsigned char>(data[at + i]);
                    if ((bits & 0x7F800000u) == 0x7F800000u)  // all exponent bits: inf or NaN
                        failInput(path, "facet " + std::to_string(f) + " has a non-finite coordinate");
                }
            MeshLayout layout;
            layout.facesInFile = count;
            layout.binaryStl = true;
            return layout;
        }
    }
    const std::string start(trim(std::string_view(data).substr(0, 64)).substr(0, 5));
    if (lowercase(start) != "solid") {
        failInput(path, "not a valid STL mesh");
    }
    MeshLayout layout;
    TextCursor lines(data);
    std::size_t facets = 0;
    std::string_view last;  // the last line that is not blank: an ASCII STL ends with "endsolid"
    while (!lines.atEnd()) {
        const std::string_view line = lines.line();
        if (!trim(line).empty()) last = trim(line);
        if (line.find("outer") == std::string_view::npos && line.find("OUTER") == std::string_view::npos) {
            continue;
        }
        const std::string where = "facet " + std::to_string(facets++);
        for (int corner = 0; corner < 3; ++corner) {
            if (lines.atEnd()) failInput(path, "not a valid STL mesh (the file is truncated)");
            const std::string content(lines.line());
            TextCursor in(content);
            in.token();  // "vertex"
            glm::dvec3& point = layout.stlCorners.emplace_back();
            for (int k = 0; k < 3; ++k) {
                const std::string_view token = in.token();
                if (token.empty()) failInput(path, where + " has a corner with fewer than three coordinates");
                point[k] = checkCoordinate(path, token, where);
            }
        }
    }
    if (lowercase(std::string(last.substr(0, 8))) != "endsolid")
        failInput(path, "not a valid STL mesh (the file is truncated: it does not end with endsolid)");
    layout.facesInFile = facets;
    return layout;
}

}  // namespace ivis::core::detail
