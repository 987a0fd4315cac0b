// The mesh reader's scalars: chosen by name (an unknown one lists those that exist), from a side
// file, and described.
#include "mesh_reader_files.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <random>
#include <string>

namespace ivis::core {
namespace {

TEST(MeshReader, UnknownScalarListsTheAvailableNames)
{
    TempDir dir;
    writeFile(dir.file("t.ply"), binaryTetraPly(false));
    writeFile(dir.file("cube.obj"), kCubeObj);
    expectReadError(dir.file("t.ply"), "no array 'foo'; available: wss (point), pressure (point)", {"foo", ""});
    expectReadError(dir.file("cube.obj"), "no array 'wss'; available: none", {"wss", ""});
}

TEST(MeshReader, ScalarNameAndFileAreExclusive)
{
    TempDir dir;
    writeFile(dir.file("cube.obj"), kCubeObj);
    writeFile(dir.file("w.txt"), "1 2 3 4 5 6 7 8\n");
    expectReadError(dir.file("cube.obj"), "not both", {"wss", dir.file("w.txt")});
}

TEST(MeshReader, SidecarScalarFile)
{
    TempDir dir;
    writeFile(dir.file("cube.obj"), kCubeObj);
    writeFile(dir.file("wss.txt"), "1 2.5\n-3e2 nan\n5 6\n7\n8\n");
    const SurfaceField cube = readMesh(dir.file("cube.obj"), {"", dir.file("wss.txt")});
    ASSERT_EQ(cube.values.size(), 8u);
    EXPECT_EQ(cube.values[1], 2.5f);
    EXPECT_EQ(cube.values[2], -300.0f);
    EXPECT_TRUE(std::isnan(cube.values[3]));
    EXPECT_EQ(cube.name, "wss");
}

TEST(MeshReader, SidecarErrors)
{
    TempDir dir;
    const std::string w = dir.file("w.txt");
    const auto expectScalarError = [&](const std::string& text, const std::string& problem) {
        writeFile(w, text);
        const std::string message = inputError([&] { readScalarFile(w, 8); });
        EXPECT_EQ(message.rfind(w + ": ", 0), 0u) << message;
        EXPECT_NE(message.find(problem), std::string::npos) << message;
    };
    expectScalarError("1 2 3 4 5 6 7\n", "expected 8 scalar values (one per vertex), found 7");
    expectScalarError("1 2 3 4 5 6 7 8 9\n", "expected 8 scalar values (one per vertex), found 9");
    expectScalarError("1 2 3 abc 5 6 7 8\n", "line 1: value 3 'abc' is not a number");
    expectScalarError("1 2\n3\n\n4 abc 6 7 8\n", "line 4: value 4 'abc' is not a number");
    expectScalarError("1 2 3 0x10 5 6 7 8\n", "value 3 '0x10' is not a number");
    expectScalarError("1 2 3 inf 5 6 7 8\n", "value 3 'inf' is not finite");
    expectScalarError("1 2 3 1e+300 5 6 7 8\n", "value 3 '1e+300' is beyond the largest a 32-bit float holds");
    // A comma-separated file: its line is one token, quoted in part, and the separators named.
    std::string commas = "1";
    for (int k = 0; k < 2000; ++k) commas += ",1";
    writeFile(w, commas);
    const std::string message = inputError([&] { readScalarFile(w, 8); });
    EXPECT_NE(message.find("line 1: value 0 '1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1...' is not a number (values are separated by "
                           "spaces or lines, not commas)"),
              std::string::npos)
        << message;
    EXPECT_LT(message.size(), 200u);
    const std::string missing = dir.file("missing.txt");
    EXPECT_EQ(inputError([&] { readScalarFile(missing, 8); }), missing + ": file not found");
    writeFile(w, "NaN -nan 1e-3");
    EXPECT_EQ(readScalarFile(w, 3).size(), 3u);
}

TEST(MeshReader, DescribeMeshReportsEveryScalar)
{
    TempDir dir;
    std::string ply = binaryTetraPly(false);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(&ply[tetraVertexByte(2, 12)], &nan, sizeof nan);  // vertex 2's wss becomes NaN
    writeFile(dir.file("t.ply"), ply);

    const MeshInfo info = describeMesh(dir.file("t.ply"));
    EXPECT_EQ(info.path, dir.file("t.ply"));
    EXPECT_EQ(info.format, "ply");
    EXPECT_EQ(info.vertices, 4u);
    EXPECT_EQ(info.triangles, 4u);
    EXPECT_EQ(info.report.degenerateDropped, 0u);
    EXPECT_EQ(info.boundaryEdges, 0u);
    EXPECT_EQ(info.components, 1u);
    EXPECT_EQ(info.bounds.lo, glm::dvec3(0.0));
    EXPECT_EQ(info.bounds.hi, glm::dvec3(1.0));
    ASSERT_EQ(info.arrays.size(), 2u);
    EXPECT_EQ(info.arrays[0].name, "wss");
    EXPECT_EQ(info.arrays[0].min, 1e-3f);
    EXPECT_EQ(info.arrays[0].max, 1.25f);
    EXPECT_EQ(info.arrays[0].nanCount, 1u);
    EXPECT_EQ(info.arrays[1].name, "pressure");
    EXPECT_EQ(info.arrays[1].min, kPressure[1]);  // a double property keeps its double values
    EXPECT_EQ(info.arrays[1].max, kPressure[0]);
    EXPECT_EQ(info.arrays[1].type, ValueType::Float64);
    EXPECT_EQ(info.arrays[1].nanCount, 0u);
}

}  // namespace
}  // namespace ivis::core
