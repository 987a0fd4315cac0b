/// @file test_support.h
/// @brief Shared test helpers: temporary folders, the shared mesh folder, running the CLI, a small
///        open mesh.
#pragma once

#include <ivis/core/triangle_mesh.h>

#include <glm/vec3.hpp>

#include <cstdint>

#include <string>
#include <vector>

namespace ivis::test {

/// @brief A fresh empty folder under the system temp dir, removed at destruction.
class TempDir {
public:
    TempDir();
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    /// @brief Path of @a name inside the folder.
    std::string file(const std::string& name) const;
    /// @brief The folder itself.
    const std::string& path() const { return mPath; }

private:
    std::string mPath;
};

/// @brief Path of a file in ../shared/meshes (env IVIS_SHARED_DIR overrides ../shared).
std::string sharedMesh(const std::string& name);

/// @brief Output and exit status of one CLI run.
struct CliResult {
    int status = -1;
    std::string out;  ///< stdout
    std::string err;  ///< stderr
};

/// @brief Runs the `inversevis` program with @a arguments (a shell-quoted string).
CliResult runCli(const std::string& arguments);

/// @brief @a count unit directions spread evenly over the sphere (Fibonacci lattice).
std::vector<glm::vec3> fibonacciDirections(int count);

/// @brief Open tube of @a n segments around the z axis, radius 1, z in [0, 1], outward-facing:
///
///   top    n .. 2n-1   (z = 1)      n+i ---- n+i+1
///                                    |   \      |
///   bottom 0 .. n-1    (z = 0)       i  ----  i+1
core::TriangleMesh openTube(std::uint32_t n);

/// @brief A running `inversevis` and where its output goes.
struct Child {
    int pid = -1;
    std::string out, err;  ///< files holding its stdout and stderr
};

/// @brief Starts the `inversevis` program with @a arguments (a shell-quoted string) without waiting.
Child startCli(const std::string& arguments);
/// @brief Waits for @a child and returns its exit status and output.
CliResult waitCli(const Child& child);

/// @brief The whole content of @a path ("" when it cannot be read).
std::string readFile(const std::string& path);

/// @brief Writes @a text to @a path (binary-safe).
void writeFile(const std::string& path, const std::string& text);

}  // namespace ivis::test
