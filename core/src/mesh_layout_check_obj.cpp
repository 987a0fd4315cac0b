#include "mesh_layout_check_formats.h"

#include <string>

namespace ivis::core::detail {
namespace {

/// @a token for a message: at most 20 characters, bytes outside printable ASCII as '?'.
std::string printable(std::string_view token)
{
    std::string text(token.substr(0, 20));
    for (char& c : text)
        if (c < 0x20 || c > 0x7e) c = '?';
    return token.size() > 20 ? text + "..." : text;
}

/// Checks the vertex references of face line @a in (after "f"), face number @a face, when
/// @a vertices vertices precede it: each "v", "v/t", "v//n" or "v/t/n" with v an integer
/// (negative: relative to the vertices before; 0 and indices past the end are refused after the
/// import), at least three of them. OpenMesh's OBJ reader asserts on a face without a usable vertex.
void checkFace(const std::string& path, TextCursor& in, std::size_t face, std::size_t vertices)
{
    const std::string where = "face " + std::to_string(face);
    int references = 0;
    for (std::string_view token = in.token(); !token.empty(); token = in.token(), ++references) {
        const std::string_view vertex = token.substr(0, token.find('/'));
        const std::size_t digitsFrom = !vertex.empty() && vertex[0] == '-' ? 1 : 0;
        bool integer = vertex.size() > digitsFrom && vertex.size() - digitsFrom <= 18;
        for (std::size_t i = digitsFrom; integer && i < vertex.size(); ++i) integer = vertex[i] >= '0' && vertex[i] <= '9';
        if (!integer) failInput(path, where + ": '" + printable(token) + "' is not a vertex reference (an index)");
        if (digitsFrom == 1 && std::stoull(std::string(vertex.substr(1))) > vertices)
            failInput(path, where + " references vertex " + std::string(vertex) + " but only " +
                                std::to_string(vertices) + " vertices precede it");
    }
    if (references < 3) failInput(path, where + " has fewer than three vertices");
}

}  // namespace

std::size_t checkObj(const std::string& path, const std::string& data, std::vector<glm::dvec3>& points)
{
    TextCursor lines(data);
    std::size_t vertices = 0;
    std::size_t faces = 0;
    while (!lines.atEnd()) {
        const std::string content(trim(lines.line()));
        TextCursor in(content);
        const std::string_view keyword = in.token();
        if (keyword == "f") checkFace(path, in, ++faces, vertices);
        if (keyword != "v") continue;
        const std::string where = "vertex " + std::to_string(++vertices);
        glm::dvec3& point = points.emplace_back();
        for (int k = 0; k < 3; ++k) {
            const std::string_view token = in.token();
            if (token.empty()) failInput(path, where + " has fewer than three coordinates");
            point[k] = checkCoordinate(path, token, where);
        }
    }
    return faces;
}

}  // namespace ivis::core::detail
