// VTK XML .vtp and .vtu files through readMesh: every layout of binary data, every numeric type,
// point and cell arrays, cell numbering, volume boundaries, VMTK's and the series' real files.
#include <ivis/core/errors.h>
#include <ivis/core/mesh_reader.h>
#include <ivis/core/surface_source.h>
#include <ivis/core/show_array.h>

#include "test_support.h"
#include "vtk_files.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <tuple>
#include <string>

namespace ivis::core {
namespace {

using test::TempDir;
using test::VtkArray;
using test::VtkDataSet;
using test::VtkXmlLayout;
using test::writeFile;

/// Unit cube with a vertex cell and a line cell before its six quads:
///       7 ------ 6         points 0..3 at z = 0, 4..7 at z = 1
///      /|       /|         cell 0: vertex {0}; cell 1: line {0, 6}
///     4 ------ 5 |         cells 2..7: quads 0-3-2-1, 4-5-6-7, 0-1-5-4, 1-2-6-5, 2-3-7-6, 3-0-4-7
///     | 3 -----|-2         point arrays: "typed" (0..7, of the type under test), "velocity" (x, y, z)
///     |/       |/          cell array: "cell_id" (0..7, Int32)
///     0 ------ 1
VtkDataSet cube(const std::string& typedType = "Float64")
{
    VtkDataSet d;
    d.points = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
    d.verts = {{0}, {1}, {}};
    d.lines = {{0, 6}, {2}, {}};
    d.polys = {{0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7}, {4, 8, 12, 16, 20, 24}, {}};
    d.pointData = {{"typed", typedType, 1, {0, 1, 2, 3, 4, 5, 6, 7}}, {"velocity", "Float32", 3, d.points}};
    d.cellData = {{"cell_id", "Int32", 1, {0, 1, 2, 3, 4, 5, 6, 7}}};
    return d;
}

const DataArray* arrayNamed(const SurfaceField& field, const std::string& name)
{
    for (const DataArray& a : field.arrays)
        if (a.name == name) return &a;
    return nullptr;
}

/// Expects @a field to be the cube of cube(@a typedType), exactly.
void expectCube(const SurfaceField& field, ValueType typedType, const std::string& context)
{
    SCOPED_TRACE(context);
    const VtkDataSet d = cube();
    ASSERT_EQ(field.mesh.positions.size(), 8u);
    for (std::size_t i = 0; i < 8; ++i) {
        EXPECT_EQ(field.mesh.positions[i], glm::vec3(d.points[3 * i], d.points[3 * i + 1], d.points[3 * i + 2]));
    }
    ASSERT_EQ(field.mesh.triangles.size(), 12u);
    EXPECT_EQ(field.mesh.triangles[0], (std::array<std::uint32_t, 3>{0, 3, 2}));  // fan of quad 0-3-2-1
    EXPECT_EQ(field.mesh.triangles[1], (std::array<std::uint32_t, 3>{0, 2, 1}));
    ASSERT_EQ(field.triangleCells.size(), 12u);
    for (std::size_t t = 0; t < 12; ++t) EXPECT_EQ(field.triangleCells[t], 2 + t / 2) << "triangle " << t;
    EXPECT_EQ(boundaryEdgeCount(field.mesh), 0u);

    ASSERT_EQ(field.arrays.size(), 3u);
    const DataArray* typed = arrayNamed(field, "typed");
    ASSERT_NE(typed, nullptr);
    EXPECT_EQ(typed->type, typedType);
    EXPECT_EQ(typed->association, Association::Point);
    EXPECT_EQ(typed->values, (std::vector<double>{0, 1, 2, 3, 4, 5, 6, 7}));
    const DataArray* velocity = arrayNamed(field, "velocity");
    ASSERT_NE(velocity, nullptr);
    EXPECT_EQ(velocity->components, 3);
    EXPECT_EQ(velocity->values, d.points);
    const DataArray* cellId = arrayNamed(field, "cell_id");
    ASSERT_NE(cellId, nullptr);
    EXPECT_EQ(cellId->association, Association::Cell);
    EXPECT_EQ(cellId->type, ValueType::Int32);
    EXPECT_EQ(cellId->values, (std::vector<double>{0, 1, 2, 3, 4, 5, 6, 7}));
}

std::string describe(const VtkXmlLayout& l)
{
    static const char* const kFormats[] = {"ascii", "binary", "appended raw", "appended base64"};
    return std::string(kFormats[l.format]) + (l.zlib ? " zlib/" + std::to_string(l.blockSize) : "") +
           (l.header64 ? " UInt64" : " UInt32") + (l.bigEndian ? " big-endian" : "") +
           (l.oneBase64Run ? " one base64 run" : "");
}

/// Every layout: 4 formats x zlib (blocks of 20 bytes: a partial last block; of 32: none) x
/// header width x byte order x one or two base64 runs.
std::vector<VtkXmlLayout> everyLayout()
{
    std::vector<VtkXmlLayout> layouts;
    for (int format = 0; format < 4; ++format)
        for (int zlib = 0; zlib < 3; ++zlib)
            for (bool header64 : {false, true})
                for (bool bigEndian : {false, true})
                    for (bool oneRun : {false, true}) {
                        if (format == VtkXmlLayout::Ascii && (zlib > 0 || header64 || bigEndian || oneRun)) continue;
                        if (format == VtkXmlLayout::AppendedRaw && oneRun) continue;
                        VtkXmlLayout l;
                        l.format = VtkXmlLayout::Format(format);
                        l.zlib = zlib > 0;
                        l.blockSize = zlib == 1 ? 20 : 32;
                        l.header64 = header64;
                        l.bigEndian = bigEndian;
                        l.oneBase64Run = oneRun;
                        layouts.push_back(l);
                    }
    return layouts;
}

TEST(VtkXmlReader, EveryLayoutReadsTheSameCube)
{
    TempDir dir;
    const std::vector<VtkXmlLayout> layouts = everyLayout();
    EXPECT_EQ(layouts.size(), 1u + 3 * 2 * 2 * 2 + 3 * 2 * 2 + 3 * 2 * 2 * 2);  // ascii, binary, raw, base64
    for (const VtkXmlLayout& layout : layouts) {
        const std::string path = dir.file("cube.vtp");
        writeFile(path, test::vtpText(cube(), layout));
        MeshReadReport report;
        expectCube(readMesh(path, {}, &report), ValueType::Float64, describe(layout));
        EXPECT_EQ(report.notes,
                  std::vector<std::string>{"left out 1 vertex cell and 1 line cell: only surfaces are shown"})
            << describe(layout);
    }
}

TEST(VtkXmlReader, EveryNumericTypeInEveryEncoding)
{
    TempDir dir;
    const char* const kTypes[] = {"Int8",   "UInt8", "Int16",  "UInt16",  "Int32",
                                  "UInt32", "Int64", "UInt64", "Float32", "Float64"};
    for (int t = 0; t < 10; ++t) {
        for (int format = 0; format < 4; ++format) {
            VtkXmlLayout layout;
            layout.format = VtkXmlLayout::Format(format);
            layout.zlib = format != VtkXmlLayout::Ascii && t % 2 == 0;
            layout.bigEndian = format != VtkXmlLayout::Ascii && t % 3 == 0;
            VtkDataSet data = cube(kTypes[t]);
            data.pointType = t % 2 ? "Float32" : "Float64";
            data.indexType = kTypes[t];  // every type can index 8 points
            const std::string path = dir.file("typed.vtp");
            writeFile(path, test::vtpText(data, layout));
            expectCube(readMesh(path), ValueType(t), describe(layout) + " " + kTypes[t]);
        }
    }
}

TEST(VtkXmlReader, StripsAreCellsAfterThePolygons)
{
    // A strip 0 1 2 3 over the unit square (two triangles, the second turned back to keep the
    // winding) after one triangle 0 1 2: the strip is cell 1, its triangles are 1-2-3 ... below.
    //  2 --- 3
    //  |   / |
    //  0 --- 1      strip triangles: (0,1,2), (2,1,3)
    VtkDataSet d;
    d.points = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
    d.polys = {{0, 1, 2}, {3}, {}};
    d.strips = {{0, 1, 2, 3}, {4}, {}};
    d.cellData = {{"id", "Float32", 1, {10, 20}}};
    TempDir dir;
    writeFile(dir.file("s.vtp"), test::vtpText(d, {}));
    SurfaceField field = readMesh(dir.file("s.vtp"), {"id", ""});
    ASSERT_EQ(field.mesh.triangles.size(), 3u);
    EXPECT_EQ(field.mesh.triangles[1], (std::array<std::uint32_t, 3>{0, 1, 2}));
    EXPECT_EQ(field.mesh.triangles[2], (std::array<std::uint32_t, 3>{2, 1, 3}));
    EXPECT_EQ(field.triangleCells, (std::vector<std::uint32_t>{0, 1, 1}));
    EXPECT_EQ(field.values, (std::vector<float>{10, 20, 20}));
    EXPECT_EQ(field.valuesOn, Association::Cell);
}

/// Two tetrahedra sharing the face 1-2-3, and a triangle cell beside them:
///   points 0 (0,0,0) 1 (1,0,0) 2 (0,1,0) 3 (0,0,1) 4 (1,1,1) 5 (2,0,0)
///   cell 0: tetra 0 1 2 3; cell 1: tetra 1 2 3 4 (the mirror through 1-2-3); cell 2: triangle 1 5 2
VtkDataSet twoTetrahedra()
{
    VtkDataSet d;
    d.points = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1, 2, 0, 0};
    d.cells = {{0, 1, 2, 3, 1, 3, 2, 4, 1, 5, 2}, {4, 8, 11}, {10, 10, 5}};
    d.cellData = {{"cell", "Int32", 1, {0, 1, 2}}};
    return d;
}

TEST(VtkXmlReader, TetrahedraShowTheirBoundary)
{
    TempDir dir;
    writeFile(dir.file("t.vtu"), test::vtuText(twoTetrahedra(), {}));
    MeshReadReport report;
    const SurfaceField field = readMesh(dir.file("t.vtu"), {"cell", ""}, &report);
    // 8 faces, the shared one twice: 6 boundary triangles, and the triangle cell.
    ASSERT_EQ(field.mesh.triangles.size(), 7u);
    std::multiset<std::uint32_t> cells(field.triangleCells.begin(), field.triangleCells.end());
    EXPECT_EQ(cells.count(0), 3u);
    EXPECT_EQ(cells.count(1), 3u);
    EXPECT_EQ(cells.count(2), 1u);
    for (std::size_t t = 0; t < field.mesh.triangles.size(); ++t) {
        std::set<std::uint32_t> corners(field.mesh.triangles[t].begin(), field.mesh.triangles[t].end());
        EXPECT_NE(corners, (std::set<std::uint32_t>{1, 2, 3})) << "the shared face is inside";
        EXPECT_EQ(field.values[t], float(field.triangleCells[t]));
    }
    EXPECT_NE(std::find(report.notes.begin(), report.notes.end(), "showing the boundary of 2 volume cells (6 faces)"),
              report.notes.end());
}

TEST(VtkXmlReader, TetrahedronFacesPointOutward)
{
    VtkDataSet d = twoTetrahedra();
    d.cells = {{0, 1, 2, 3}, {4}, {10}};
    d.cellData.clear();
    TempDir dir;
    writeFile(dir.file("t.vtu"), test::vtuText(d, {}));
    const SurfaceField field = readMesh(dir.file("t.vtu"));
    ASSERT_EQ(field.mesh.triangles.size(), 4u);
    const glm::vec3 centre(0.25f);
    for (const auto& t : field.mesh.triangles) {
        const glm::vec3 a = field.mesh.positions[t[0]], b = field.mesh.positions[t[1]], c = field.mesh.positions[t[2]];
        const glm::vec3 n = glm::cross(b - a, c - a);
        EXPECT_GT(glm::dot(n, (a + b + c) / 3.0f - centre), 0.0f);
    }
}

TEST(VtkXmlReader, HexahedronWedgeAndPyramidBoundaries)
{
    // A unit hexahedron, a wedge on its top face and a pyramid on its side face: each pair shares
    // one quad face, so the boundary is 6 + 5 + 5 faces less 2 x 2 shared ones = 12 faces.
    VtkDataSet d;
    d.points = {0,   0,   0,  1,   0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1,  // hexahedron 0..7
                0.5, 0,   2,  0.5, 1, 2,                                                        // wedge ridge 8, 9
                2,   0.5, 0.5};                                                                 // pyramid apex 10
    d.cells = {{0, 1, 2, 3, 4, 5, 6, 7, 4, 5, 8, 7, 6, 9, 1, 2, 6, 5, 10}, {8, 14, 19}, {12, 13, 14}};
    TempDir dir;
    writeFile(dir.file("h.vtu"), test::vtuText(d, {}));
    MeshReadReport report;
    const SurfaceField field = readMesh(dir.file("h.vtu"), {}, &report);
    std::set<std::uint32_t> faces(field.triangleCells.begin(), field.triangleCells.end());
    EXPECT_EQ(faces, (std::set<std::uint32_t>{0, 1, 2}));
    EXPECT_EQ(boundaryEdgeCount(field.mesh), 0u);  // a closed surface
    EXPECT_EQ(componentCount(field.mesh), 1u);
    EXPECT_NE(std::find(report.notes.begin(), report.notes.end(), "showing the boundary of 3 volume cells (12 faces)"),
              report.notes.end());
}

// ----------------------------------------------------------------------------------------------
// Bad input: one line "<path>: <problem>", exit status 2 in the program, never a crash
// ----------------------------------------------------------------------------------------------

/// The message readMesh throws for a file holding @a text (written as @a name), or a marker.
std::string readError(const TempDir& dir, const std::string& text, const std::string& name = "bad.vtp")
{
    const std::string path = dir.file(name);
    writeFile(path, text);
    try {
        readMesh(path);
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        return message.substr(path.size() + 2);
    } catch (const std::exception& e) {
        return std::string("<not an InputError: ") + e.what() + ">";
    }
    return "<no error>";
}

/// @a text with the first @a from after @a anchor replaced by @a to.
std::string replaced(std::string text, const std::string& from, const std::string& to, const std::string& anchor = "")
{
    const std::size_t at = text.find(from, anchor.empty() ? 0 : text.find(anchor));
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

/// Where the content of the DataArray named @a name starts, and its length.
std::pair<std::size_t, std::size_t> arrayContent(const std::string& text, const std::string& name)
{
    const std::size_t begin = text.find('>', text.find("Name=\"" + name + "\"")) + 1;
    return {begin, text.find('<', begin) - begin};
}

TEST(VtkXmlReader, TruncatedAndInvalidBase64)
{
    TempDir dir;
    VtkXmlLayout binary;
    const std::string text = test::vtpText(cube(), binary);
    const auto [begin, length] = arrayContent(text, "Points");
    std::string cut = text;
    cut.erase(begin + length / 2, length - length / 2);
    EXPECT_EQ(readError(dir, cut), "Points: the base64 text ends early");
    std::string bad = text;
    bad[begin + 12] = '%';
    EXPECT_EQ(readError(dir, bad), "Points: '%' is not a base64 character here");

    VtkXmlLayout appended;
    appended.format = VtkXmlLayout::AppendedBase64;
    const std::string a = test::vtpText(cube(), appended);
    // Points, read first, start at base64 character 284.
    const std::size_t underscore = a.find("_", a.find("<AppendedData"));
    EXPECT_EQ(readError(dir, a.substr(0, underscore + 40)),
              "Points: offset 284 lies past the end of the appended data (39 characters)");
    EXPECT_EQ(readError(dir, a.substr(0, underscore + 1 + 284 + 20)), "Points: the base64 text ends early");
}

TEST(VtkXmlReader, CorruptZlibBlockAndCompressionHeaders)
{
    TempDir dir;
    VtkXmlLayout layout;
    layout.format = VtkXmlLayout::AppendedRaw;
    layout.zlib = true;
    const std::string text = test::vtpText(cube(), layout);
    // The first blob is "typed": 8 Float64 in one block, a 16-byte header, then the zlib stream.
    const std::size_t data = text.find('_', text.find("<AppendedData")) + 1;
    std::string corrupt = text;
    for (std::size_t i = 16; i < 24; ++i) corrupt[data + i] = char(~corrupt[data + i]);
    EXPECT_EQ(readError(dir, corrupt), "PointData array 'typed': zlib block 0 of 1 is corrupt");
    std::string tooLong = text;
    tooLong[data + 12 + 2] = '\x7f';  // the compressed size of block 0 grows by 8 MB
    EXPECT_EQ(readError(dir, tooLong), "PointData array 'typed': the compressed blocks run past the end of the data");
    // UInt64 sizes: a second block's size that would wrap the sum around stays past the data.
    layout.header64 = true;
    layout.blockSize = 40;  // "typed" (64 bytes) in two blocks: sizes at bytes 24..31 and 32..39
    std::string wrapping = test::vtpText(cube(), layout);
    const std::size_t start = wrapping.find('_', wrapping.find("<AppendedData")) + 1;
    for (std::size_t i = 32; i < 40; ++i) wrapping[start + i] = '\xff';
    EXPECT_EQ(readError(dir, wrapping), "PointData array 'typed': the compressed blocks run past the end of the data");
    std::string blocks = text;
    blocks[data + 3] = '\x7f';  // 2^31 blocks
    EXPECT_EQ(readError(dir, blocks), "PointData array 'typed': the compression header is longer than the data");
}

TEST(VtkXmlReader, CountsThatDisagreeWithTheData)
{
    TempDir dir;
    for (const int format : {VtkXmlLayout::Ascii, VtkXmlLayout::Binary}) {
        VtkXmlLayout layout;
        layout.format = VtkXmlLayout::Format(format);
        const std::string text = test::vtpText(cube(), layout);
        SCOPED_TRACE(format);
        EXPECT_EQ(readError(dir, replaced(text, "NumberOfPoints=\"8\"", "NumberOfPoints=\"9\"")),
                  "Points: the data holds 8 tuples, but NumberOfPoints says 9");
        EXPECT_EQ(readError(dir, replaced(text, "NumberOfPolys=\"6\"", "NumberOfPolys=\"5\"")),
                  "Polys offsets: the data holds 6 tuples, but NumberOfPolys says 5");
    }
    VtkXmlLayout ascii;
    ascii.format = VtkXmlLayout::Ascii;
    const std::string text = test::vtpText(cube(), ascii);
    EXPECT_EQ(readError(dir, replaced(text, "4 8 12 16 20 24", "4 8 12 16 20 26")),
              "Polys connectivity: the data holds 24 tuples, but the last offset says 26");
    EXPECT_EQ(readError(dir, replaced(text, "4 8 12 16 20 24", "4 8 6 16 20 24")),
              "Polys: the offsets decrease at cell 4");
    EXPECT_EQ(readError(dir, replaced(text, "0 1 2 3 4 5 6 7 ", "0 1 2 3 4 5 6 ", "cell_id")),
              "CellData array 'cell_id': the data holds 7 tuples, but NumberOfVerts+Lines+Polys+Strips says 8");
    // Found by vtk_xml_fuzzer: cell arrays of more than one component.
    std::string pairs = replaced(text, "NumberOfPolys=\"6\"", "NumberOfPolys=\"3\"");
    const std::size_t polysOffsets = pairs.find("Name=\"offsets\"", pairs.find("<Polys>"));
    pairs.replace(pairs.find("NumberOfComponents=\"1\"", polysOffsets), 22, "NumberOfComponents=\"2\"");
    EXPECT_EQ(readError(dir, pairs), "Polys offsets: 2 components, not 1");
    EXPECT_EQ(readError(dir, replaced(text, "0 3 2 1 ", "0 3 2 8 ")),
              "cell 2 references point 8, but the file has 8 points");
    EXPECT_EQ(readError(dir, replaced(text, "0 3 2 1 ", "0 3 2 -1 ")),
              "cell 2 references point -1, but the file has 8 points");
    EXPECT_EQ(readError(dir, replaced(text, "0 3 2 1 ", "0 3 2 1.5 ")),
              "Polys connectivity: value 1.5 at position 3 is not an index");
    EXPECT_EQ(readError(dir, replaced(text, "0 3 2 1 ", "0 3 2 one ")), "Polys connectivity: 'one' is not a number");
    EXPECT_EQ(readError(dir, replaced(text, "NumberOfComponents=\"3\"", "NumberOfComponents=\"2\"", "Name=\"Points\"")),
              "Points: the data holds 12 tuples, but NumberOfPoints says 8");
    EXPECT_EQ(readError(dir, replaced(text, "NumberOfComponents=\"3\"", "NumberOfComponents=\"5\"", "Name=\"Points\"")),
              "Points: the data holds 24 values, not a whole number of 5-component tuples");
}

TEST(VtkXmlReader, UnsupportedCellsAreNamed)
{
    TempDir dir;
    VtkDataSet d = twoTetrahedra();
    d.cells.types = {24, 10, 5};
    EXPECT_EQ(readError(dir, test::vtuText(d, {}), "bad.vtu"),
              "cell 0 has type VTK_QUADRATIC_TETRA (24), which is not read (surface cells, triangle strips and linear "
              "volume cells are)");
    d.cells.types = {10, 42, 5};
    EXPECT_NE(readError(dir, test::vtuText(d, {}), "bad.vtu").find("cell 1 has type VTK_POLYHEDRON (42)"),
              std::string::npos);
    d.cells.types = {12, 10, 5};
    EXPECT_EQ(readError(dir, test::vtuText(d, {}), "bad.vtu"), "cell 0 (VTK_HEXAHEDRON (12)) has 4 points, expected 8");
    d.cells.types = {10, 10, 44};
    EXPECT_EQ(readError(dir, test::vtuText(d, {}), "bad.vtu").substr(0, 47),
              "cell 2 has type 44, which is not read (surface ");
    VtkXmlLayout ascii;
    ascii.format = VtkXmlLayout::Ascii;
    d.cells.types = {10, 10, 300};
    EXPECT_EQ(readError(dir, test::vtuText(d, ascii), "bad.vtu"),
              "cell 2 has the cell type 300, which VTK does not define");
}

TEST(VtkXmlReader, MalformedFiles)
{
    TempDir dir;
    VtkXmlLayout ascii;
    ascii.format = VtkXmlLayout::Ascii;
    const std::string text = test::vtpText(cube(), ascii);
    EXPECT_EQ(readError(dir, "not xml at all"), "not valid XML (No document element found at byte 13)");
    EXPECT_EQ(readError(dir, "<PolyData/>"), "not a VTK XML file (no <VTKFile> element)");
    EXPECT_EQ(readError(dir, text.substr(0, text.size() / 2)).rfind("not valid XML (", 0), 0u);
    EXPECT_EQ(readError(dir, replaced(text, "type=\"PolyData\"", "type=\"ImageData\"")),
              "VTK XML type 'ImageData' is not read (PolyData and UnstructuredGrid are)");
    EXPECT_EQ(readError(dir, replaced(text, "</Piece>", "</Piece><Piece NumberOfPoints=\"0\"/>")),
              "the PolyData has 2 pieces; files with one piece are read");
    EXPECT_EQ(readError(dir, replaced(text, "header_type=\"UInt32\"", "compressor=\"vtkLZ4DataCompressor\"")),
              "compressor 'vtkLZ4DataCompressor' is not supported (vtkZLibDataCompressor is)");
    EXPECT_EQ(readError(dir, replaced(text, "header_type=\"UInt32\"", "header_type=\"UInt16\"")),
              "header_type 'UInt16' is not UInt32 or UInt64");
    EXPECT_EQ(readError(dir, replaced(text, "type=\"Float32\" Name=\"Points\"", "type=\"String\" Name=\"Points\"")),
              "Points: type 'String' is not a numeric type");
    EXPECT_EQ(readError(dir, replaced(text, "format=\"ascii\"", "format=\"appended\" offset=\"0\"", "Name=\"typed\"")),
              "PointData array 'typed': format is appended, but the file has no AppendedData");
    EXPECT_EQ(readError(dir, replaced(text, "<Points>", "<Pts>", "</CellData>")).rfind("not valid XML", 0), 0u);
    std::string noPoints = text;
    noPoints.erase(noPoints.find("<Points>"), noPoints.find("</Points>") + 9 - noPoints.find("<Points>"));
    EXPECT_EQ(readError(dir, noPoints), "the piece has 8 points but no <Points> DataArray");

    VtkXmlLayout raw;
    raw.format = VtkXmlLayout::AppendedRaw;
    const std::string appended = test::vtpText(cube(), raw);
    const std::size_t appendedBytes = appended.size() - appended.find('_', appended.find("<AppendedData")) - 1;
    EXPECT_EQ(readError(dir, replaced(appended, "offset=\"0\"", "offset=\"99999\"")),
              "PointData array 'typed': offset 99999 lies past the end of the appended data (" +
                  std::to_string(appendedBytes) + " bytes)");
    EXPECT_EQ(readError(dir, replaced(appended, "_", "#", "<AppendedData")), "AppendedData does not start with '_'");
    // A String array is left out with a note, the rest is read.
    MeshReadReport report;
    writeFile(dir.file("s.vtp"), replaced(text, "type=\"Float64\" Name=\"typed\"", "type=\"String\" Name=\"typed\""));
    EXPECT_EQ(readMesh(dir.file("s.vtp"), {}, &report).arrays.size(), 2u);
    EXPECT_NE(std::find(report.notes.begin(), report.notes.end(),
                        "left out PointData array 'typed' of type String: only numeric arrays are read"),
              report.notes.end());
}

TEST(VtkXmlReader, DamagedBytesNeverCrash)
{
    // Every layout, each byte of a sample of positions set to a random value: the reader returns
    // a mesh or one InputError line, nothing else (the fuzz target covers far more).
    TempDir dir;
    std::mt19937 rng(2024);
    std::size_t errors = 0, reads = 0;
    for (const VtkXmlLayout& layout : everyLayout()) {
        const std::string text = test::vtpText(cube(), layout);
        for (int trial = 0; trial < 20; ++trial) {
            std::string damaged = text;
            for (int k = 0; k < 3; ++k) damaged[rng() % damaged.size()] = char(rng());
            const std::string message = readError(dir, damaged);
            EXPECT_EQ(message.find("<not an InputError"), std::string::npos) << message;
            (message == "<no error>" ? reads : errors)++;
        }
    }
    EXPECT_GT(errors, 100u);
    EXPECT_GT(reads, 0u);  // damage to bytes no value depends on (whitespace, RangeMin) is harmless
}

// ----------------------------------------------------------------------------------------------
// Real files (../shared/meshes/vtk, see its README)
// ----------------------------------------------------------------------------------------------

std::string sharedVtk(const std::string& name)
{
    try {
        return test::sharedMesh("vtk/" + name);
    } catch (const std::exception& e) {
        ADD_FAILURE() << e.what();
        return {};
    }
}

TEST(VtkXmlReader, VmtkCompressedInlineWithInt64Connectivity)
{
    const std::string split = sharedVtk("vmtk_aorta_branch_split.vtp");
    const std::string metrics = sharedVtk("vmtk_aorta_branch_metrics.vtp");
    ASSERT_FALSE(split.empty() || metrics.empty());
    const MeshInfo info = describeMesh(split);
    EXPECT_EQ(info.vertices, 6826u);
    EXPECT_EQ(info.cells, 13288u);
    EXPECT_EQ(info.triangles, 13288u);
    // The README's arrays, in file order, with the type VMTK wrote.
    const std::vector<std::tuple<std::string, ValueType, int>> expected = {{"Scalars_", ValueType::Float32, 1},
                                                                           {"GroupIds", ValueType::Int32, 1},
                                                                           {"ClippingArray", ValueType::Float64, 1},
                                                                           {"Normals_", ValueType::Float32, 3}};
    ASSERT_EQ(info.arrays.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ(info.arrays[i].name, std::get<0>(expected[i]));
        EXPECT_EQ(info.arrays[i].type, std::get<1>(expected[i]));
        EXPECT_EQ(info.arrays[i].components, std::get<2>(expected[i]));
    }
    // The RangeMin/RangeMax VMTK wrote beside each array.
    EXPECT_EQ(info.arrays[1].min, 0.0);
    EXPECT_EQ(info.arrays[1].max, 3.0);
    EXPECT_NEAR(info.arrays[2].min, -2.7454885876e-07, 1e-16);
    EXPECT_NEAR(info.arrays[2].max, 2174.4532371, 1e-7);
    EXPECT_NEAR(info.arrays[3].min, 0.93662568108, 1e-6);  // |normal|
    EXPECT_NEAR(info.arrays[3].max, 1.0000000407, 1e-6);
    // <PointData Scalars="ClippingArray">: the active scalars, shown when no array is chosen.
    const SurfaceField shown = loadSurface(split);
    for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_EQ(shown.arrays[i].activeScalars, i == 2) << i;
    EXPECT_EQ(shown.name, "ClippingArray");

    // The metrics file is the same surface with two more arrays.
    const SurfaceField a = readMesh(split);
    const SurfaceField b = readMesh(metrics, {"AngularMetric", ""});
    EXPECT_EQ(a.mesh.positions, b.mesh.positions);
    EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
    EXPECT_NEAR(finiteRange(b.values).first, -3.1413507096, 1e-6);
    EXPECT_NEAR(finiteRange(b.values).second, 3.1408430693, 1e-6);
}

TEST(VtkXmlReader, VmtkAppendedBase64CowIsTheSharedCow)
{
    const std::string vtp = sharedVtk("vmtk_cow_appended.vtp");
    ASSERT_FALSE(vtp.empty());
    const SurfaceField cow = readMesh(vtp);
    const SurfaceField ply = readMesh(test::sharedMesh("cow.ply"));
    // The same points, numbered differently, and 3263 polygons that fan into as many triangles
    // as the PLY has (which split some quads along the other diagonal).
    EXPECT_EQ(describeMesh(vtp).cells, 3263u);
    EXPECT_EQ(cow.mesh.triangles.size(), ply.mesh.triangles.size());
    using Point = std::array<float, 3>;
    const auto point = [](const SurfaceField& f, std::uint32_t v) {
        return Point{f.mesh.positions[v].x, f.mesh.positions[v].y, f.mesh.positions[v].z};
    };
    std::multiset<Point> cowPoints, plyPoints;
    for (std::uint32_t v = 0; v < cow.mesh.positions.size(); ++v) cowPoints.insert(point(cow, v));
    for (std::uint32_t v = 0; v < ply.mesh.positions.size(); ++v) plyPoints.insert(point(ply, v));
    EXPECT_EQ(cowPoints, plyPoints);
    // Every polygon's own edges (those its fan triangles do not share) are edges of the PLY.
    std::set<std::pair<Point, Point>> plyEdges;
    for (const auto& t : ply.mesh.triangles)
        for (int k = 0; k < 3; ++k) plyEdges.insert(std::minmax(point(ply, t[k]), point(ply, t[(k + 1) % 3])));
    std::map<std::uint32_t, std::map<std::pair<Point, Point>, int>> polygonEdges;
    for (std::size_t t = 0; t < cow.mesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            ++polygonEdges[cow.triangleCells[t]][std::minmax(point(cow, cow.mesh.triangles[t][k]),
                                                             point(cow, cow.mesh.triangles[t][(k + 1) % 3]))];
    EXPECT_EQ(polygonEdges.size(), 3263u);
    std::set<std::pair<Point, Point>> outlines;
    for (const auto& [cell, edges] : polygonEdges)
        for (const auto& [edge, uses] : edges)
            if (uses == 1) {
                EXPECT_EQ(plyEdges.count(edge), 1u) << "polygon " << cell;
                outlines.insert(edge);
            }
    // The PLY's other edges are one diagonal for each triangle a polygon adds beyond its first.
    EXPECT_EQ(outlines.size() + (ply.mesh.triangles.size() - 3263u), plyEdges.size());
}

TEST(VtkXmlReader, ArterySeriesMatchesTheVampyPly)
{
    const std::string ply = test::sharedMesh("vampy_artery_cfd_pressure.ply");
    for (const char* step : {"0200", "0400", "0600", "0800", "1000"}) {
        const std::string vtp = sharedVtk(std::string("artery_series/artery_t") + step + ".vtp");
        ASSERT_FALSE(vtp.empty());
        const SurfaceField point = readMesh(vtp, {"pressure", ""});
        const SurfaceField original = readMesh(ply, {"pressure_t" + std::to_string(std::stoi(step)), ""});
        EXPECT_EQ(point.mesh.positions, original.mesh.positions) << step;
        EXPECT_EQ(point.mesh.triangles, original.mesh.triangles) << step;
        EXPECT_EQ(point.values, original.values) << step;
        // pressure_cell is the mean of each triangle's corner values (the README).
        const SurfaceField cell = readMesh(vtp, {"pressure_cell", ""});
        ASSERT_EQ(cell.valuesOn, Association::Cell);
        for (std::size_t t = 0; t < cell.mesh.triangles.size(); ++t) {
            const auto& c = cell.mesh.triangles[t];
            const float mean = (original.values[c[0]] + original.values[c[1]] + original.values[c[2]]) / 3.0f;
            EXPECT_NEAR(cell.values[t], mean, 1e-6f) << step << " triangle " << t;
        }
    }
}

}  // namespace
}  // namespace ivis::core
