#include "mesh_layout_check_formats.h"

#include <string>

namespace ivis::core::detail {

std::size_t checkObj(const std::string& path, const std::string& data)
{
    TextCursor lines(data);
    std::size_t vertices = 0;
    std::size_t faces = 0;
    while (!lines.atEnd()) {
        const std::string content(trim(lines.line()));
        TextCursor in(content);
        const std::string_view keyword = in.token();
        if (keyword == "f") ++faces;
        if (keyword != "v") continue;
        const std::string where = "vertex " + std::to_string(++vertices);
        for (int k = 0; k < 3; ++k) {
            const std::string_view token = in.token();
            if (token.empty()) failInput(path, where + " has fewer than three coordinates");
            checkCoordinate(path, token, where);
        }
    }
    return faces;
}

}  // namespace ivis::core::detail
