// The mesh reader: its formats and exact values, topology kept as read, and the shared meshes.
#include "mesh_reader_files.h"

#include <ivis/core/procedural_scenes.h>

#include <glm/geometric.hpp>
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
#include <sstream>
#include <string>

namespace ivis::core {
namespace {

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

// OpenMesh's ASCII reader reads an 8-bit value as one character ("200" as '2', then "00" as the
// next value): such properties are read as 16-bit and keep their type, and a value beyond their
// type is refused, naming it.
TEST(MeshReader, AsciiPly8BitPropertiesAreReadAsTheirNumbers)
{
    const std::string header = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                               "property float z\nproperty uchar flag\nproperty float after\nelement face 4\n"
                               "property list uchar int vertex_indices\nproperty int8 tag\nend_header\n";
    const int flags[4] = {0, 9, 200, 255}, tags[4] = {-128, 5, 127, -1};
    std::string body;
    for (int v = 0; v < 4; ++v)
        body += std::to_string(kTetraXyz[v][0]) + " " + std::to_string(kTetraXyz[v][1]) + " " +
                std::to_string(kTetraXyz[v][2]) + " " + std::to_string(flags[v]) + " " + std::to_string(0.5 * v) + "\n";
    for (int f = 0; f < 4; ++f)
        body += "3 " + std::to_string(kTetraFaces[f][0]) + " " + std::to_string(kTetraFaces[f][1]) + " " +
                std::to_string(kTetraFaces[f][2]) + " " + std::to_string(tags[f]) + "\n";
    TempDir dir;
    writeFile(dir.file("bytes.ply"), header + body);
    const SurfaceField field = readMesh(dir.file("bytes.ply"), {"flag", ""});
    ASSERT_EQ(field.arrays.size(), 3u);
    EXPECT_EQ(field.arrays[0].name, "flag");
    EXPECT_EQ(field.arrays[0].type, ValueType::UInt8);
    EXPECT_EQ(field.arrays[0].values, (std::vector<double>{0, 9, 200, 255}));
    EXPECT_EQ(field.arrays[1].values, (std::vector<double>{0, 0.5, 1, 1.5}));  // read from where the flags end
    EXPECT_EQ(field.arrays[2].name, "tag");
    EXPECT_EQ(field.arrays[2].association, Association::Cell);
    EXPECT_EQ(field.arrays[2].type, ValueType::Int8);
    EXPECT_EQ(field.arrays[2].values, (std::vector<double>{-128, 5, 127, -1}));
    EXPECT_EQ(field.values, (std::vector<float>{0, 9, 200, 255}));

    std::string wide = body;
    wide.replace(wide.find(" 200 "), 5, " 256 ");
    writeFile(dir.file("wide.ply"), header + wide);
    try {
        readMesh(dir.file("wide.ply"));
        ADD_FAILURE() << "a uchar value of 256 was read";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), dir.file("wide.ply") + ": vertex 2 has value '256' for the 8-bit unsigned "
                                                               "property 'flag' (0 to 255)");
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
    const std::string path = dir.file("near.off");
    writeFile(path, "OFF\n3 1 0\n0 0 10\n30 0 10\n0 30 10\n3 0 1 2\n");
    const SurfaceField near = readMesh(path);
    EXPECT_EQ(near.mesh.positions[1], glm::vec3(30, 0, 10));
    EXPECT_EQ(near.normalization.center, glm::dvec3(0.0));
    EXPECT_EQ(near.normalization.scale, 1.0);
    // A mesh further from its origin than it is long is kept relative to its box's centre (1005,
    // 2010, 3000) rounded to a multiple of 16, the largest power of two within its longest side, 20.
    const std::string farPath = dir.file("far.off");
    writeFile(farPath, "OFF\n3 1 0\n1000 2000 3000\n1010 2000 3000\n1000 2020 3000\n3 0 1 2\n");
    const SurfaceField far = readMesh(farPath);
    EXPECT_EQ(far.normalization.center, glm::dvec3(1008, 2016, 3008));
    EXPECT_EQ(far.mesh.positions[1], glm::vec3(2, -16, -8));
    EXPECT_EQ(far.normalization.meshFromNormalized(glm::dvec3(far.mesh.positions[2])), glm::dvec3(1000, 2020, 3000));
    EXPECT_EQ(describeMesh(farPath).bounds.hi, glm::dvec3(1010, 2020, 3000));
}

/// The sphere's points moved by @a offset (and -2 and 0.5 times it in y and z), one a line in
/// double precision, each after @a prefix.
std::string movedPoints(const SurfaceField& sphere, double offset, const char* prefix)
{
    std::string text;
    char line[128];
    for (const glm::vec3& p : sphere.mesh.positions) {
        std::snprintf(line, sizeof line, "%s%.17g %.17g %.17g\n", prefix, double(p.x) + offset,
                      double(p.y) - 2.0 * offset, double(p.z) + 0.5 * offset);
        text += line;
    }
    return text;
}

TEST(MeshReader, AMeshFarFromItsOriginKeepsItsShape)
{
    // The unit sphere moved a million and a billion units away, written in double precision (a
    // .vtk file's double POINTS, an OBJ's, an OFF's, an ASCII PLY's and an ASCII STL's text, a
    // binary PLY's double properties in either byte order): every triangle kept, and normalised
    // where the unmoved one is (compared corner by corner: an STL numbers its vertices as they appear).
    const SurfaceField sphere = makeSphere(4);
    SurfaceField unmoved = sphere;
    normalize(unmoved);
    const std::size_t points = sphere.mesh.positions.size(), triangles = sphere.mesh.triangles.size();
    std::string polygons, objFaces;  // "3 a b c" lines as VTK's POLYGONS and OFF list them; OBJ's from 1
    std::vector<std::string> pointLines[2];  // per offset, each point's "x y z" line
    for (int o = 0; o < 2; ++o) {
        std::istringstream lines(movedPoints(sphere, o == 0 ? 1e6 : -1e9, ""));
        for (std::string line; std::getline(lines, line);) pointLines[o].push_back(line);
    }
    for (const auto& t : sphere.mesh.triangles) {
        polygons += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + "\n";
        objFaces += "f " + std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " +
                    std::to_string(t[2] + 1) + "\n";
    }
    TempDir dir;
    for (const double offset : {1e6, -1e9})
        for (const std::string format : {"vtk", "obj", "off", "ply", "ply-le", "ply-be", "stl"}) {
            std::string text;
            if (format == "stl") {
                text = "solid far\n";
                for (const auto& t : sphere.mesh.triangles) {
                    text += "facet normal 0 0 0\n outer loop\n";
                    for (const std::uint32_t v : t) text += "  vertex " + pointLines[offset > 0.0 ? 0 : 1][v] + "\n";
                    text += " endloop\nendfacet\n";
                }
                text += "endsolid far\n";
            }
            const std::string plyHeader =
                " 1.0\nelement vertex " + std::to_string(points) +
                "\nproperty double x\nproperty double y\nproperty double z\nelement face " + std::to_string(triangles) +
                "\nproperty list uchar int vertex_indices\nend_header\n";
            if (format == "ply") text = "ply\nformat ascii" + plyHeader + movedPoints(sphere, offset, "") + polygons;
            if (format == "ply-le" || format == "ply-be") {
                Bytes body(format == "ply-be");
                for (const glm::vec3& q : sphere.mesh.positions)
                    body.put(double(q.x) + offset).put(double(q.y) - 2.0 * offset).put(double(q.z) + 0.5 * offset);
                for (const auto& t : sphere.mesh.triangles) body.triangle(t[0], t[1], t[2]);
                const char* encoding = format == "ply-be" ? "binary_big_endian" : "binary_little_endian";
                text = std::string("ply\nformat ") + encoding + plyHeader + body.str();
            }
            if (format == "vtk")
                text = "# vtk DataFile Version 3.0\nfar sphere\nASCII\nDATASET POLYDATA\nPOINTS " +
                       std::to_string(points) + " double\n" + movedPoints(sphere, offset, "") + "POLYGONS " +
                       std::to_string(triangles) + " " + std::to_string(4 * triangles) + "\n" + polygons;
            if (format == "obj") text = movedPoints(sphere, offset, "v ") + objFaces;
            if (format == "off")
                text = "OFF\n" + std::to_string(points) + " " + std::to_string(triangles) + " 0\n" +
                       movedPoints(sphere, offset, "") + polygons;
            const std::string path = dir.file("far-" + format + "." + format.substr(0, 3));
            writeFile(path, text);
            MeshReadReport report;
            SurfaceField far = readMesh(path, {}, &report);
            EXPECT_EQ(report.degenerateDropped, 0u) << format << " " << offset;
            ASSERT_EQ(far.mesh.triangles.size(), triangles) << format << " " << offset;
            normalize(far);
            ASSERT_EQ(far.mesh.positions.size(), points) << format << " " << offset;
            float worst = 0.0f;
            for (std::size_t t = 0; t < triangles; ++t)
                for (int k = 0; k < 3; ++k)
                    worst = std::max(worst, glm::length(far.mesh.positions[far.mesh.triangles[t][k]] -
                                                        unmoved.mesh.positions[unmoved.mesh.triangles[t][k]]));
            EXPECT_LT(worst, 1e-6f) << format << " " << offset;
            const glm::dvec3 back =
                far.normalization.meshFromNormalized(glm::dvec3(far.mesh.positions[far.mesh.triangles[0][0]]));
            EXPECT_NEAR(back.x, double(sphere.mesh.positions[sphere.mesh.triangles[0][0]].x) + offset, 1e-5)
                << format << " " << offset;
        }
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

TEST(MeshReader, PointsNoTriangleUsesAreLeftOutWithTheirData)
{
    // A unit square (points 0, 1, 3, 4) and, between them in the file, point 2 far away (and one
    // at the end), which no face uses, as VTK files often carry them.
    TempDir dir;
    writeFile(dir.file("u.ply"), "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\n"
                                 "property float z\nproperty float p\nelement face 2\nproperty list uchar int "
                                 "vertex_indices\nend_header\n0 0 0 10\n1 0 0 11\n1000 1000 1000 99\n1 1 0 13\n"
                                 "0 1 0 14\n0 0 500 -99\n3 0 1 3\n3 0 3 4\n");
    writeFile(dir.file("u.txt"), "20 21 -500 23 24 500\n");
    MeshReadReport report;
    SurfaceField field = readMesh(dir.file("u.ply"), {}, &report);
    EXPECT_EQ(report.unusedPointsDropped, 2u);
    ASSERT_EQ(field.mesh.positions.size(), 4u);
    const Bounds3 box = bounds(field.mesh);
    EXPECT_EQ(box.hi, glm::dvec3(1.0, 1.0, 0.0));
    ASSERT_EQ(field.arrays.size(), 1u);
    EXPECT_EQ(field.arrays[0].values, (std::vector<double>{10, 11, 13, 14}));
    // Each triangle still joins the same points, and each point keeps its own value.
    const std::vector<std::array<glm::vec3, 3>> corners = {{glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(1, 1, 0)},
                                                           {glm::vec3(0, 0, 0), glm::vec3(1, 1, 0), glm::vec3(0, 1, 0)}};
    ASSERT_EQ(field.mesh.triangles.size(), 2u);
    for (std::size_t t = 0; t < 2; ++t)
        for (int k = 0; k < 3; ++k) EXPECT_EQ(field.mesh.positions[field.mesh.triangles[t][k]], corners[t][k]);

    // A scalar file gives one value per point of the file; the same points' values are kept.
    field = readMesh(dir.file("u.ply"), {"", dir.file("u.txt"), false}, &report);
    EXPECT_EQ(field.values, (std::vector<float>{20, 21, 23, 24}));

    // info counts the file's points and bounds the ones drawn.
    const MeshInfo info = describeMesh(dir.file("u.ply"));
    EXPECT_EQ(info.vertices, 6u);
    EXPECT_EQ(info.report.unusedPointsDropped, 2u);
    EXPECT_EQ(info.bounds.hi, glm::dvec3(1.0, 1.0, 0.0));
    EXPECT_EQ(info.arrays.at(0).max, 14.0);
}

// ----------------------------------------------------------------------------------------------
// Scalars
// ----------------------------------------------------------------------------------------------

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
