// The program with VTK files and arrays: info lists point and cell arrays and the steps of a
// series (which sdf does not take); every command takes --scalar, --scalar-file and --cell-to-point; a cell array renders
// flat per triangle; a file with arrays and no choice shows its first point array and says so.
#include "cli_fixture.h"
#include "vtk_files.h"

#include <ivis/core/image_io.h>
#include <ivis/core/mesh_reader.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <string>

namespace ivis::app {
namespace {

using test::CliResult;
using test::runCli;
using test::sharedMesh;

std::string arteryStep()
{
    return sharedMesh("vtk/artery_series/artery_t0200.vtp");
}

TEST_F(Cli, InfoListsPointAndCellArrays)
{
    const CliResult result = runCli("info " + quoted(arteryStep()) + " --json");
    ASSERT_EQ(result.status, 0) << result.err;
    const nlohmann::json info = nlohmann::json::parse(result.out);
    EXPECT_EQ(info.at("format"), "vtp");
    EXPECT_EQ(info.at("vertices"), 1104);
    EXPECT_EQ(info.at("cells"), 2204);
    const nlohmann::json& arrays = info.at("arrays");
    ASSERT_EQ(arrays.size(), 2u);
    EXPECT_EQ(arrays[0].at("name"), "pressure");
    EXPECT_EQ(arrays[0].at("association"), "point");
    EXPECT_NEAR(arrays[0].at("min").get<double>(), 0.2294, 1e-4);  // pressure_t200 of MANIFEST.md
    EXPECT_NEAR(arrays[0].at("max").get<double>(), 0.7932, 1e-4);
    EXPECT_EQ(arrays[1].at("name"), "pressure_cell");
    EXPECT_EQ(arrays[1].at("association"), "cell");
    EXPECT_EQ(arrays[1].at("components"), 1);

    const CliResult text = runCli("info " + quoted(arteryStep()));
    ASSERT_EQ(text.status, 0) << text.err;
    EXPECT_NE(text.out.find("pressure_cell         cell   Float32  1 component"), std::string::npos) << text.out;
}

// info's columns line up in a terminal whatever the names' bytes: "τ_w" is 4 bytes in 3 columns,
// "壁面" 6 bytes in 4 columns (wide characters), a Latin-1 "pré" 3 bytes in 3; an array of NaN
// only has no range (min 0 max 0 read as a constant array) and JSON null, its name as U+FFFD
// where it is not UTF-8 (that made info --json an internal error).
TEST_F(Cli, InfoColumnsAlignForAnyNameAndNaNOnlyHasNoRange)
{
    const std::string path = input("names.vtk");
    std::string arrays;
    for (const char* name : {"ab", "\xcf\x84_w", "\xe5\xa3\x81\xe9\x9d\xa2", "pr%E9"})
        arrays += std::string("SCALARS ") + name + " float 1\nLOOKUP_TABLE default\n1 2 3\n";
    writeFile(path, "# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n0 0 0 1 0 0 0 1 0\n"
                    "POLYGONS 1 4\n3 0 1 2\nPOINT_DATA 3\n" + arrays +
                    "SCALARS gone float 1\nLOOKUP_TABLE default\nnan nan nan\n");
    const CliResult text = runCli("info " + quoted(path));
    ASSERT_EQ(text.status, 0) << text.err;
    const std::pair<const char*, std::size_t> pointAt[] = {
        {"    ab ", 26}, {"    \xcf\x84_w", 27}, {"    \xe5\xa3\x81", 28}, {"    pr\xe9", 26}};
    for (const auto& [start, byte] : pointAt) {
        const std::size_t line = text.out.find(start);
        ASSERT_NE(line, std::string::npos) << start;
        EXPECT_EQ(text.out.find(" point ", line), line + byte - 1) << start;  // the column after the padding
    }
    EXPECT_NE(text.out.find("gone                  point  Float32  1 component   no finite value  (3 NaN)"),
              std::string::npos) << text.out;
    const CliResult json = runCli("info " + quoted(path) + " --json");
    ASSERT_EQ(json.status, 0) << json.err;
    const nlohmann::json info = nlohmann::json::parse(json.out);
    EXPECT_EQ(info.at("arrays")[3].at("name"), "pr\xef\xbf\xbd");
    EXPECT_TRUE(info.at("arrays")[4].at("min").is_null() && info.at("arrays")[4].at("max").is_null());
}

TEST_F(Cli, InfoListsTheStepsOfASeriesAndSdfTakesOneStep)
{
    const std::string pvd = sharedMesh("vtk/artery_series/artery.pvd");
    const CliResult result = runCli("info " + quoted(pvd) + " --json");
    ASSERT_EQ(result.status, 0) << result.err;
    const nlohmann::json steps = nlohmann::json::parse(result.out).at("time_steps");
    ASSERT_EQ(steps.size(), 5u);
    for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(steps[i].at("time"), 200.0 * double(i + 1));
    // Its arrays, each with its range over every step: the least and greatest of the steps' own.
    const nlohmann::json arrays = nlohmann::json::parse(result.out).at("arrays");
    ASSERT_EQ(arrays.size(), 2u) << arrays.dump();
    for (const nlohmann::json& array : arrays) {
        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
        for (const nlohmann::json& step : steps) {
            const CliResult one = runCli("info " + quoted(step.at("file").get<std::string>()) + " --json");
            ASSERT_EQ(one.status, 0) << one.err;
            const nlohmann::json stepInfo = nlohmann::json::parse(one.out);
            for (const nlohmann::json& own : stepInfo.at("arrays"))
                if (own.at("name") == array.at("name") && own.at("association") == array.at("association"))
                    lo = std::min(lo, own.at("min").get<double>()), hi = std::max(hi, own.at("max").get<double>());
        }
        EXPECT_EQ(array.at("min").get<double>(), lo) << array.dump();
        EXPECT_EQ(array.at("max").get<double>(), hi) << array.dump();
        EXPECT_EQ(array.at("steps"), 5);
        EXPECT_LT(lo, hi);
    }
    EXPECT_EQ(arrays[0].at("name"), "pressure");
    EXPECT_EQ(arrays[1].at("name"), "pressure_cell");
    expectRejected(sdf(pvd), {pvd + ": a time series of 5 steps; this command takes one step's file",
                              "artery_t0200.vtp", "(render, optimize and the viewer take series)"});
}

TEST_F(Cli, FirstPointArrayIsShownWhenNoneIsChosen)
{
    const CliResult result = runCli(render(arteryStep()));
    ASSERT_EQ(result.status, 0) << result.err;
    EXPECT_NE(result.err.find(arteryStep() + ": showing the point array 'pressure' (choose another with --scalar NAME"),
              std::string::npos)
        << result.err;
    const CliResult chosen = runCli(render(arteryStep(), "--scalar pressure"));
    EXPECT_EQ(chosen.err.find("showing the point array"), std::string::npos) << chosen.err;
}

/// The "scalar" and "triangle" channels of a 96x96 render of the artery step with @a extra.
std::pair<std::vector<float>, std::vector<float>> renderedScalars(const std::string& folder, const std::string& extra)
{
    const std::string exr = folder + "/x.exr";
    const CliResult result = runCli("render " + quoted(arteryStep()) + " --volume-res 48 --res 96x96 -o " +
                                    quoted(folder + "/x.png") + " --exr " + quoted(exr) + " " + extra);
    EXPECT_EQ(result.status, 0) << result.err;
    if (result.status != 0) return {};
    return {core::readExrChannel(exr, "scalar"), core::readExrChannel(exr, "triangle")};
}

TEST_F(Cli, CellArrayIsFlatPerTriangleAndAveragedOnRequest)
{
    core::MeshReadOptions options;
    options.scalarName = "pressure_cell";
    const core::SurfaceField field = core::readMesh(arteryStep(), options);
    const auto [flat, triangles] = renderedScalars(mOutputs.path(), "--scalar pressure_cell");
    ASSERT_EQ(flat.size(), triangles.size());
    std::size_t shown = 0;
    for (std::size_t i = 0; i < flat.size(); ++i) {
        if (std::isnan(flat[i]) || triangles[i] < 0) continue;
        EXPECT_EQ(flat[i], field.values[std::size_t(triangles[i])]) << "pixel " << i;  // exactly its triangle's value
        ++shown;
    }
    EXPECT_GT(shown, 1000u);

    const auto [smooth, smoothTriangles] = renderedScalars(mOutputs.path(), "--scalar pressure_cell --cell-to-point");
    std::size_t blended = 0;
    for (std::size_t i = 0; i < smooth.size(); ++i) {
        if (std::isnan(smooth[i]) || smoothTriangles[i] < 0) continue;
        blended += smooth[i] != field.values[std::size_t(smoothTriangles[i])];
    }
    EXPECT_GT(blended, shown / 2) << "averaged onto vertices, the values vary across a triangle";
}

TEST_F(Cli, CellToPointAveragesACellArrayOrIsRefused)
{
    // It used to be ignored on a point array, on hot spots and on a file without cell arrays.
    expectRejected(render(arteryStep(), "--scalar pressure --cell-to-point"),
                   {arteryStep() + ": --cell-to-point averages a cell array; 'pressure' is a point array"});
    expectRejected(render(arteryStep(), "--hotspots 2 --cell-to-point"), {"--cell-to-point excludes --hotspots"});
    expectRejected(render(sharedMesh("stanford_bunny.ply"), "--cell-to-point"),
                   {"stanford_bunny.ply: --cell-to-point averages a cell array, and the file has none"});
    // Without --scalar it averages the file's cell array, not the point pressure shown by default.
    const CliResult result = runCli(render(arteryStep(), "--cell-to-point"));
    ASSERT_EQ(result.status, 0) << result.err;
    EXPECT_NE(result.err.find(": showing the cell array 'pressure_cell (averaged)'"), std::string::npos) << result.err;
}

TEST_F(Cli, EveryCommandTakesTheArrayOptions)
{
    for (const char* command : {"render", "optimize", "evaluate", "sdf"}) {
        const CliResult help = runCli(std::string(command) + " --help");
        EXPECT_EQ(help.status, 0) << command;
        for (const char* option : {"--scalar ", "--scalar-file", "--cell-to-point", ".vtp"})
            EXPECT_NE(help.out.find(option), std::string::npos) << command << " lacks " << option;
    }
    // A chosen component of a vector and a cell array through optimize's pipeline.
    const std::string vtu = input("tet.vtu");
    test::writeFile(vtu, R"(<VTKFile type="UnstructuredGrid" version="1.0">
<UnstructuredGrid><Piece NumberOfPoints="4" NumberOfCells="1">
<PointData><DataArray type="Float32" Name="v" NumberOfComponents="3" format="ascii">1 0 0 0 2 0 0 0 3 4 4 4</DataArray></PointData>
<CellData><DataArray type="Int32" Name="c" format="ascii">7</DataArray></CellData>
<Points><DataArray type="Float64" NumberOfComponents="3" format="ascii">0 0 0 1 0 0 0 1 0 0 0 1</DataArray></Points>
<Cells><DataArray type="Int32" Name="connectivity" format="ascii">0 1 2 3</DataArray>
<DataArray type="Int32" Name="offsets" format="ascii">4</DataArray>
<DataArray type="UInt8" Name="types" format="ascii">10</DataArray></Cells>
</Piece></UnstructuredGrid></VTKFile>
)");
    const std::string common = " --volume-res 48 --opt-res 16 --res 32x32 --steps 1 --cache-dir " + quoted(output("")) +
                               " -o " + quoted(output("best.png"));
    expectRejected("optimize " + quoted(vtu) + " --scalar v:3" + common,
                   {vtu + ": array 'v' has 3 components; '3' is not one of magnitude, 0..2"});
    EXPECT_EQ(runCli("optimize " + quoted(vtu) + " --scalar v:1" + common).status, 0);
    EXPECT_EQ(runCli("optimize " + quoted(vtu) + " --scalar c --energy scalar" + common).status, 0);
}

/// A unit square of two triangles as VTK XML PolyData.
test::VtkDataSet square()
{
    test::VtkDataSet d;
    d.points = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    d.polys = {{0, 1, 2, 0, 2, 3}, {3, 6}, {}};
    d.pointData = {{"p", "Float64", 1, std::vector<double>(4, 1.0)}};
    return d;
}

TEST_F(Cli, BadVtkFilesAreRejectedWithOneLineAndNothingWritten)
{
    std::string base64 = test::vtpText(square(), {});
    base64.erase(base64.find("</DataArray>", base64.find("Name=\"Points\"")) - 9, 8);
    const std::string truncated = input("truncated.vtp");
    test::writeFile(truncated, base64);
    expectMeshRejected(truncated, {truncated + ": Points: the base64 text ends early"});
    expectBadInput(runCli("info " + quoted(truncated)), {truncated + ": Points: the base64 text ends early"});

    test::VtkXmlLayout zlib;
    zlib.format = test::VtkXmlLayout::AppendedRaw;
    zlib.zlib = true;
    std::string packed = test::vtpText(square(), zlib);
    const std::size_t data = packed.find('_', packed.find("<AppendedData")) + 1;
    for (std::size_t i = 16; i < 20; ++i) packed[data + i] = char(~packed[data + i]);  // "p": its zlib stream
    const std::string corrupt = input("corrupt.vtp");
    test::writeFile(corrupt, packed);
    expectMeshRejected(corrupt, {corrupt + ": PointData array 'p': zlib block 0 of 1 is corrupt"});

    test::VtkDataSet quadratic = square();
    quadratic.cells = {{0, 1, 2, 3, 0, 1}, {6}, {22}};
    const std::string vtu = input("quadratic.vtu");
    test::writeFile(vtu, test::vtuText(quadratic, {}));
    expectMeshRejected(vtu, {vtu + ": cell 0 has type VTK_QUADRATIC_TRIANGLE (22), which is not read"});

    const std::string vtk = input("index.vtk");
    test::writeFile(vtk,
                    "# vtk DataFile Version 3.0\nx\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n0 0 0 1 0 0 0 1 0\n"
                    "POLYGONS 1 4\n3 0 1 3\n");
    expectMeshRejected(vtk, {vtk + ": cell 0 references point 3, but the file has 3 points"});

    const std::string pvd = input("series.pvd");
    test::writeFile(pvd,
                    "<VTKFile type=\"Collection\"><Collection><DataSet timestep=\"1\" file=\"gone.vtp\"/>"
                    "</Collection></VTKFile>");
    expectMeshRejected(pvd, {pvd + ": DataSet 0 names 'gone.vtp', which does not exist"});
    expectBadInput(runCli("info " + quoted(pvd)), {pvd + ": DataSet 0 names 'gone.vtp', which does not exist"});
}

}  // namespace
}  // namespace ivis::app
