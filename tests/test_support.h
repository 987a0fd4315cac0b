/// @file test_support.h
/// @brief Shared test helpers: temporary folders, the shared mesh folder, running the CLI.
#pragma once

#include <glm/vec3.hpp>

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
