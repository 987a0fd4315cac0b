#include <ivis/core/file_bytes.h>

#include <ivis/core/mesh_layout_check.h>

#include <cctype>
#include <cerrno>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace ivis::core::detail {
namespace {

namespace fs = std::filesystem;

/// "Permission denied" -> "permission denied".
std::string systemMessage(int code)
{
    std::string text = std::generic_category().message(code);
    if (!text.empty()) text[0] = char(std::tolower(static_cast<unsigned char>(text[0])));
    return text;
}

}  // namespace

std::string readFileBytes(const std::string& path)
{
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (ec && ec != std::errc::no_such_file_or_directory && ec != std::errc::not_a_directory) {
        failInput(path, "cannot read file (" + systemMessage(ec.value()) + ")");
    }
    if (!fs::exists(status)) failInput(path, "file not found");
    if (fs::is_directory(status)) failInput(path, "is a directory, not a file");
    // Opening a FIFO waits for a writer, and a device's size is unknown: only files are read.
    if (!fs::is_regular_file(status)) failInput(path, "not a regular file (a pipe or device), which is not read");

    std::ifstream in(path, std::ios::binary);
    if (!in) failInput(path, "cannot read file (" + systemMessage(errno) + ")");
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (size < 0) failInput(path, "cannot read file (not a regular file)");
    in.seekg(0);
    std::string data(std::size_t(size), '\0');
    if (!in.read(data.data(), size)) failInput(path, "cannot read file (read error)");
    return data;
}

}  // namespace ivis::core::detail
