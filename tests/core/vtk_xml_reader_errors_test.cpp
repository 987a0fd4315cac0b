// VTK XML files through readMesh on bad input: truncated and invalid base64, corrupt zlib blocks,
// counts that disagree with the data, unsupported cells, malformed and damaged files: one line, never a crash.
#include <ivis/core/errors.h>
#include <ivis/core/mesh_reader.h>
#include <ivis/core/surface_source.h>
#include <ivis/core/show_array.h>

#include "mesh_reader_files.h"
#include "test_support.h"
#include "vtk_files.h"
#include "vtk_xml_shapes.h"

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
using test::writeFile;

// ----------------------------------------------------------------------------------------------
// Bad input: one line "<path>: <problem>", exit status 2 in the program, never a crash
// ----------------------------------------------------------------------------------------------

/// The problem readMesh reports for a file holding @a text (written as @a name), or a marker.
std::string readError(const TempDir& dir, const std::string& text, const std::string& name = "bad.vtp")
{
    return readProblem(dir, text, name);
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

TEST(VtkXmlReader, RawAppendedDataShortOfItsArraysEndsEarlyBeforeItsClosingTags)
{
    TempDir dir;
    VtkXmlLayout layout;
    layout.format = VtkXmlLayout::AppendedRaw;
    std::string text = test::vtpText(cube(), layout);
    text.erase(text.rfind("\n</AppendedData>") - 8, 8);  // the last array's last 8 bytes, the closing tags kept
    const std::string message = readError(dir, text);
    EXPECT_NE(message.find("the appended data ends early"), std::string::npos) << message;
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
    EXPECT_EQ(readError(dir, replaced(text, "0 1 2 3 4 5 6 7 ", "0 1 2.5 3 4 5 6 7 ", "cell_id")),
              "CellData array 'cell_id': value 2 (2.5) does not fit the array's type Int32");
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
    // It said "the UnstructuredGrid has 0 pieces".
    EXPECT_EQ(readError(dir, replaced(text, "type=\"PolyData\"", "type=\"UnstructuredGrid\"")),
              "the file's type is UnstructuredGrid but it holds no <UnstructuredGrid> element");
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
    // The appended data: from its '_' to the closing tag.
    const std::size_t appendedBytes =
        appended.rfind("</AppendedData>") - appended.find('_', appended.find("<AppendedData")) - 1;
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

}  // namespace
}  // namespace ivis::core
