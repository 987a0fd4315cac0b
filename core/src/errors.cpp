#include <ivis/core/errors.h>

#include <algorithm>
#include <cctype>
#include <string>

namespace ivis {

std::string oneLine(std::string text)
{
    std::replace(text.begin(), text.end(), '\r', ' ');
    std::replace(text.begin(), text.end(), '\n', ' ');
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
    return text;
}

}  // namespace ivis

namespace ivis::detail {

void checkFailed(const char* condition, const char* file, int line)
{
    throw InternalError(std::string("internal check failed: ") + condition + " at " + file + ":" +
                        std::to_string(line));
}

}  // namespace ivis::detail
