/// @file cli_fixture.h
/// @brief The `inversevis` program as the CLI tests run it: quoting, the bad-input contract, and a
///        fixture whose output folder must stay empty whenever the program rejects its input.
#pragma once

#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace ivis::app {

namespace fs = std::filesystem;
using test::CliResult;
using test::runCli;
using test::sharedMesh;
using test::TempDir;
using test::writeFile;

/// One triangle: 3 vertices, OBJ numbering from 1.
inline constexpr const char* kTriangleObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

/// A closed tetrahedron 1-2-3-4 plus the zero-area triangle 1-5-2 (vertex 5 lies on edge 1-2),
/// which reading drops and logs.
inline constexpr const char* kTetraWithDegenerateObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 0.5 0 0\n"
                                                       "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\nf 1 5 2\n";

/// Shell-quotes a path for runCli.
inline std::string quoted(const std::string& path)
{
    return "'" + path + "'";
}

/// Everything inside @a folder (files and sub-folders, recursively), relative to it.
inline std::vector<std::string> contents(const std::string& folder)
{
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(folder))
        names.push_back(std::filesystem::relative(entry.path(), folder).string());
    std::sort(names.begin(), names.end());
    return names;
}

/// Expects the bad-input contract: status 2, nothing on stdout, exactly one stderr line
/// "inversevis: error: ..." that contains every one of @a parts.
inline void expectBadInput(const test::CliResult& result, const std::vector<std::string>& parts)
{
    EXPECT_EQ(result.status, 2) << result.err;
    EXPECT_EQ(result.out, "");
    EXPECT_EQ(result.err.rfind("inversevis: error: ", 0), 0u) << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    EXPECT_TRUE(!result.err.empty() && result.err.back() == '\n') << result.err;
    for (const std::string& part : parts)
        EXPECT_NE(result.err.find(part), std::string::npos) << "'" << part << "' not in: " << result.err;
}

/// Writes input files to one folder and points every output at another, which must stay empty
/// whenever the program rejects its input.
class Cli : public testing::Test {
protected:
    /// Path of input file @a name (written by the test).
    std::string input(const std::string& name) const { return mInputs.file(name); }
    /// Path of output file @a name.
    std::string output(const std::string& name) const { return mOutputs.file(name); }

    /// `sdf MESH --volume-res 48 -o OUT/s.vdb EXTRA`.
    std::string sdf(const std::string& mesh, const std::string& extra = "") const
    {
        return "sdf " + quoted(mesh) + " --volume-res 48 -o " + quoted(output("s.vdb")) + " " + extra;
    }
    /// `render MESH --res 32x32 --volume-res 48 --cache-dir OUT -o OUT/x.png EXTRA` (the volume cache
    /// goes to OUT too).
    std::string render(const std::string& mesh, const std::string& extra = "") const
    {
        return "render " + quoted(mesh) + " --volume-res 48 --res 32x32 --cache-dir " + quoted(output("")) + " -o " +
               quoted(output("x.png")) + " " + extra;
    }

    /// `render` of @a mesh writing only its colour bar to @a bar (no -o: the picture is not written).
    std::string renderLegendOnly(const std::string& mesh, const std::string& bar, const std::string& extra = "") const
    {
        return "render " + quoted(mesh) + " --volume-res 48 --res 32x32 --cache-dir " + quoted(output("")) +
               " --legend-only " + quoted(bar) + " " + extra;
    }

    /// Runs @a arguments, expects the bad-input contract and an untouched output folder.
    void expectRejected(const std::string& arguments, const std::vector<std::string>& parts) const
    {
        SCOPED_TRACE(arguments);
        expectBadInput(test::runCli(arguments), parts);
        EXPECT_EQ(contents(mOutputs.path()), std::vector<std::string>{});
    }
    /// expectRejected for both `sdf` and `render` of @a mesh.
    void expectMeshRejected(const std::string& mesh, const std::vector<std::string>& parts) const
    {
        expectRejected(sdf(mesh), parts);
        expectRejected(render(mesh), parts);
    }

    test::TempDir mInputs;
    test::TempDir mOutputs;
};

}  // namespace ivis::app
