// VTK legacy .vtk files through readMesh: ASCII and big-endian binary, the classic cell lists and
// the OFFSETS/CONNECTIVITY lists of version 5, POLYDATA and UNSTRUCTURED_GRID, attribute arrays.
#include <ivis/core/mesh_reader.h>

#include "test_support.h"
#include "vtk_files.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <sstream>
#include <string>

namespace ivis::core {
namespace {

using test::TempDir;
using test::writeFile;

/// The XML name of a legacy type, for test::vtkBytes.
std::string xmlType(const std::string& legacy)
{
    static const std::map<std::string, std::string> kTypes = {
        {"float", "Float32"}, {"double", "Float64"},     {"int", "Int32"},           {"unsigned_char", "UInt8"},
        {"short", "Int16"},   {"vtktypeint64", "Int64"}, {"unsigned_long", "UInt64"}};
    return kTypes.at(legacy);
}

/// Writes legacy sections in ASCII or big-endian binary.
class LegacyFile {
public:
    LegacyFile(bool binary, const std::string& dataset) : mBinary(binary)
    {
        mText = "# vtk DataFile Version 5.1\ntest file\n" + std::string(binary ? "BINARY" : "ASCII") + "\nDATASET " +
                dataset + "\n";
    }
    /// A keyword line followed by @a values of legacy type @a type.
    LegacyFile& section(const std::string& line, const std::vector<double>& values, const std::string& type)
    {
        mText += line + "\n";
        if (mBinary) {
            mText += test::vtkBytes(values, xmlType(type), true) + "\n";
        } else {
            std::ostringstream text;
            text.precision(9);
            for (double v : values) text << v << ' ';
            mText += text.str() + "\n";
        }
        return *this;
    }
    /// A line of text as it is.
    LegacyFile& line(const std::string& text)
    {
        mText += text + "\n";
        return *this;
    }
    const std::string& str() const { return mText; }

private:
    bool mBinary;
    std::string mText;
};

// The cube of vtk_xml_reader_test: points 0..3 at z = 0, 4..7 at z = 1; cell 0 a vertex, cell 1
// a line, cells 2..7 quads; point arrays "typed" (0..7) and "velocity" (x, y, z), cell array
// "cell_id" (0..7).
const std::vector<double> kCubePoints = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
const std::vector<double> kQuads = {0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7};
const std::vector<double> kZeroToSeven = {0, 1, 2, 3, 4, 5, 6, 7};

/// The polygons come first in the file: VTK still numbers the cells vertices, lines, polygons.
std::string classicCube(bool binary)
{
    std::vector<double> polygons;
    for (std::size_t q = 0; q < 6; ++q) {
        polygons.push_back(4);
        polygons.insert(polygons.end(), kQuads.begin() + std::ptrdiff_t(4 * q),
                        kQuads.begin() + std::ptrdiff_t(4 * q + 4));
    }
    return LegacyFile(binary, "POLYDATA")
        .line("FIELD FieldData 1")
        .section("TIME 1 1 double", {1.5}, "double")
        .section("POINTS 8 float", kCubePoints, "float")
        .section("POLYGONS 6 30", polygons, "int")
        .section("VERTICES 1 2", {1, 0}, "int")
        .section("LINES 1 3", {2, 0, 6}, "int")
        .line("POINT_DATA 8")
        .section("SCALARS typed double 1\nLOOKUP_TABLE default", kZeroToSeven, "double")
        .section("VECTORS velocity float", kCubePoints, "float")
        .line("CELL_DATA 8")
        .line("FIELD FieldData 1")
        .section("cell_id 1 8 int", kZeroToSeven, "int")
        .str();
}

/// Version 5 lists: OFFSETS and CONNECTIVITY, METADATA after arrays.
std::string offsetsCube(bool binary)
{
    return LegacyFile(binary, "POLYDATA")
        .section("POINTS 8 double", kCubePoints, "double")
        .section("VERTICES 2 1\nOFFSETS vtktypeint64", {0, 1}, "vtktypeint64")
        .section("CONNECTIVITY vtktypeint64", {0}, "vtktypeint64")
        .section("LINES 2 2\nOFFSETS vtktypeint64", {0, 2}, "vtktypeint64")
        .section("CONNECTIVITY vtktypeint64", {0, 6}, "vtktypeint64")
        .section("POLYGONS 7 24\nOFFSETS vtktypeint64", {0, 4, 8, 12, 16, 20, 24}, "vtktypeint64")
        .section("CONNECTIVITY vtktypeint64", kQuads, "vtktypeint64")
        .line("POINT_DATA 8")
        .section("SCALARS typed double 1\nLOOKUP_TABLE default", kZeroToSeven, "double")
        .line(
            "METADATA\nINFORMATION 2\nNAME L2_NORM_RANGE LOCATION vtkDataArray\nDATA 2 0 7\n"
            "NAME L2_NORM_FINITE_RANGE LOCATION vtkDataArray\nDATA 2 0 7\n")
        .section("VECTORS velocity float", kCubePoints, "float")
        .line("METADATA\nCOMPONENT_NAMES\nX\nY\nZ\nINFORMATION 0\n")
        .line("CELL_DATA 8")
        .section("SCALARS cell_id int\nLOOKUP_TABLE default", kZeroToSeven, "int")
        .str();
}

void expectCube(const SurfaceField& field, const MeshReadReport& report, const std::string& context)
{
    SCOPED_TRACE(context);
    ASSERT_EQ(field.mesh.positions.size(), 8u);
    for (std::size_t i = 0; i < 8; ++i)
        EXPECT_EQ(field.mesh.positions[i],
                  glm::vec3(kCubePoints[3 * i], kCubePoints[3 * i + 1], kCubePoints[3 * i + 2]));
    ASSERT_EQ(field.mesh.triangles.size(), 12u);
    EXPECT_EQ(field.mesh.triangles[0], (std::array<std::uint32_t, 3>{0, 3, 2}));
    for (std::size_t t = 0; t < 12; ++t) EXPECT_EQ(field.triangleCells[t], 2 + t / 2) << "triangle " << t;
    ASSERT_EQ(field.arrays.size(), 3u);
    EXPECT_EQ(field.arrays[0].name, "typed");
    EXPECT_EQ(field.arrays[0].type, ValueType::Float64);
    EXPECT_EQ(field.arrays[0].values, kZeroToSeven);
    EXPECT_EQ(field.arrays[1].name, "velocity");
    EXPECT_EQ(field.arrays[1].components, 3);
    EXPECT_EQ(field.arrays[1].values, kCubePoints);
    EXPECT_EQ(field.arrays[2].name, "cell_id");
    EXPECT_EQ(field.arrays[2].association, Association::Cell);
    EXPECT_EQ(field.arrays[2].type, ValueType::Int32);
    EXPECT_EQ(field.arrays[2].values, kZeroToSeven);
    EXPECT_EQ(report.notes,
              std::vector<std::string>{"left out 1 vertex cell and 1 line cell: only surfaces are shown"});
}

TEST(VtkLegacyReader, ClassicAndOffsetListsInAsciiAndBinary)
{
    TempDir dir;
    for (const bool binary : {false, true}) {
        for (const bool offsets : {false, true}) {
            const std::string path = dir.file("cube.vtk");
            writeFile(path, offsets ? offsetsCube(binary) : classicCube(binary));
            MeshReadReport report;
            const SurfaceField field = readMesh(path, {}, &report);
            expectCube(field, report, std::string(binary ? "binary" : "ascii") + (offsets ? " offsets" : " classic"));
        }
    }
}

TEST(VtkLegacyReader, StripsNormalsTensorsAndEncodedNames)
{
    // Unit square as one strip 0 1 2 3: triangles (0,1,2) and (2,1,3).
    //  2 --- 3
    //  |   / |
    //  0 --- 1
    const std::string text =
        LegacyFile(false, "POLYDATA")
            .section("POINTS 4 float", {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}, "float")
            .section("TRIANGLE_STRIPS 1 5", {4, 0, 1, 2, 3}, "int")
            .line("POINT_DATA 4")
            .section("NORMALS normals float", {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, "float")
            .section("SCALARS wall%20shear%20stress float 2\nLOOKUP_TABLE default", {1, 2, 3, 4, 5, 6, 7, 8}, "float")
            .line("CELL_DATA 1")
            .section("TENSORS stress double", {1, 0, 0, 0, 2, 0, 0, 0, 3}, "double")
            .str();
    TempDir dir;
    writeFile(dir.file("s.vtk"), text);
    const SurfaceField field = readMesh(dir.file("s.vtk"), {"wall shear stress:1", ""});
    ASSERT_EQ(field.mesh.triangles.size(), 2u);
    EXPECT_EQ(field.mesh.triangles[1], (std::array<std::uint32_t, 3>{2, 1, 3}));
    EXPECT_EQ(field.triangleCells, (std::vector<std::uint32_t>{0, 0}));
    EXPECT_EQ(field.values, (std::vector<float>{2, 4, 6, 8}));
    ASSERT_EQ(field.arrays.size(), 3u);
    EXPECT_EQ(field.arrays[0].components, 3);
    EXPECT_EQ(field.arrays[1].name, "wall shear stress");
    EXPECT_EQ(field.arrays[1].components, 2);
    EXPECT_EQ(field.arrays[2].components, 9);
    EXPECT_EQ(field.arrays[2].association, Association::Cell);
}

TEST(VtkLegacyReader, UnstructuredTetrahedraShowTheirBoundary)
{
    // Two tetrahedra sharing the face 1-2-3 (vtk_xml_reader_test's), in both encodings.
    for (const bool binary : {false, true}) {
        const std::string text = LegacyFile(binary, "UNSTRUCTURED_GRID")
                                     .section("POINTS 5 float", {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1}, "float")
                                     .section("CELLS 2 10", {4, 0, 1, 2, 3, 4, 1, 3, 2, 4}, "int")
                                     .section("CELL_TYPES 2", {10, 10}, "int")
                                     .line("CELL_DATA 2")
                                     .section("SCALARS id float\nLOOKUP_TABLE default", {5, 7}, "float")
                                     .str();
        TempDir dir;
        writeFile(dir.file("t.vtk"), text);
        const SurfaceField field = readMesh(dir.file("t.vtk"), {"id", ""});
        ASSERT_EQ(field.mesh.triangles.size(), 6u) << binary;
        EXPECT_EQ(boundaryEdgeCount(field.mesh), 0u);
        for (std::size_t t = 0; t < 6; ++t) {
            EXPECT_EQ(field.values[t], field.triangleCells[t] == 0 ? 5.0f : 7.0f);
            const std::set<std::uint32_t> corners(field.mesh.triangles[t].begin(), field.mesh.triangles[t].end());
            EXPECT_NE(corners, (std::set<std::uint32_t>{1, 2, 3}));
        }
    }
}

}  // namespace
}  // namespace ivis::core
