#include <ivis/core/file_extension.h>

#include <cctype>
#include <filesystem>

namespace ivis::core {

std::string lowerCaseExtension(const std::string& path)
{
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    return extension;
}

}  // namespace ivis::core
