// VTK XML .vtp and .vtu files through readMesh: every layout of binary data, every numeric type,
// point and cell arrays, cell numbering, volume boundaries, VMTK's and the series' real files.
#include <ivis/core/errors.h>
#include <ivis/core/mesh_reader.h>
#include <ivis/core/surface_source.h>
#include <ivis/core/show_array.h>

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
