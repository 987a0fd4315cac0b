#include <ivis/core/errors.h>

#include <string>

namespace ivis::detail {

void checkFailed(const char* condition, const char* file, int line)
{
    throw InternalError(std::string("internal check failed: ") + condition + " at " + file + ":" +
                        std::to_string(line));
}

}  // namespace ivis::detail
