#include <ivis/core/atomic_file.h>

#include <ivis/core/errors.h>

#include <atomic>
#include <filesystem>
#include <unistd.h>

namespace ivis::core {

void writeAtomically(const std::string& path, const std::function<void(const std::string&)>& write)
{
    static std::atomic<int> counter{0};
    const std::string temporary = path + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter++);
    try {
        write(temporary);
        std::error_code error;
        std::filesystem::rename(temporary, path, error);
        if (error) throw std::runtime_error(error.message());
    } catch (const Cancelled&) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw;
    } catch (const std::exception& e) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        const std::string why = e.what();
        // An InputError from the writer already names a path: keep only its reason.
        const std::size_t colon = why.rfind(": ");
        throw InputError(path + ": cannot write (" + (colon == std::string::npos ? why : why.substr(colon + 2)) + ")");
    }
}

}  // namespace ivis::core
