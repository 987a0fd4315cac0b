// The mesh reader on bad input: missing, unreadable and foreign files, broken and truncated PLY,
// non-finite and non-numeric values, out-of-range indices and random bytes: one line, never a crash.
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

TEST(MeshReader, AsciiStlCutBetweenFacetsIsTruncated)
{
    TempDir dir;
    const std::string facets = "facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 1 0\n"
                               " endloop\nendfacet\nfacet normal 0 0 1\n outer loop\n  vertex 1 0 0\n"
                               "  vertex 1 1 0\n  vertex 0 1 0\n endloop\nendfacet\n";
    writeFile(dir.file("whole.stl"), "solid s\n" + facets + "endsolid s\n\n");
    EXPECT_EQ(readMesh(dir.file("whole.stl")).mesh.triangles.size(), 2u);
    writeFile(dir.file("cut.stl"), "solid s\n" + facets);
    expectReadError(dir.file("cut.stl"), "not a valid STL mesh (the file is truncated: it does not end with endsolid)");
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
    writeFile(path, header.substr(0, afterZ) + "property list uchar uchar flags\n" + header.substr(afterZ));
    expectReadError(path, "list property 'flags' of element 'vertex' has an 8-bit type");
    writeFile(path, "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty int x\nproperty int y\n"
                    "property int z\nend_header\n" + std::string(36, '\0'));
    expectReadError(path, "must be float or double");
    // A second face element (the fuzzer's tests/fuzz/regressions/ply/two-face-elements.ply) sent
    // OpenMesh's ASCII reader into 16 GB and 100 s.
    const std::string twoFaces = xyzPlyHeader(3, 0);
    writeFile(path, twoFaces.substr(0, afterZ) + "element face 2\nproperty char tag\n" + twoFaces.substr(afterZ) +
                        "0 0 0\n1 0 0\n0 1 0\n");
    expectReadError(path, "not a valid PLY mesh (two face elements)");
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
    writeFile(dir.file("nv.off"), "OFF\n4000000000 1 0\n0 0 0\n");  // its points are not asked for up front
    expectReadError(dir.file("nv.off"), "truncated");
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

    // A binary STL of two facets, the second with a NaN corner (it said "the mesh has no triangles").
    std::string stl(80, ' ');
    const std::uint32_t facets = 2;
    stl.append(reinterpret_cast<const char*>(&facets), 4);
    for (int f = 0; f < 2; ++f) {
        const float values[12] = {0, 0, 1, 0, 0, 0, 1, 0, 0, 0, f == 1 ? nan : 1.0f, 0};
        stl.append(reinterpret_cast<const char*>(values), sizeof values).append(2, '\0');
    }
    writeFile(dir.file("nan.stl"), stl);
    expectReadError(dir.file("nan.stl"), "facet 1 has a non-finite coordinate");
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

}  // namespace
}  // namespace ivis::core
