#include "test_support.h"

#include <glm/gtc/constants.hpp>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

namespace ivis::test {
namespace fs = std::filesystem;

TempDir::TempDir()
{
    static std::atomic<int> counter{0};
    const fs::path base = fs::temp_directory_path() /
                          ("ivis-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    fs::create_directories(base);
    mPath = base.string();
}

TempDir::~TempDir()
{
    std::error_code ignored;
    fs::remove_all(mPath, ignored);
}

std::string TempDir::file(const std::string& name) const { return (fs::path(mPath) / name).string(); }

std::string sharedMesh(const std::string& name)
{
    const char* env = std::getenv("IVIS_SHARED_DIR");
    const fs::path shared = env ? fs::path(env) : fs::path(IVIS_SOURCE_DIR) / ".." / "shared";
    const fs::path path = shared / "meshes" / name;
    if (!fs::exists(path)) throw std::runtime_error("shared mesh missing: " + path.string());
    return path.string();
}

std::string readFile(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

CliResult runCli(const std::string& arguments)
{
    TempDir dir;
    const std::string out = dir.file("out"), err = dir.file("err");
    // The program's default cache folder is the test run's own, never the user's.
    static const TempDir cacheHome;
    const std::string command = "XDG_CACHE_HOME='" + cacheHome.path() + "' '" + IVIS_CLI_PATH + "' " + arguments + " >'" +
                                out + "' 2>'" + err + "'";
    const int raw = std::system(command.c_str());
    CliResult result;
    result.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    result.out = readFile(out);
    result.err = readFile(err);
    return result;
}

void writeFile(const std::string& path, const std::string& text)
{
    std::ofstream out(path, std::ios::binary);
    out << text;
    if (!out) throw std::runtime_error("cannot write " + path);
}

std::vector<glm::vec3> fibonacciDirections(int count)
{
    std::vector<glm::vec3> out;
    for (int i = 0; i < count; ++i) {
        const double z = 1.0 - (2.0 * i + 1.0) / count, ring = std::sqrt(1.0 - z * z);
        const double angle = 2.399963229728653 * i;
        out.emplace_back(float(ring * std::cos(angle)), float(ring * std::sin(angle)), float(z));
    }
    return out;
}

Child startCli(const std::string& arguments)
{
    static std::atomic<int> counter{0};
    Child child;
    const std::string stem = (fs::temp_directory_path() / ("ivis-child-" + std::to_string(::getpid()) + "-" +
                                                          std::to_string(counter++))).string();
    child.out = stem + ".out";
    child.err = stem + ".err";
    // exec: the shell becomes the program, so a signal sent to the pid reaches it.
    const std::string command = std::string("exec '") + IVIS_CLI_PATH + "' " + arguments + " >'" + child.out + "' 2>'" +
                                child.err + "'";
    child.pid = ::fork();
    if (child.pid == 0) {
        ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    return child;
}

CliResult waitCli(const Child& child)
{
    int raw = 0;
    ::waitpid(child.pid, &raw, 0);
    CliResult result;
    result.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    result.out = readFile(child.out);
    result.err = readFile(child.err);
    fs::remove(child.out);
    fs::remove(child.err);
    return result;
}

core::TriangleMesh openTube(std::uint32_t n)
{
    core::TriangleMesh mesh;
    for (int ring = 0; ring < 2; ++ring) {
        for (std::uint32_t i = 0; i < n; ++i) {
            const double angle = 2.0 * glm::pi<double>() * i / n;
            mesh.positions.emplace_back(std::cos(angle), std::sin(angle), float(ring));
        }
    }
    for (std::uint32_t i = 0; i < n; ++i) {
        const std::uint32_t j = (i + 1) % n;
        mesh.triangles.push_back({i, j, n + j});
        mesh.triangles.push_back({i, n + j, n + i});
    }
    mesh.dataTriangleCount = mesh.triangles.size();
    return mesh;
}

}  // namespace ivis::test
