// VTK legacy .vtk files through readMesh: ASCII and big-endian binary, the classic cell lists and
// the OFFSETS/CONNECTIVITY lists of version 5, POLYDATA and UNSTRUCTURED_GRID, attribute arrays.
#include <ivis/core/errors.h>
#include <ivis/core/mesh_reader.h>
#include <ivis/core/surface_source.h>

#include "mesh_reader_files.h"
#include "test_support.h"
#include "vtk_files.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
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
    // `info` gives the range a picture can draw: cells 0 and 1 (the vertex and the line) are not drawn.
    const std::vector<ArrayInfo> info = describeArrays(field);
    EXPECT_EQ(std::make_pair(info[2].min, info[2].max), std::make_pair(2.0, 7.0));
    EXPECT_EQ(std::make_pair(info[0].min, info[0].max), std::make_pair(0.0, 7.0));  // a point array: every point
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
            .section("SCALARS second float 1\nLOOKUP_TABLE default", {1, 2, 3, 4}, "float")
            .line("CELL_DATA 1")
            .section("TENSORS stress double", {1, 0, 0, 0, 2, 0, 0, 0, 3}, "double")
            .section("SCALARS cell_id float\nLOOKUP_TABLE default", {5}, "float")
            .str();
    TempDir dir;
    writeFile(dir.file("s.vtk"), text);
    const SurfaceField field = readMesh(dir.file("s.vtk"), {"wall shear stress:1", ""});
    ASSERT_EQ(field.mesh.triangles.size(), 2u);
    EXPECT_EQ(field.mesh.triangles[1], (std::array<std::uint32_t, 3>{2, 1, 3}));
    EXPECT_EQ(field.triangleCells, (std::vector<std::uint32_t>{0, 0}));
    EXPECT_EQ(field.values, (std::vector<float>{2, 4, 6, 8}));
    ASSERT_EQ(field.arrays.size(), 5u);
    EXPECT_EQ(field.arrays[0].components, 3);
    EXPECT_EQ(field.arrays[1].name, "wall shear stress");
    EXPECT_EQ(field.arrays[1].components, 2);
    EXPECT_EQ(field.arrays[3].components, 9);
    EXPECT_EQ(field.arrays[3].association, Association::Cell);
    // Each section's first SCALARS are its active scalars (vtkDataReader's); the point data's are
    // shown by default.
    for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(field.arrays[i].activeScalars, i == 1 || i == 4) << i;
    EXPECT_EQ(loadSurface(dir.file("s.vtk")).name, "wall shear stress magnitude");
}

TEST(VtkLegacyReader, MetadataAfterEveryFieldArrayAsParaViewWritesIt)
{
    for (const bool binary : {false, true}) {
        const std::string text =
            LegacyFile(binary, "POLYDATA")
                .section("POINTS 4 float", {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}, "float")
                .section("TRIANGLE_STRIPS 1 5", {4, 0, 1, 2, 3}, "int")
                .line("POINT_DATA 4")
                .line("FIELD FieldData 2")
                .section("p 1 4 double", {1, 2, 3, 4}, "double")
                .line("METADATA\nCOMPONENT_NAMES\nP\n")
                .section("U 3 4 float", {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1}, "float")
                .line("METADATA\nINFORMATION 1\nNAME L2_NORM_RANGE LOCATION vtkDataArray\nDATA 2 1 1.7\n")
                .str();
        TempDir dir;
        writeFile(dir.file("f.vtk"), text);
        const SurfaceField field = readMesh(dir.file("f.vtk"), {"U:2", ""});
        ASSERT_EQ(field.arrays.size(), 2u) << binary;
        EXPECT_EQ(field.arrays[0].name, "p");
        EXPECT_EQ(field.arrays[1].name, "U");
        EXPECT_EQ(field.values, (std::vector<float>{0, 0, 1, 1})) << binary;
    }
}

// A `bit` array (as vtkBitArray writes it): ASCII 0s and 1s, or in binary bits packed eight to a
// byte with the first in the highest bit, the last byte padded; read as UInt8 0 and 1, and the
// array after it read from where the bits end.
TEST(VtkLegacyReader, BitArraysAreReadAsZerosAndOnes)
{
    const std::vector<double> flags = {1, 0, 1, 1, 0, 0, 0, 1, 0, 1, 1, 1};  // 2 x 6 bits: 0xB1, then 0x70
    for (const bool binary : {false, true}) {
        LegacyFile file(binary, "POLYDATA");
        file.section("POINTS 6 float", {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 2, 0, 0, 2, 1, 0}, "float")
            .section("POLYGONS 4 16", {3, 0, 1, 2, 3, 1, 3, 2, 3, 1, 4, 3, 3, 4, 5, 3}, "int")
            .line("POINT_DATA 6");
        if (binary) {
            file.line("SCALARS flags bit 2\nLOOKUP_TABLE default\n\xB1\x70");
        } else {
            file.section("SCALARS flags bit 2\nLOOKUP_TABLE default", {1, 0, 7, 1, 0, 0, 0, 1, 0, 1, 1, 1}, "int");
        }
        file.section("SCALARS after float 1\nLOOKUP_TABLE default", {0, 1, 2, 3, 4, 5}, "float");
        TempDir dir;
        writeFile(dir.file("b.vtk"), file.str());
        const SurfaceField field = readMesh(dir.file("b.vtk"), {"flags:0", ""});
        ASSERT_EQ(field.arrays.size(), 2u) << binary;
        EXPECT_EQ(field.arrays[0].type, ValueType::UInt8);
        EXPECT_EQ(field.arrays[0].components, 2);
        EXPECT_EQ(field.arrays[0].values, flags) << binary << " (ASCII: any number but 0 is 1, as VTK reads it)";
        EXPECT_EQ(field.arrays[1].values, (std::vector<double>{0, 1, 2, 3, 4, 5})) << binary;
    }
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

// ----------------------------------------------------------------------------------------------
// Bad input: one line "<path>: <problem>", never a crash
// ----------------------------------------------------------------------------------------------

/// The problem readMesh reports for a .vtk file holding @a text, or a marker.
std::string readError(const TempDir& dir, const std::string& text)
{
    return readProblem(dir, text, "bad.vtk");
}

std::string replaced(std::string text, const std::string& from, const std::string& to)
{
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

TEST(VtkLegacyReader, HeadersDatasetsAndKeywords)
{
    TempDir dir;
    const std::string cube = classicCube(false);
    EXPECT_EQ(readError(dir, "hello\n"), "not a VTK legacy file (no '# vtk DataFile Version' line)");
    EXPECT_EQ(readError(dir, replaced(cube, "ASCII", "TEXT")), "the third line is not ASCII or BINARY");
    EXPECT_EQ(readError(dir, replaced(cube, "DATASET POLYDATA", "DATASET STRUCTURED_POINTS")),
              "DATASET STRUCTURED_POINTS is not read (POLYDATA and UNSTRUCTURED_GRID are)");
    EXPECT_EQ(readError(dir, replaced(cube, "VECTORS velocity float", "VECTORS velocity string")),
              "VECTORS: data type 'string' is not a numeric type");
    EXPECT_EQ(readError(dir, cube + "SPLINES 3\n"), "'SPLINES' is not a section of a polydata file");
    // Bytes quoted from the file stay printable, on one line.
    EXPECT_EQ(readError(dir, cube + std::string("SP\0L\x1bINES 3\n", 11)),
              "'SP\\x00L\\x1bINES' is not a section of a polydata file");
    EXPECT_EQ(readError(dir, replaced(cube, "POINTS 8 float", "POINTS eight float")), "POINTS: 'eight' is not a count");
    EXPECT_EQ(readError(dir, replaced(cube, "VECTORS velocity float", "COLOR_SCALARS c 4000000000")),
              "COLOR_SCALARS c: 4000000000 components");
    // ASCII values an integer array's type does not hold (VTK's stream would stop inside them).
    EXPECT_EQ(readError(dir, replaced(cube, "cell_id 1 8 int\n0 ", "cell_id 1 8 int\n-0.5 ")),
              "FIELD array cell_id: value 0 (-0.5) does not fit the array's type Int32");
    EXPECT_EQ(readError(dir, replaced(cube, "cell_id 1 8 int\n0 ", "cell_id 1 8 unsigned_char\n-1 ")),
              "FIELD array cell_id: value 0 (-1) does not fit the array's type UInt8");
}

TEST(VtkLegacyReader, TruncatedData)
{
    TempDir dir;
    const std::string ascii = classicCube(false);
    const std::size_t points = ascii.find("POINTS 8 float\n") + 15;
    std::size_t cut = points;
    for (int token = 0; token < 22; ++token) cut = ascii.find(' ', cut) + 1;  // 22 of the 24 coordinates
    EXPECT_EQ(readError(dir, ascii.substr(0, cut)), "POINTS: the file ends after 22 of its 24 values");
    const std::string binary = classicCube(true);
    EXPECT_EQ(readError(dir, binary.substr(0, binary.find("POINTS 8 float\n") + 15 + 22 * 4)),
              "POINTS: the file ends within its 24 binary values");
    EXPECT_EQ(readError(dir, binary.substr(0, binary.find("LINES 1 3\n") + 10 + 5)),
              "LINES: the file ends within its 3 binary values");
    EXPECT_EQ(readError(dir, binary.substr(0, binary.find("CELL_DATA 8\n")) + "CELL_DATA 8\nSCALARS b bit 2\n\xff"),
              "SCALARS b: the file ends within its 16 binary bits");
}

TEST(VtkLegacyReader, CountsAndIndicesThatDisagreeWithTheData)
{
    TempDir dir;
    for (const bool binary : {false, true}) {
        SCOPED_TRACE(binary);
        const std::string cube = classicCube(binary);
        EXPECT_EQ(readError(dir, replaced(cube, "POINT_DATA 8", "POINT_DATA 9")),
                  "POINT_DATA 9 disagrees with the file's 8 points");
        EXPECT_EQ(readError(dir, replaced(cube, "CELL_DATA 8", "CELL_DATA 6")),
                  "CELL_DATA 6 disagrees with the file's 8 cells");
        EXPECT_EQ(readError(dir, replaced(cube, "cell_id 1 8 int", "cell_id 1 7 int")),
                  "FIELD array cell_id has 7 tuples, but CELL_DATA says 8");
        const std::string offsets = offsetsCube(binary);
        // Four values more than the header says: they are not a section.
        const std::string message = readError(dir, replaced(offsets, "POLYGONS 7 24", "POLYGONS 7 20"));
        EXPECT_NE(message.find("is not a section of a polydata file"), std::string::npos) << message;
    }
    const std::string cube = classicCube(false);
    EXPECT_EQ(readError(dir, replaced(cube, "POLYGONS 6 30\n4 0 3 2 1", "POLYGONS 6 30\n4 0 3 2 8")),
              "cell 2 references point 8, but the file has 8 points");
    EXPECT_EQ(readError(dir, replaced(cube, "POLYGONS 6 30\n4 0 3 2 1", "POLYGONS 6 30\n99 0 3 2 1")),
              "POLYGONS: cell 0 has 99 points, more than the list holds");
    EXPECT_EQ(readError(dir, replaced(cube, "POLYGONS 6 30\n4 0 3 2 1", "POLYGONS 6 30\n9 0 3 2 1")),
              "POLYGONS: the list of 30 values ends within cell 5");
    EXPECT_EQ(readError(dir, replaced(cube, "POLYGONS 6 30", "POLYGONS 5 30")),
              "POLYGONS: 5 cells use 25 values, but the header says 30");
    EXPECT_EQ(readError(dir, replaced(offsetsCube(false), "0 4 8 12 16 20 24", "0 4 8 12 16 20 28")),
              "POLYGONS: the offsets end at 28 but the connectivity has 24 values");
    EXPECT_EQ(readError(dir, replaced(offsetsCube(false), "0 4 8 12 16 20 24", "0 4 8 6 16 20 24")),
              "POLYGONS: the offsets decrease at cell 4");
    EXPECT_EQ(readError(dir, replaced(offsetsCube(false), "0 4 8 12 16 20 24", "1 4 8 12 16 20 24")),
              "POLYGONS: the offsets do not start at 0");
}

TEST(VtkLegacyReader, UnsupportedAndMalformedCells)
{
    TempDir dir;
    const auto grid = [](const std::string& types) {
        return LegacyFile(false, "UNSTRUCTURED_GRID")
            .section("POINTS 5 float", {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1}, "float")
            .section("CELLS 2 10", {4, 0, 1, 2, 3, 4, 1, 3, 2, 4}, "int")
            .line(types)
            .str();
    };
    EXPECT_EQ(readError(dir, grid("CELL_TYPES 2\n10 24")),
              "cell 1 has type VTK_QUADRATIC_TETRA (24), which is not read (surface cells, triangle strips and "
              "linear volume cells are)");
    EXPECT_EQ(readError(dir, grid("CELL_TYPES 2\n10 16")).substr(0, 42), "cell 1 has type VTK_HEXAGONAL_PRISM (16), ");
    EXPECT_EQ(readError(dir, grid("CELL_TYPES 2\n10 13")), "cell 1 (VTK_WEDGE (13)) has 4 points, expected 6");
    EXPECT_EQ(readError(dir, grid("CELL_TYPES 2\n10 -1")), "cell 1 has the cell type -1, which VTK does not define");
    EXPECT_EQ(readError(dir, grid("CELL_TYPES 3\n10 10 10")), "CELL_TYPES lists 3 cells, but CELLS has 2");
    EXPECT_EQ(readError(dir, grid("POINT_DATA 5")), "CELLS are not followed by CELL_TYPES");
}

TEST(VtkLegacyReader, DamagedBytesNeverCrash)
{
    TempDir dir;
    std::mt19937 rng(77);
    std::size_t errors = 0;
    for (const std::string& text : {classicCube(false), classicCube(true), offsetsCube(false), offsetsCube(true)}) {
        for (int trial = 0; trial < 60; ++trial) {
            std::string damaged = text;
            for (int k = 0; k < 3; ++k) damaged[rng() % damaged.size()] = char(rng());
            const std::string message = readError(dir, damaged);
            EXPECT_EQ(message.find("<not an InputError"), std::string::npos) << message;
            errors += message != "<no error>";
        }
    }
    EXPECT_GT(errors, 60u);
}

}  // namespace
}  // namespace ivis::core
