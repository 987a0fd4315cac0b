#include <ivis/core/errors.h>
#include <ivis/core/mesh_reader.h>

#include "test_support.h"

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

using test::TempDir;
using test::writeFile;

/// The InputError message @a read throws, or a marker when it throws nothing or something else.
std::string inputError(const std::function<void()>& read)
{
    try {
        read();
    } catch (const InputError& e) {
        return e.what();
    } catch (const std::exception& e) {
        return std::string("<not an InputError: ") + e.what() + ">";
    }
    return "<no error>";
}

/// Expects readMesh(@a path) to fail with one line "<path>: ...@a problem...".
void expectReadError(const std::string& path, const std::string& problem, const MeshReadOptions& options = {})
{
    const std::string message = inputError([&] { readMesh(path, options); });
    EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(problem), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

/// Little- or big-endian bytes of binary PLY data.
class Bytes {
public:
    explicit Bytes(bool bigEndian = false) : mBigEndian(bigEndian) {}
    template <typename T>
    Bytes& put(T value)
    {
        char raw[sizeof(T)];
        std::memcpy(raw, &value, sizeof(T));
        if (mBigEndian) std::reverse(raw, raw + sizeof(T));
        mData.append(raw, sizeof(T));
        return *this;
    }
    /// Appends bytes as they are.
    Bytes& raw(const std::string& bytes)
    {
        mData += bytes;
        return *this;
    }
    /// A triangle as "list uchar int vertex_indices".
    Bytes& triangle(int a, int b, int c) { return put<std::uint8_t>(3).put(a).put(b).put(c); }
    const std::string& str() const { return mData; }

private:
    bool mBigEndian;
    std::string mData;
};

/// PLY header for @a vertices float x y z and @a faces "list uchar int vertex_indices".
std::string xyzPlyHeader(int vertices, int faces, const std::string& format = "ascii")
{
    return "ply\nformat " + format + " 1.0\nelement vertex " + std::to_string(vertices) +
           "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
           std::to_string(faces) + "\nproperty list uchar int vertex_indices\nend_header\n";
}

/// Header of a tetrahedron PLY with vertex x y z, float wss, double pressure; 4 triangles.
std::string tetraPlyHeader(const std::string& format)
{
    return "ply\nformat " + format +
           " 1.0\ncomment tetrahedron\nelement vertex 4\nproperty float x\nproperty float y\n"
           "property float z\nproperty float wss\nproperty double pressure\nelement face 4\n"
           "property list uchar int vertex_indices\nend_header\n";
}

/// Tetrahedron: 0 origin, 1 on x, 2 on y, 3 on z (outward faces 0-2-1, 0-1-3, 0-3-2, 1-2-3).
const float kTetraXyz[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
const int kTetraFaces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
const float kWss[4] = {0.5f, 1.25f, -3.0f, 1e-3f};
const double kPressure[4] = {101325.123456789, -0.000123456789, 7.0, 1e-300};

/// Byte offset of @a byte within vertex @a v of binaryTetraPly(false) (24 bytes per vertex).
std::size_t tetraVertexByte(int v, int byte)
{
    return tetraPlyHeader("binary_little_endian").size() + std::size_t(24 * v + byte);
}

std::string binaryTetraPly(bool bigEndian)
{
    Bytes body(bigEndian);
    for (int v = 0; v < 4; ++v) {
        body.put(kTetraXyz[v][0]).put(kTetraXyz[v][1]).put(kTetraXyz[v][2]).put(kWss[v]).put(kPressure[v]);
    }
    for (const auto& f : kTetraFaces) body.triangle(f[0], f[1], f[2]);
    return tetraPlyHeader(bigEndian ? "binary_big_endian" : "binary_little_endian") + body.str();
}

std::string asciiTetraPly()
{
    std::string text = tetraPlyHeader("ascii");
    char line[160];
    for (int v = 0; v < 4; ++v) {
        std::snprintf(line, sizeof line, "%g %g %g %.9g %.17g\n", kTetraXyz[v][0], kTetraXyz[v][1],
                      kTetraXyz[v][2], double(kWss[v]), kPressure[v]);
        text += line;
    }
    for (const auto& f : kTetraFaces) {
        text += "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) + "\n";
    }
    return text;
}

/// Unit cube as an OBJ with six quads (1-based):
///     8 ---- 7        bottom 1 2 3 4 (z = 0), top 5 6 7 8 (z = 1)
///    /|     /|
///   5 ---- 6 |
///   | 4 ---|-3
///   |/     |/
///   1 ---- 2
const char* const kCubeObj =
    "# cube\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";

std::string sharedMeshPath(const std::string& name)
{
    try {
        return test::sharedMesh(name);
    } catch (const std::exception& e) {
        ADD_FAILURE() << e.what();
        return {};
    }
}

// ----------------------------------------------------------------------------------------------
// Formats and values
// ----------------------------------------------------------------------------------------------

TEST(MeshReader, BinaryPlyFloatAndDoublePropertiesAreExact)
{
    TempDir dir;
    for (const bool bigEndian : {false, true}) {
        const std::string path = dir.file(bigEndian ? "be.ply" : "le.ply");
        writeFile(path, binaryTetraPly(bigEndian));
        const SurfaceField wss = readMesh(path, {"wss", ""});
        const SurfaceField pressure = readMesh(path, {"pressure", ""});
        ASSERT_EQ(wss.values.size(), 4u);
        ASSERT_EQ(pressure.values.size(), 4u);
        for (int v = 0; v < 4; ++v) {
            EXPECT_EQ(wss.values[v], kWss[v]);
            EXPECT_EQ(pressure.values[v], float(kPressure[v]));
            EXPECT_EQ(wss.mesh.positions[v], glm::vec3(kTetraXyz[v][0], kTetraXyz[v][1], kTetraXyz[v][2]));
        }
        EXPECT_EQ(wss.name, "wss");
        EXPECT_EQ(wss.sourcePath, path);
        EXPECT_EQ(wss.mesh.triangles.size(), 4u);
        EXPECT_EQ(wss.mesh.dataTriangleCount, 4u);
        EXPECT_EQ(boundaryEdgeCount(wss.mesh), 0u);
    }
}

TEST(MeshReader, PlyFacePropertiesAreCellArraysAndIntegersAreArraysToo)
{
    // The tetrahedron with an int and a uchar vertex property and a float and an int face property.
    const std::string header =
        "ply\nformat FORMAT 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
        "property int label\nUCHARelement face 4\nproperty list uchar int vertex_indices\nproperty float quality\n"
        "property int region\nend_header\n";
    const auto make = [&](const std::string& format, bool withUchar) {
        std::string h = header;
        h.replace(h.find("FORMAT"), 6, format);
        h.replace(h.find("UCHAR"), 5, withUchar ? "property uchar flag\n" : "");
        return h;
    };
    TempDir dir;
    Bytes binary;
    for (int v = 0; v < 4; ++v) {
        binary.put(kTetraXyz[v][0]).put(kTetraXyz[v][1]).put(kTetraXyz[v][2]).put(100 + v).put(std::uint8_t(200 + v));
    }
    for (int f = 0; f < 4; ++f) {
        binary.triangle(kTetraFaces[f][0], kTetraFaces[f][1], kTetraFaces[f][2]).put(0.5f * float(f)).put(-f);
    }
    writeFile(dir.file("b.ply"), make("binary_little_endian", true) + binary.str());
    std::string ascii = make("ascii", false);
    for (int v = 0; v < 4; ++v)
        ascii += std::to_string(kTetraXyz[v][0]) + " " + std::to_string(kTetraXyz[v][1]) + " " +
                 std::to_string(kTetraXyz[v][2]) + " " + std::to_string(100 + v) + "\n";
    for (int f = 0; f < 4; ++f)
        ascii += "3 " + std::to_string(kTetraFaces[f][0]) + " " + std::to_string(kTetraFaces[f][1]) + " " +
                 std::to_string(kTetraFaces[f][2]) + " " + std::to_string(0.5 * f) + " " + std::to_string(-f) + "\n";
    writeFile(dir.file("a.ply"), ascii);

    for (const char* name : {"b.ply", "a.ply"}) {
        SCOPED_TRACE(name);
        const SurfaceField field = readMesh(dir.file(name), {"quality", ""});
        EXPECT_EQ(field.valuesOn, Association::Cell);
        EXPECT_EQ(field.values, (std::vector<float>{0.0f, 0.5f, 1.0f, 1.5f}));
        const bool binaryFile = std::string(name) == "b.ply";
        ASSERT_EQ(field.arrays.size(), binaryFile ? 4u : 3u);
        EXPECT_EQ(field.arrays[0].name, "label");
        EXPECT_EQ(field.arrays[0].type, ValueType::Int32);
        EXPECT_EQ(field.arrays[0].values, (std::vector<double>{100, 101, 102, 103}));
        if (binaryFile) {
            EXPECT_EQ(field.arrays[1].type, ValueType::UInt8);
            EXPECT_EQ(field.arrays[1].values, (std::vector<double>{200, 201, 202, 203}));
        }
        const DataArray& region = field.arrays.back();
        EXPECT_EQ(region.name, "region");
        EXPECT_EQ(region.association, Association::Cell);
        EXPECT_EQ(region.type, ValueType::Int32);
        EXPECT_EQ(region.values, (std::vector<double>{0, -1, -2, -3}));
        EXPECT_EQ(readMesh(dir.file(name), {"label", ""}).values, (std::vector<float>{100, 101, 102, 103}));
    }
}

TEST(MeshReader, BinaryPlyHeaderEndingInACommentOrBlanks)
{
    // OpenMesh 9.0 alone starts the data one byte off after these header endings.
    TempDir dir;
    const std::string ply = binaryTetraPly(false);
    const std::size_t end = ply.find("end_header\n");
    for (const std::string& tail : {std::string("comment last\nend_header\n"), std::string("end_header  \n"),
                                    std::string("end_header\r\n")}) {
        const std::string path = dir.file("tail.ply");
        writeFile(path, ply.substr(0, end) + tail + ply.substr(end + 11));
        const SurfaceField field = readMesh(path, {"pressure", ""});
        EXPECT_EQ(field.mesh.positions[3], glm::vec3(0, 0, 1)) << tail;
        EXPECT_EQ(field.values[0], float(kPressure[0])) << tail;
        EXPECT_EQ(field.mesh.triangles.size(), 4u) << tail;
    }
}

TEST(MeshReader, AsciiPlyFloatAndDoublePropertiesAreExact)
{
    TempDir dir;
    const std::string path = dir.file("tetra.ply");
    writeFile(path, asciiTetraPly());
    const SurfaceField wss = readMesh(path, {"wss", ""});
    const SurfaceField pressure = readMesh(path, {"pressure", ""});
    for (int v = 0; v < 4; ++v) {
        EXPECT_EQ(wss.values[v], kWss[v]);
        EXPECT_EQ(pressure.values[v], float(kPressure[v]));
    }
    for (int t = 0; t < 4; ++t) {
        EXPECT_EQ(wss.mesh.triangles[t], (std::array<std::uint32_t, 3>{std::uint32_t(kTetraFaces[t][0]),
                                                                       std::uint32_t(kTetraFaces[t][1]),
                                                                       std::uint32_t(kTetraFaces[t][2])}));
    }
    EXPECT_FALSE(readMesh(path).hasScalar());
}

TEST(MeshReader, ExtensionIsCaseInsensitive)
{
    TempDir dir;
    const std::string path = dir.file("TETRA.PLY");
    writeFile(path, binaryTetraPly(false));
    EXPECT_EQ(readMesh(path).mesh.triangles.size(), 4u);
}

TEST(MeshReader, ObjQuadsAreFanTriangulated)
{
    TempDir dir;
    const std::string path = dir.file("cube.obj");
    writeFile(path, kCubeObj);
    MeshReadReport report;
    const SurfaceField cube = readMesh(path, {}, &report);
    EXPECT_EQ(report.degenerateDropped, 0u);
    EXPECT_EQ(cube.mesh.positions.size(), 8u);
    ASSERT_EQ(cube.mesh.triangles.size(), 12u);
    // First quad 1 4 3 2 -> (0,3,2), (0,2,1).
    EXPECT_EQ(cube.mesh.triangles[0], (std::array<std::uint32_t, 3>{0, 3, 2}));
    EXPECT_EQ(cube.mesh.triangles[1], (std::array<std::uint32_t, 3>{0, 2, 1}));
    EXPECT_EQ(boundaryEdgeCount(cube.mesh), 0u);
    EXPECT_EQ(componentCount(cube.mesh), 1u);
}

TEST(MeshReader, ObjNegativeIndicesAndSlashes)
{
    TempDir dir;
    const std::string path = dir.file("tri.obj");
    writeFile(path, "v 0 0 0\nv 2 0 0\nv 0 2 0\nvt 0 0\nvn 0 0 1\nf -3/1/1 -2/1/1 -1/1/1\n");
    const SurfaceField tri = readMesh(path);
    ASSERT_EQ(tri.mesh.triangles.size(), 1u);
    EXPECT_EQ(tri.mesh.triangles[0], (std::array<std::uint32_t, 3>{0, 1, 2}));
}

TEST(MeshReader, CoordinatesStayInFileUnits)
{
    TempDir dir;
    const std::string path = dir.file("far.off");
    writeFile(path, "OFF\n3 1 0\n1000 2000 3000\n1010 2000 3000\n1000 2020 3000\n3 0 1 2\n");
    const SurfaceField far = readMesh(path);
    EXPECT_EQ(far.mesh.positions[1], glm::vec3(1010, 2000, 3000));
    EXPECT_EQ(far.normalization.scale, 1.0);
}

TEST(MeshReader, StlAsciiAndBinaryMergeCorners)
{
    TempDir dir;
    std::string ascii = "solid tetra\n";
    Bytes binary;
    binary.raw(std::string(80, ' ')).put(std::uint32_t(4));
    for (const auto& f : kTetraFaces) {
        ascii += "facet normal 0 0 0\n outer loop\n";
        binary.put(0.0f).put(0.0f).put(0.0f);
        for (int corner : f) {
            const float* p = kTetraXyz[corner];
            ascii += "  vertex " + std::to_string(p[0]) + " " + std::to_string(p[1]) + " " +
                     std::to_string(p[2]) + "\n";
            binary.put(p[0]).put(p[1]).put(p[2]);
        }
        ascii += " endloop\nendfacet\n";
        binary.put(std::uint16_t(0));
    }
    ascii += "endsolid tetra\n";
    writeFile(dir.file("a.stl"), ascii);
    writeFile(dir.file("b.stl"), binary.str());
    // Vertices are numbered in the order each merged corner first appears (VTK's STL reader's
    // order), which the documented --scalar-file order is: faces 0-2-1 and 0-1-3 come first, so
    // the corners appear as tetra vertices 0, 2, 1, 3.
    writeFile(dir.file("w.txt"), "10 12 11 13\n");
    const int kFirstAppearance[4] = {0, 2, 1, 3};
    for (const char* name : {"a.stl", "b.stl"}) {
        const SurfaceField tetra = readMesh(dir.file(name), {"", dir.file("w.txt")});
        EXPECT_EQ(tetra.mesh.positions.size(), 4u) << name;
        EXPECT_EQ(tetra.mesh.triangles.size(), 4u) << name;
        EXPECT_EQ(boundaryEdgeCount(tetra.mesh), 0u) << name;
        for (int v = 0; v < 4; ++v) {
            const float* p = kTetraXyz[kFirstAppearance[v]];
            EXPECT_EQ(tetra.mesh.positions[std::size_t(v)], glm::vec3(p[0], p[1], p[2])) << name << " vertex " << v;
            EXPECT_EQ(tetra.values[std::size_t(v)], 10.0f + float(kFirstAppearance[v])) << name << " vertex " << v;
        }
    }
}

// ----------------------------------------------------------------------------------------------
// Non-manifold input and degenerate triangles
// ----------------------------------------------------------------------------------------------

TEST(MeshReader, NonManifoldTrianglesAllSurvive)
{
    // Fins: triangles 0-1-2, 1-0-3, 0-1-4 all share the edge 0-1.
    //        2
    //  3 - 0-+-1 - 4
    const std::string finsXyz = "0 0 0\n1 0 0\n0.5 1 0\n0.5 -1 0\n0.5 0 1\n";
    // Two tetrahedra sharing vertex 0 (second one mirrored through the origin: 4 5 6).
    const std::string bowXyz = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n-1 0 0\n0 -1 0\n0 0 -1\n";
    const std::string bowFaces = "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n3 0 4 5\n3 0 6 4\n3 0 5 6\n3 4 6 5\n";

    TempDir dir;
    writeFile(dir.file("fins.off"), "OFF\n5 3 0\n" + finsXyz + "3 0 1 2\n3 1 0 3\n3 0 1 4\n");
    writeFile(dir.file("fins.obj"),
              "v 0 0 0\nv 1 0 0\nv 0.5 1 0\nv 0.5 -1 0\nv 0.5 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n");
    writeFile(dir.file("fins.ply"), xyzPlyHeader(5, 3) + finsXyz + "3 0 1 2\n3 1 0 3\n3 0 1 4\n");
    writeFile(dir.file("bowtie.off"), "OFF\n7 8 0\n" + bowXyz + bowFaces);
    writeFile(dir.file("bowtie.ply"), xyzPlyHeader(7, 8) + bowXyz + bowFaces);

    for (const char* name : {"fins.off", "fins.obj", "fins.ply"}) {
        MeshReadReport report;
        report.degenerateDropped = 99;
        const SurfaceField fins = readMesh(dir.file(name), {}, &report);
        EXPECT_EQ(fins.mesh.triangles.size(), 3u) << name;
        EXPECT_EQ(fins.mesh.positions.size(), 5u) << name;
        EXPECT_EQ(report.degenerateDropped, 0u) << name;
        EXPECT_EQ(boundaryEdgeCount(fins.mesh), 6u) << name;
    }
    for (const char* name : {"bowtie.off", "bowtie.ply"}) {
        const SurfaceField bow = readMesh(dir.file(name));
        EXPECT_EQ(bow.mesh.triangles.size(), 8u) << name;
        EXPECT_EQ(bow.mesh.positions.size(), 7u) << name;
        EXPECT_EQ(boundaryEdgeCount(bow.mesh), 0u) << name;
        EXPECT_EQ(componentCount(bow.mesh), 1u) << name;
    }
}

TEST(MeshReader, DegenerateTrianglesAreDroppedAndCounted)
{
    // 0 1 2 3 form a unit square; 4 lies on the segment 0-1 (collinear with it).
    //  3 --- 2
    //  |     |
    //  0--4--1
    const std::string xyz = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0 0\n";
    TempDir dir;
    writeFile(dir.file("d.off"), "OFF\n5 5 0\n" + xyz + "3 0 1 2\n3 0 2 3\n3 0 0 2\n3 0 4 1\n4 0 1 1 2\n");
    MeshReadReport report;
    SurfaceField field = readMesh(dir.file("d.off"), {}, &report);
    // Kept: 0-1-2, 0-2-3 and the fan triangle 0-1-2 of the quad; dropped: repeated index,
    // zero area, and the quad's fan triangle 0-1-1.
    EXPECT_EQ(field.mesh.triangles.size(), 3u);
    EXPECT_EQ(report.degenerateDropped, 3u);

    // OpenMesh's OBJ reader skips a face with a repeated corner itself; it is still counted.
    writeFile(dir.file("d.obj"), "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\nf 1 1 2\n");
    field = readMesh(dir.file("d.obj"), {}, &report);
    EXPECT_EQ(field.mesh.triangles.size(), 1u);
    EXPECT_EQ(report.degenerateDropped, 1u);
}

// ----------------------------------------------------------------------------------------------
// Scalars
// ----------------------------------------------------------------------------------------------

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
    expectScalarError("1 2 3 abc 5 6 7 8\n", "value 3 'abc' is not a number");
    expectScalarError("1 2 3 0x10 5 6 7 8\n", "value 3 '0x10' is not a number");
    expectScalarError("1 2 3 inf 5 6 7 8\n", "value 3 'inf' is not finite");
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

// ----------------------------------------------------------------------------------------------
// Bad input: one line "<path>: <problem>", never a crash
// ----------------------------------------------------------------------------------------------

TEST(MeshReader, MissingUnreadableAndUnknownFiles)
{
    TempDir dir;
    const std::string missing = dir.file("x.ply");
    EXPECT_EQ(inputError([&] { readMesh(missing); }), missing + ": file not found");
    EXPECT_EQ(inputError([&] { describeMesh(missing); }), missing + ": file not found");

    expectReadError(dir.path(), "is a directory");

    writeFile(dir.file("x.abc"), "whatever");
    EXPECT_EQ(inputError([&] { readMesh(dir.file("x.abc")); }),
              dir.file("x.abc") + ": unknown mesh format '.abc' (expected .obj, .off, .ply, .stl, .vtk, .vtp, .vtu)");
}

TEST(MeshReader, PermissionDenied)
{
    TempDir dir;
    const std::string path = dir.file("x.ply");
    writeFile(path, binaryTetraPly(false));
    ASSERT_EQ(::chmod(path.c_str(), 0), 0);
    // root reads anything; read as "nobody" for the duration of the call.
    const bool root = ::geteuid() == 0;
    if (root) {
        ASSERT_EQ(::seteuid(65534), 0);
    }
    const std::string message = inputError([&] { readMesh(path); });
    if (root) {
        ASSERT_EQ(::seteuid(0), 0);
    }
    EXPECT_EQ(message, path + ": cannot read file (permission denied)");
}

TEST(MeshReader, NotAMesh)
{
    TempDir dir;
    std::mt19937 rng(7);
    std::string noise(4096, '\0');
    for (char& c : noise) c = char(rng());
    writeFile(dir.file("noise.ply"), noise);
    writeFile(dir.file("empty.ply"), "");
    writeFile(dir.file("text.ply"), "this is not a mesh\n");
    writeFile(dir.file("noise.stl"), "garbage that is neither ascii nor binary STL");
    writeFile(dir.file("noise.off"), "OFX\n");
    for (const char* name : {"noise.ply", "empty.ply", "text.ply"}) {
        expectReadError(dir.file(name), "not a valid PLY mesh");
    }
    expectReadError(dir.file("noise.stl"), "not a valid STL mesh");
    expectReadError(dir.file("noise.off"), "not a valid OFF mesh");

    writeFile(dir.file("points.obj"), "v 0 0 0\nv 1 0 0\n");
    writeFile(dir.file("empty.obj"), "");
    writeFile(dir.file("empty.off"), "OFF\n0 0 0\n");
    for (const char* name : {"points.obj", "empty.obj", "empty.off"}) {
        expectReadError(dir.file(name), "mesh has no triangles");
    }
}

TEST(MeshReader, BrokenPlyHeaders)
{
    // Each of these makes OpenMesh 9.0 itself loop without bound or crash.
    TempDir dir;
    const std::string path = dir.file("h.ply");
    const std::string start = "ply\nformat ascii 1.0\n";
    for (const std::string& header : std::vector<std::string>{
             start + "element vertex 3\n",                                   // no end_header
          start + "property float x\nend_header\n",                       // property before element
          start + "element vertex 5000000000\nproperty float x\nend_header\n",  // count overflow
          start + "element vertex 4000000000\nproperty float x\nproperty float y\nproperty float z\n"
                  "end_header\n0 0 0\n",
          "ply\nformat ascii one\nend_header\n",                          // bad version
          "ply\nformat binary_middle_endian 1.0\nend_header\n",
          start + "element vertex 1\nproperty float x\nproperty float y\nend_header\n0 0\n",  // no z
          start + "element vertex 1\nproperty list int float x\nend_header\n"}) {
        writeFile(path, header);
        expectReadError(path, "not a valid PLY mesh");
    }
}

TEST(MeshReader, UnsupportedPlyLayoutsAreRejected)
{
    TempDir dir;
    const std::string path = dir.file("u.ply");
    const std::string header = xyzPlyHeader(3, 0);
    const std::size_t afterZ = header.find("element face");
    writeFile(path, header.substr(0, afterZ) + "property uchar flag\n" + header.substr(afterZ));
    expectReadError(path, "8-bit type");
    writeFile(path, "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty int x\nproperty int y\n"
                    "property int z\nend_header\n" + std::string(36, '\0'));
    expectReadError(path, "must be float or double");
}

TEST(MeshReader, TruncatedBinaryPlyNeverCrashes)
{
    TempDir dir;
    const std::string full = binaryTetraPly(false);
    const std::size_t header = tetraPlyHeader("binary_little_endian").size();
    const std::string path = dir.file("cut.ply");
    for (std::size_t size = 0; size < full.size(); ++size) {
        writeFile(path, full.substr(0, size));
        const std::string message = inputError([&] { readMesh(path); });
        EXPECT_EQ(message.rfind(path + ": not a valid PLY mesh", 0), 0u) << size << ": " << message;
        if (size >= header) {
            EXPECT_NE(message.find("truncated"), std::string::npos) << message;
        }
    }
}

TEST(MeshReader, TruncatedAsciiFiles)
{
    TempDir dir;
    const std::string ply = asciiTetraPly();
    writeFile(dir.file("cut.ply"), ply.substr(0, ply.size() - 4));  // last face loses an index
    expectReadError(dir.file("cut.ply"), "truncated");
    writeFile(dir.file("cut.off"), "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n");
    expectReadError(dir.file("cut.off"), "truncated");
}

TEST(MeshReader, HugeCountsFailFast)
{
    TempDir dir;
    writeFile(dir.file("len.off"), "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4000000000 0 1 2\n");
    expectReadError(dir.file("len.off"), "truncated");
    writeFile(dir.file("nf.off"), "OFF\n3 4000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    expectReadError(dir.file("nf.off"), "truncated");
    writeFile(dir.file("ov.off"), "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n99999999999 0 1 2\n");
    expectReadError(dir.file("ov.off"), "not a valid OFF mesh");
    Bytes body;
    for (int i = 0; i < 9; ++i) body.put(0.0f);
    body.put(std::int32_t(-5)).put(0).put(1).put(2);
    std::string header = xyzPlyHeader(3, 1, "binary_little_endian");
    header.replace(header.find("list uchar"), 10, "list int");
    writeFile(dir.file("neg.ply"), header + body.str());
    expectReadError(dir.file("neg.ply"), "not a valid PLY mesh");
}

TEST(MeshReader, NonFiniteCoordinates)
{
    TempDir dir;
    // 13 vertices, the last one (vertex 12) is not finite.
    std::string off = "OFF\n13 1 0\n";
    for (int v = 0; v < 12; ++v) off += std::to_string(v) + " " + std::to_string(v * v) + " 1\n";
    writeFile(dir.file("x.off"), off + "1 nan 0\n3 0 1 2\n");
    expectReadError(dir.file("x.off"), "vertex 12 has a non-finite coordinate");
    writeFile(dir.file("inf.obj"), "v 0 0 0\nv 1 0 0\nv inf 1 0\nf 1 2 3\n");
    expectReadError(dir.file("inf.obj"), "vertex 3 has a non-finite coordinate");
    writeFile(dir.file("big.ply"), xyzPlyHeader(3, 1) + "0 0 0\n1 0 1e39\n0 1 0\n3 0 1 2\n");
    expectReadError(dir.file("big.ply"), "vertex 1 has a non-finite coordinate");

    std::string ply = binaryTetraPly(false);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(&ply[tetraVertexByte(1, 4)], &nan, sizeof nan);  // y of vertex 1
    writeFile(dir.file("nan.ply"), ply);
    expectReadError(dir.file("nan.ply"), "vertex 1 has a non-finite coordinate");
}

TEST(MeshReader, NonNumericValues)
{
    TempDir dir;
    writeFile(dir.file("a.off"), "OFF\n3 1 0\n0 0 0\n1 abc 0\n0 1 0\n3 0 1 2\n");
    expectReadError(dir.file("a.off"), "vertex 1 has a non-numeric coordinate 'abc'");
    writeFile(dir.file("a.obj"), "v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n");
    expectReadError(dir.file("a.obj"), "vertex 2 has fewer than three coordinates");
    writeFile(dir.file("i.off"), "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 x 2\n3 0 1 2\n");
    expectReadError(dir.file("i.off"), "face 0 has an invalid index 'x'");
    // ">>" would read "2-1" as 2 and then -1, taking -1 as the next face's length.
    writeFile(dir.file("j.off"), "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2-1\n3 0 1 2\n");
    expectReadError(dir.file("j.off"), "face 0 has an invalid index '2-1'");
    // Well-formed but out of range for an unsigned int: OpenMesh's stream fails, and we notice.
    writeFile(dir.file("k.off"), "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 99999999999\n");
    expectReadError(dir.file("k.off"), "cannot read face 0");

    const std::string ply = asciiTetraPly();
    const std::size_t wss0 = ply.find("0.5 ");
    writeFile(dir.file("w.ply"), ply.substr(0, wss0) + "oops" + ply.substr(wss0 + 3));
    expectReadError(dir.file("w.ply"), "vertex 0 has an invalid value 'oops' for property 'wss'");
    writeFile(dir.file("n.ply"), ply.substr(0, wss0) + "nan" + ply.substr(wss0 + 3));
    expectReadError(dir.file("n.ply"), "vertex 0 has a non-finite value 'nan' for property 'wss'");
    writeFile(dir.file("f.ply"), ply.substr(0, ply.rfind("3 1 2 3")) + "3 1 2 3.5\n");
    expectReadError(dir.file("f.ply"), "face 3 has an invalid value '3.5' for property 'vertex_indices'");
}

TEST(MeshReader, OutOfRangeIndices)
{
    TempDir dir;
    writeFile(dir.file("x.obj"), std::string(kCubeObj) + "f 1 2 99\n");
    expectReadError(dir.file("x.obj"), "face 7 references vertex 99 but the mesh has 8 vertices");
    writeFile(dir.file("zero.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n");
    expectReadError(dir.file("zero.obj"), "face 1 references vertex 0 but the mesh has 3 vertices");
    writeFile(dir.file("x.off"), "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 1 12\n");
    expectReadError(dir.file("x.off"), "face 1 references vertex 12 but the mesh has 4 vertices");

    const std::string ascii = asciiTetraPly();
    writeFile(dir.file("a.ply"), ascii.substr(0, ascii.rfind("3 1 2 3")) + "3 1 2 -1\n");
    expectReadError(dir.file("a.ply"), "face 3 references vertex -1 but the mesh has 4 vertices");
    std::string binary = binaryTetraPly(false);
    const int bad = 4;
    std::memcpy(&binary[binary.size() - 4], &bad, sizeof bad);
    writeFile(dir.file("b.ply"), binary);
    expectReadError(dir.file("b.ply"), "face 3 references vertex 4 but the mesh has 4 vertices");
}

TEST(MeshReader, RandomBytesNeverCrash)
{
    TempDir dir;
    std::mt19937 rng(1234);
    const std::string plyHeader = tetraPlyHeader("binary_little_endian");
    for (int trial = 0; trial < 40; ++trial) {
        std::string noise(std::size_t(rng() % 600), '\0');
        for (char& c : noise) c = char(rng() % 256);
        for (const char* ext : {".ply", ".off", ".obj", ".stl"}) {
            const std::string path = dir.file("r" + std::to_string(trial) + ext);
            const bool withHeader = std::string(ext) == ".ply" && trial % 2 == 0;
            writeFile(path, withHeader ? plyHeader + noise : noise);
            const std::string message = inputError([&] { readMesh(path); });
            // Random data may occasionally decode to a valid mesh; otherwise it is an InputError.
            if (message != "<no error>") {
                EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
            }
        }
    }
}

TEST(MeshReader, OpenMeshStaysQuiet)
{
    TempDir dir;
    writeFile(dir.file("m.obj"), std::string("mtllib missing.mtl\nusemtl nothing\n") + kCubeObj);
    writeFile(dir.file("bad.ply"), "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n");
    testing::internal::CaptureStderr();
    EXPECT_EQ(readMesh(dir.file("m.obj")).mesh.triangles.size(), 12u);
    EXPECT_THROW(readMesh(dir.file("bad.ply")), InputError);
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

// ----------------------------------------------------------------------------------------------
// Real meshes from ../shared/meshes (see MANIFEST.md); a missing file is a failure
// ----------------------------------------------------------------------------------------------

TEST(MeshReader, SharedVampyPressureScalars)
{
    const std::string path = sharedMeshPath("vampy_artery_cfd_pressure.ply");
    ASSERT_FALSE(path.empty());
    const MeshInfo info = describeMesh(path);
    EXPECT_EQ(info.vertices, 1104u);
    EXPECT_EQ(info.triangles, 2204u);
    EXPECT_EQ(info.boundaryEdges, 0u);
    EXPECT_EQ(info.components, 1u);
    const std::pair<const char*, std::pair<double, double>> expected[] = {
        {"pressure_t200", {0.2294, 0.7932}},     {"pressure_t400", {0.09313, 0.2698}},
        {"pressure_t600", {-0.009525, 0.1407}},  {"pressure_t800", {-0.0451, 0.08232}},
        {"pressure_t1000", {-0.05931, 0.04502}}};
    ASSERT_EQ(info.arrays.size(), 5u);
    for (std::size_t i = 0; i < 5; ++i) {
        EXPECT_EQ(info.arrays[i].name, expected[i].first);
        EXPECT_NEAR(info.arrays[i].min, expected[i].second.first, 1e-4) << expected[i].first;
        EXPECT_NEAR(info.arrays[i].max, expected[i].second.second, 1e-4) << expected[i].first;
        EXPECT_EQ(info.arrays[i].nanCount, 0u);
    }
    const SurfaceField field = readMesh(path, {"pressure_t600", ""});
    EXPECT_EQ(field.values.size(), 1104u);
    EXPECT_NEAR(finiteRange(field.values).first, -0.009525, 1e-4);
}

TEST(MeshReader, SharedLeftAtriumIsOpen)
{
    const std::string path = sharedMeshPath("lasc2013_b003_left_atrium.ply");
    ASSERT_FALSE(path.empty());
    const SurfaceField atrium = readMesh(path);
    EXPECT_EQ(atrium.mesh.positions.size(), 10516u);
    EXPECT_EQ(atrium.mesh.triangles.size(), 20576u);
    EXPECT_EQ(boundaryEdgeCount(atrium.mesh), 462u);
    EXPECT_EQ(componentCount(atrium.mesh), 1u);
}

}  // namespace
}  // namespace ivis::core
