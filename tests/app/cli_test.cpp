// The `inversevis` program as a user runs it: exit statuses, the one-line error contract, and
// that bad input never leaves an output (or a temporary) behind.
#include "cli_fixture.h"

#include <gtest/gtest.h>
#include <ivis/core/camera.h>
#include <ivis/core/image_io.h>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <sys/stat.h>
#include <sys/wait.h>
#include <csignal>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace ivis::app {
namespace {

namespace fs = std::filesystem;
using test::CliResult;
using test::runCli;
using test::sharedMesh;
using test::TempDir;
using test::writeFile;

/// One triangle: 3 vertices, OBJ numbering from 1.
constexpr const char* kTriangleObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

/// A closed tetrahedron 1-2-3-4 plus the zero-area triangle 1-5-2 (vertex 5 lies on edge 1-2),
/// which reading drops and logs.
constexpr const char* kTetraWithDegenerateObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 0.5 0 0\n"
                                                "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\nf 1 5 2\n";

// ----------------------------------------------------------------------------------------------
// Bad mesh files
// ----------------------------------------------------------------------------------------------

TEST_F(Cli, MissingFile)
{
    const std::string path = input("missing.ply");
    expectMeshRejected(path, {path + ": file not found"});
    expectBadInput(runCli("info " + quoted(path)), {path + ": file not found"});
}

TEST_F(Cli, UnreadableFile)
{
    expectMeshRejected(mInputs.path(), {mInputs.path() + ": is a directory, not a file"});

    const std::string path = input("locked.obj");
    writeFile(path, kTriangleObj);
    ASSERT_EQ(::chmod(path.c_str(), 0), 0);
    // root reads anything: run the program as "nobody". Real and effective ids both change (the
    // shell would reset an effective id alone); the saved id stays root so that we can return.
    const bool root = ::geteuid() == 0;
    if (root) {
        ASSERT_EQ(::setresuid(65534, 65534, 0), 0);
    }
    const CliResult result = runCli(sdf(path));
    if (root) {
        ASSERT_EQ(::setresuid(0, 0, 0), 0);
    }
    expectBadInput(result, {path + ": cannot read file (permission denied)"});
    EXPECT_EQ(contents(mOutputs.path()), std::vector<std::string>{});
}

TEST_F(Cli, UnknownFormat)
{
    const std::string path = input("points.xyz");
    writeFile(path, "0 0 0\n1 0 0\n0 1 0\n");
    expectMeshRejected(path, {path + ": unknown mesh format '.xyz' (expected .obj, .off, .ply, .stl, .vtk, .vtp, .vtu)"});
}

TEST_F(Cli, TextInAPlyFile)
{
    const std::string path = input("notes.ply");
    writeFile(path, "this is not a mesh\n");
    expectMeshRejected(path, {path + ": not a valid PLY mesh"});
}

TEST_F(Cli, RandomBytesInAnStlFile)
{
    std::mt19937 rng(11);
    std::string noise(300, '\0');
    for (char& c : noise) c = char(rng());
    const std::string path = input("noise.stl");
    writeFile(path, noise);
    expectMeshRejected(path, {path + ": not a valid STL mesh"});
}

TEST_F(Cli, ZeroTriangles)
{
    const std::string path = input("points.obj");
    writeFile(path, "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    expectMeshRejected(path, {path + ": mesh has no triangles"});
}

TEST_F(Cli, NonFiniteCoordinates)
{
    const std::string obj = input("nan.obj");
    writeFile(obj, "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n");
    expectMeshRejected(obj, {obj + ": vertex 2 has a non-finite coordinate"});  // OBJ counts from 1
    const std::string off = input("inf.off");
    writeFile(off, "OFF\n3 1 0\n0 0 0\n1 0 inf\n0 1 0\n3 0 1 2\n");
    expectMeshRejected(off, {off + ": vertex 1 has a non-finite coordinate"});
}

TEST_F(Cli, OutOfRangeIndexInObj)
{
    const std::string path = input("bad.obj");
    writeFile(path, std::string(kTriangleObj) + "f 1 2 9\n");
    expectMeshRejected(path, {path + ": face 2 references vertex 9 but the mesh has 3 vertices"});
}

TEST_F(Cli, OutOfRangeIndexInPly)
{
    const std::string path = input("bad.ply");
    writeFile(path, "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                    "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
    expectMeshRejected(path, {path + ": face 0 references vertex 7 but the mesh has 3 vertices"});
}

// ----------------------------------------------------------------------------------------------
// Bad scalars
// ----------------------------------------------------------------------------------------------

TEST_F(Cli, ScalarFileWithTheWrongCount)
{
    const std::string values = input("w.txt");
    writeFile(values, "1 2 3\n");
    const std::string mesh = sharedMesh("vampy_artery_cfd_pressure.ply");
    const std::string problem = values + ": expected 1104 scalar values (one per vertex), found 3";
    expectRejected(sdf(mesh, "--scalar-file " + quoted(values)), {problem});
    expectRejected(render(mesh, "--scalar-file " + quoted(values)), {problem});
}

TEST_F(Cli, ScalarFileWithANonNumber)
{
    const std::string mesh = input("t.obj");
    const std::string values = input("w.txt");
    writeFile(mesh, kTriangleObj);
    writeFile(values, "1 2 x\n");
    expectRejected(sdf(mesh, "--scalar-file " + quoted(values)), {values + ": value 2 'x' is not a number"});
}

TEST_F(Cli, UnknownScalarNameListsTheNamesThatExist)
{
    const std::string mesh = sharedMesh("vampy_artery_cfd_pressure.ply");
    const std::vector<std::string> parts = {
        mesh + ": no array 'wss'",
        "available: pressure_t200 (point), pressure_t400 (point), pressure_t600 (point), pressure_t800 (point), "
        "pressure_t1000 (point)"};
    expectRejected(sdf(mesh, "--scalar wss"), parts);
    expectRejected(render(mesh, "--scalar wss"), parts);
}

// ----------------------------------------------------------------------------------------------
// Bad option values
// ----------------------------------------------------------------------------------------------

TEST_F(Cli, UnknownRenderMethod)
{
    expectRejected(render(sharedMesh("vampy_artery_cfd_pressure.ply"), "--method ring"),
                   {"unknown method 'ring' (known: front, backfaces, neugebauer, mirror, inversevis, inversevis-adaptive, inversevis-wrap)"});
}

TEST_F(Cli, VersionNamesTheLibraries)
{
    const CliResult result = runCli("--version");
    EXPECT_EQ(result.status, 0) << result.err;
    for (const char* part : {"inversevis 0.", "OpenVDB 10.", "Embree 3.", "OpenEXR 3."})
        EXPECT_NE(result.out.find(part), std::string::npos) << part << " not in: " << result.out;
}

TEST_F(Cli, MethodParameterOutOfItsBounds)
{
    const std::string mesh = sharedMesh("vampy_artery_cfd_pressure.ply");
    expectRejected(render(mesh, "--method inversevis --alpha 7"), {"inversevis --alpha 7 is out of range (0 to 4)"});
    expectRejected(render(mesh, "--method mirror --mirror-w 0.3 0.3 0 0 30"), {"mirror --mirror-w 30 is out of range"});
    expectRejected(render(mesh, "--max-steps 2.5"), {"--max-steps 2.5 is not a whole number"});
}

TEST_F(Cli, ParameterOfAnotherMethodIsRejected)
{
    const std::string mesh = sharedMesh("vampy_artery_cfd_pressure.ply");
    expectRejected(render(mesh, "--method mirror --alpha 0.7"), {"--alpha does not apply to the method mirror"});
    expectRejected(render(mesh, "--ring-width 0.2"), {"--ring-width does not apply to the method inversevis-wrap"});
}

TEST_F(Cli, HullOffsetBeyondAGivenReachNamesBothAndTheDefaultReachFollowsTheHull)
{
    const std::string mesh = sharedMesh("vampy_artery_cfd_pressure.ply");
    expectRejected(render(mesh, "--hull-offset 0.7 --reach 0.7"), {"--hull-offset 0.7", "--reach 0.7"});
    expectRejected(render(mesh, "--method inversevis --hull-offset 0.7 --reach 0.6"), {"--hull-offset 0.7", "--reach 0.6"});
    EXPECT_EQ(runCli(render(mesh, "--hull-offset 0.7 --reach 0.8")).status, 0);
    // Without --reach the far field reaches as far as the method's rays need.
    EXPECT_EQ(runCli(render(mesh, "--hull-offset 1.5")).status, 0);
    EXPECT_EQ(runCli(render(mesh, "--method inversevis --hull-offset 1.3")).status, 0);
    // Beyond the volume's largest reach, the message names the hull offset, not a reach never given.
    expectBadInput(runCli(render(mesh, "--method inversevis --hull-offset 1.9")),
                   {"inversevis --hull-offset 1.9 needs a volume reaching 2.5, beyond the largest (2): at most 1.4"});
}

TEST_F(Cli, OptimizeStartsFromTheGivenCameraAndRejectsOrthographic)
{
    const std::string camera = input("camera.json");
    writeFile(camera, R"({"eye": [0, 1.25, 2.1650635], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y_deg": 60})");
    const std::string common = "optimize scene:sphere --volume-res 48 --opt-res 16 --res 32x32 --steps 0 --cache-dir " +
                               quoted(output("")) + " -o " + quoted(output("best.png"));
    const CliResult result = runCli(common + " --camera " + quoted(camera) + " --json " + quoted(output("b.json")));
    ASSERT_EQ(result.status, 0) << result.err;
    const nlohmann::json report = nlohmann::json::parse(std::ifstream(output("b.json")));
    const nlohmann::json& first = report.at("visited").at(0);
    EXPECT_NEAR(first.at("theta").get<double>(), 60.0, 1e-6);
    EXPECT_NEAR(first.at("phi").get<double>(), 0.0, 1e-6);
    EXPECT_EQ(report.at("visited").size(), 13u) << "the given view, no proposal, the compass search's 12 round it";
    EXPECT_FALSE(report.at("framed").get<bool>()) << "a camera file's field of view is kept";
    // A view file gives the start, and each view is framed (its fixed field of view, centred,
    // cut the best picture off at the frame).
    const CliResult viewed = runCli(render("scene:sphere", "--theta 60 --view-out " + quoted(output("v.json"))));
    ASSERT_EQ(viewed.status, 0) << viewed.err;
    ASSERT_EQ(runCli(common + " --view " + quoted(output("v.json")) + " --json " + quoted(output("b.json"))).status, 0);
    const nlohmann::json started = nlohmann::json::parse(std::ifstream(output("b.json")));
    EXPECT_NEAR(started.at("visited").at(0).at("theta").get<double>(), 60.0, 1e-6);
    EXPECT_TRUE(started.at("framed").get<bool>());
    fs::remove_all(output(""));
    fs::create_directories(output(""));
    expectRejected(common + " --ortho", {"--ortho"});
    // Ignored beside a camera file, or beside --ortho (whose framing is its half height).
    for (const char* beside : {" --theta 10", " --phi 10", " --fov 40", " --ortho"})
        expectRejected(render("scene:sphere", "--camera " + quoted(camera) + beside), {"--camera", "excludes"});
    expectRejected(render("scene:sphere", "--ortho --fov 40"), {"--ortho", "excludes"});
}

TEST_F(Cli, EvaluateTakesTheMeshAndVolumeOptions)
{
    const CliResult result =
        runCli("evaluate " + quoted(sharedMesh("vampy_artery_cfd_pressure.ply")) +
               " --scalar pressure_t200 --energy scalar --cap-holes --band 4 --reach 0.7 --distance unsigned "
               "--volume-res 48 --methods inversevis --opt-res 16 --steps 0 --display-res 32 --cache-dir " +
               quoted(output("")) + " --json " + quoted(output("e.json")));
    ASSERT_EQ(result.status, 0) << result.err;
    EXPECT_TRUE(nlohmann::json::parse(std::ifstream(output("e.json"))).contains("vampy_artery_cfd_pressure"));
}

TEST_F(Cli, BadImageResolution)
{
    const std::string mesh = sharedMesh("vampy_artery_cfd_pressure.ply");
    expectRejected("render " + quoted(mesh) + " --volume-res 48 --res 10y10 -o " + quoted(output("x.png")),
                   {"--res '10y10': expected WIDTHxHEIGHT"});
    // Sizes that wrapped round an int (4294967297 read as 1), signs, blanks and trailing text.
    for (const char* size : {"4294967297x10", "4294967396x100", "-5x10", "+5x10", "10x10x", "0x10", "32769x10"})
        expectRejected("render " + quoted(mesh) + " --volume-res 48 --res " + size + " -o " + quoted(output("x.png")),
                       {std::string("--res '") + size + "': expected WIDTHxHEIGHT"});
    expectRejected("sdf " + quoted(mesh) + " --volume-res 10y10 -o " + quoted(output("s.vdb")), {"--volume-res", "10y10"});
}

TEST_F(Cli, OutOfRangeVolumeResolution)
{
    expectRejected("sdf " + quoted(sharedMesh("vampy_artery_cfd_pressure.ply")) + " --volume-res 8 -o " +
                       quoted(output("s.vdb")),
                   {"--volume-res: Value 8 not in range 16 to 4096"});  // the option named (it was not)
}

TEST_F(Cli, UnknownColourMap)
{
    expectRejected(render(sharedMesh("vampy_artery_cfd_pressure.ply"), "--colormap jet"),
                   {"unknown colour map 'jet' (known: viridis, coolwarm, grey, blue-white-red, inferno, magma, plasma, turbo)"});
}

TEST_F(Cli, RangeLoMustBeBelowHi)
{
    const std::string mesh = sharedMesh("vampy_artery_cfd_pressure.ply");
    expectRejected(render(mesh, "--range 2 1"), {"invalid range [2, 1]: lo must be less than hi"});
    expectRejected(render(mesh, "--range 1 1"), {"invalid range [1, 1]: lo must be less than hi"});
    expectRejected(render(mesh, "--range 1e-300 1e300 --log"), {"magnitude at most 3.4e38 (single precision)"});
    // A picture too narrow for the object named as such (it spoke of rings the method does not have).
    expectRejected("render " + quoted(mesh) + " --volume-res 48 --method front --res 3x2000 --cache-dir " +
                       quoted(output("")) + " -o " + quoted(output("x.png")),
                   {"a framed picture of 3x2000 needs a width above 5% of its height"});
}

TEST_F(Cli, BadCameraFile)
{
    const std::string mesh = sharedMesh("vampy_artery_cfd_pressure.ply");
    const std::string text = input("text.json");
    writeFile(text, "not json\n");
    expectRejected(render(mesh, "--camera " + quoted(text)), {text + ": bad camera file"});
    const std::string shape = input("shape.json");
    writeFile(shape, R"({"eye": [1, 2], "target": [0, 0, 0]})");
    expectRejected(render(mesh, "--camera " + quoted(shape)), {shape + ": bad camera file ('eye' must be [x, y, z])"});
}

TEST_F(Cli, BadFlagFailsBeforeTheMeshIsReadAndLogged)
{
    // Reading this mesh logs a line (dropped triangle), capping another; neither may precede the error.
    const std::string path = input("tetra.obj");
    writeFile(path, kTetraWithDegenerateObj);
    expectRejected(render(path, "--colormap jet"), {"unknown colour map 'jet'"});
    expectRejected(render("scene:vessel-tree", "--cap-holes --range 2 1"), {"invalid range [2, 1]"});
}

// Each output is named for the format written into it (a PNG was written into x.exr, x.jpg or x,
// an EXR into a .png), and no two outputs name the same file (the later overwrote the earlier).
TEST_F(Cli, OutputsAreNamedForTheirFormatAndApart)
{
    for (const char* name : {"x.exr", "x.jpg", "x"})
        expectRejected("render scene:sphere --volume-res 48 --res 32x32 -o " + quoted(output(name)),
                       {output(name) + ": -o writes .png files"});
    expectRejected(render("scene:sphere", "--exr " + quoted(output("e.png"))), {"e.png: --exr writes .exr files"});
    expectRejected(render("scene:sphere", "--tear-map " + quoted(output("t.exr"))), {"t.exr: --tear-map writes .png"});
    expectRejected("sdf scene:sphere --volume-res 48 -o " + quoted(output("s.png")), {"s.png: -o writes .vdb files"});
    expectRejected("optimize scene:sphere --volume-res 48 -o " + quoted(output("b.exr")), {"b.exr: -o writes .png"});
    expectRejected(render("scene:sphere", "--stats-json " + quoted(output("x.png"))),
                   {output("x.png") + ": named by both -o and --stats-json"});
    expectRejected(render("scene:sphere", "--camera-out " + quoted(output("c.json")) + " --view-out " +
                                              quoted(output(".") + "/c.json")),
                   {"named by both --camera-out and --view-out"});
    // The files a command writes by itself, and the files it reads, are never overwritten.
    expectRejected(render("scene:sphere", "--stats-json " + quoted(output("x.png.camera.json"))),
                   {"x.png.camera.json: named by both --stats-json and the camera file (-o's name + .camera.json)"});
    expectRejected("optimize scene:sphere --volume-res 48 -o " + quoted(output("b.png")) + " --json " +
                       quoted(output("b.png.view.json")),
                   {"b.png.view.json: named by both --json and the view file (-o's name + .view.json)"});
    const std::string mesh = input("m.obj");
    test::writeFile(mesh, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const std::string values = input("v.txt");
    test::writeFile(values, "1\n2\n3\n");
    expectRejected(render(mesh, "--scalar-file " + quoted(values) + " --stats-json " + quoted(values)),
                   {values + ": --stats-json would overwrite --scalar-file, which this command reads"});
    expectRejected(render(mesh, "--stats-json " + quoted(mesh)),
                   {mesh + ": --stats-json would overwrite the mesh, which this command reads"});
    // A series: its steps' files are read, and its frames and video are written (they were
    // overwritten by --stats-json, --json, --camera-out and --view-out).
    const std::string step = input("m2.obj"), pvd = input("s.pvd");
    test::writeFile(step, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\n");
    test::writeFile(pvd, "<VTKFile type=\"Collection\"><Collection><DataSet timestep=\"0\" file=\"m.obj\"/>"
                         "<DataSet timestep=\"1\" file=\"m2.obj\"/></Collection></VTKFile>");
    expectRejected(render(pvd, "--stats-json " + quoted(step)),
                   {step + ": --stats-json would overwrite a step of " + pvd + ", which this command reads"});
    expectRejected(render(pvd, "--no-video --stats-json " + quoted(output("x_0001.png"))),
                   {"x_0001.png: named by both --stats-json and -o (frame 1)"});
    expectRejected(render(pvd, "--exr " + quoted(output("x.exr")) + " --view-out " + quoted(output("x_0000.exr"))),
                   {"x_0000.exr: named by both --view-out and --exr (frame 0)"});
    expectRejected(render(pvd, "--camera-out " + quoted(output("x.mp4"))),
                   {"x.mp4: named by both --camera-out and the video (-o's name as .mp4)"});
    expectRejected("optimize " + quoted(pvd) + " --volume-res 48 -o " + quoted(output("b.png")) + " --json " +
                       quoted(output("b_0000.png")),
                   {"b_0000.png: named by both --json and -o (frame 0)"});
    test::writeFile(input("v.json"), "{}");
    expectRejected(render("scene:sphere", "--view-out " + quoted(input("v.json")) + " --view " +
                                              quoted(input("v.json"))),
                   {"--view-out would overwrite --view"});
    fs::create_directory(input("folder.png"));
    expectRejected(render("scene:sphere", "--tear-map " + quoted(input("folder.png"))),
                   {input("folder.png") + ": --tear-map names a folder, not a file"});
    // Any case of the extension, and any name for JSON.
    const CliResult upper = runCli("render scene:sphere --volume-res 48 --res 32x32 --cache-dir " + quoted(output("")) +
                                   " -o " + quoted(output("X.PNG")) + " --stats-json " + quoted(output("stats.txt")));
    EXPECT_EQ(upper.status, 0) << upper.err;
    EXPECT_TRUE(fs::exists(output("X.PNG")));
    EXPECT_TRUE(fs::exists(output("stats.txt")));
}

// A picture larger than the memory is one line and status 2 (it was "internal error: std::bad_alloc",
// status 1), and leaves nothing.
TEST_F(Cli, APictureLargerThanTheMemoryIsOneLine)
{
    const std::string command = "ulimit -v 2000000; exec '" + std::string(IVIS_CLI_PATH) +
                                "' render scene:sphere --method front --volume-res 32 --res 32768x32768 --cache-dir '" +
                                input("") + "' -o '" + output("x.png") + "' 2>'" + input("err") + "'";
    const int status = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(status)) << "killed by a signal";
    EXPECT_EQ(WEXITSTATUS(status), 2);
    EXPECT_EQ(test::readFile(input("err")), "inversevis: error: out of memory: a smaller --res, --spp or --volume-res needs less\n");
    EXPECT_EQ(contents(mOutputs.path()), std::vector<std::string>{});
}

TEST_F(Cli, WritingIntoAMissingFolderLeavesNothing)
{
    // The render's volume cache would go beside the picture; no folder may be created for it.
    const std::string mesh = sharedMesh("vampy_artery_cfd_pressure.ply");
    const std::string picture = output("no-such-folder") + "/x.png";
    expectRejected("render " + quoted(mesh) + " --volume-res 48 --res 32x32 -o " + quoted(picture),
                   {picture + ": cannot write (folder '" + output("no-such-folder") + "' does not exist)"});
    const std::string exr = output("no-such-folder") + "/x.exr";
    expectRejected(render(mesh, "--exr " + quoted(exr)), {exr + ": cannot write"});
    const std::string volume = output("no-such-folder") + "/s.vdb";
    expectRejected("sdf " + quoted(mesh) + " --volume-res 48 -o " + quoted(volume), {volume + ": cannot write"});

    ASSERT_FALSE(fs::exists("/nonexistent"));
    expectBadInput(runCli("render " + quoted(mesh) + " --volume-res 48 --res 32x32 -o /nonexistent/x.png"),
                   {"/nonexistent/x.png: cannot write"});
    EXPECT_FALSE(fs::exists("/nonexistent"));
}

// ----------------------------------------------------------------------------------------------
// Reports
// ----------------------------------------------------------------------------------------------

TEST_F(Cli, InfoJsonReportsCountsAndPressureScalars)
{
    const CliResult result = runCli("info " + quoted(sharedMesh("vampy_artery_cfd_pressure.ply")) + " --json");
    ASSERT_EQ(result.status, 0) << result.err;
    const nlohmann::json info = nlohmann::json::parse(result.out);
    EXPECT_EQ(info.at("vertices"), 1104);
    EXPECT_EQ(info.at("triangles"), 2204);
    EXPECT_EQ(info.at("boundary_edges"), 0);
    EXPECT_EQ(info.at("open_mesh"), false);
    // MANIFEST.md: name, min, max (4 significant digits).
    const struct {
        const char* name;
        double min, max;
    } expected[] = {{"pressure_t200", 0.2294, 0.7932},
                    {"pressure_t400", 0.09313, 0.2698},
                    {"pressure_t600", -0.009525, 0.1407},
                    {"pressure_t800", -0.0451, 0.08232},
                    {"pressure_t1000", -0.05931, 0.04502}};
    const nlohmann::json& scalars = info.at("arrays");
    ASSERT_EQ(scalars.size(), 5u);
    for (std::size_t i = 0; i < 5; ++i) {
        EXPECT_EQ(scalars[i].at("name"), expected[i].name);
        EXPECT_NEAR(scalars[i].at("min").get<double>(), expected[i].min, 1e-4) << expected[i].name;
        EXPECT_NEAR(scalars[i].at("max").get<double>(), expected[i].max, 1e-4) << expected[i].name;
        EXPECT_EQ(scalars[i].at("nan_count"), 0) << expected[i].name;
        EXPECT_EQ(scalars[i].at("association"), "point") << expected[i].name;
        EXPECT_EQ(scalars[i].at("type"), "Float32") << expected[i].name;
        EXPECT_EQ(scalars[i].at("components"), 1) << expected[i].name;
        EXPECT_EQ(scalars[i].at("shown_by_default"), i == 0) << expected[i].name;  // a PLY: the first
    }
    // A VMTK file's active scalars (<PointData Scalars="ClippingArray">), the third point array.
    const CliResult vmtk = runCli("info " + quoted(sharedMesh("vtk/vmtk_aorta_branch_split.vtp")));
    ASSERT_EQ(vmtk.status, 0) << vmtk.err;
    const std::size_t marked = vmtk.out.find("  (shown by default)");
    ASSERT_NE(marked, std::string::npos) << vmtk.out;
    EXPECT_EQ(vmtk.out.rfind("ClippingArray", marked), vmtk.out.rfind("\n", marked) + 5) << vmtk.out;
    EXPECT_EQ(vmtk.out.find("(shown by default)", marked + 3), std::string::npos) << vmtk.out;
    // A generated scene is no file (info said "file not found").
    expectBadInput(runCli("info scene:vessel-tree"), {"scene:vessel-tree: a generated scene, not a file"});
}

TEST_F(Cli, InfoReportsTheOpenLeftAtrium)
{
    const CliResult result = runCli("info " + quoted(sharedMesh("lasc2013_b003_left_atrium.ply")));
    ASSERT_EQ(result.status, 0) << result.err;
    EXPECT_NE(result.out.find("boundary edges  462 (open)"), std::string::npos) << result.out;
    EXPECT_NE(result.out.find("triangles       20576"), std::string::npos) << result.out;
}

TEST_F(Cli, SdfJsonReportsTheVolumeAndReusesItsCache)
{
    const std::string arguments = "sdf scene:sphere --volume-res 64 --json -o " + quoted(output("s.vdb"));
    const CliResult first = runCli(arguments);
    ASSERT_EQ(first.status, 0) << first.err;
    const nlohmann::json report = nlohmann::json::parse(first.out);  // exactly one JSON value
    ASSERT_TRUE(report.is_object());
    EXPECT_EQ(report.at("cache"), "built");
    EXPECT_EQ(report.at("resolution"), 64);
    EXPECT_DOUBLE_EQ(report.at("voxel_size").get<double>(), 5.0 / 64.0);  // box [-2.5,2.5]^3
    EXPECT_GT(report.at("active_voxels").get<std::int64_t>(), 0);
    EXPECT_GT(report.at("memory_bytes").get<std::int64_t>(), 0);
    EXPECT_GE(report.at("seconds").get<double>(), 0.0);
    EXPECT_EQ(report.at("open_mesh"), false);
    EXPECT_EQ(report.at("triangles"), 5120);  // icosphere, 4 subdivisions
    EXPECT_EQ(contents(mOutputs.path()), std::vector<std::string>{"s.vdb"});

    const CliResult second = runCli(arguments);
    ASSERT_EQ(second.status, 0) << second.err;
    EXPECT_EQ(nlohmann::json::parse(second.out).at("cache"), "reused");
    EXPECT_EQ(contents(mOutputs.path()), std::vector<std::string>{"s.vdb"});
}

TEST_F(Cli, SdfOfTheOpenVesselTreeIsUnsignedUnlessCapped)
{
    const CliResult open = runCli("sdf scene:vessel-tree --volume-res 64 --json -o " + quoted(output("open.vdb")));
    ASSERT_EQ(open.status, 0) << open.err;
    const nlohmann::json openReport = nlohmann::json::parse(open.out);
    EXPECT_EQ(openReport.at("open_mesh"), true);
    EXPECT_EQ(openReport.at("unsigned_distance"), true);

    const CliResult capped =
        runCli("sdf scene:vessel-tree --volume-res 64 --json --cap-holes -o " + quoted(output("capped.vdb")));
    ASSERT_EQ(capped.status, 0) << capped.err;
    const nlohmann::json cappedReport = nlohmann::json::parse(capped.out);
    EXPECT_EQ(cappedReport.at("open_mesh"), false);
    EXPECT_EQ(cappedReport.at("unsigned_distance"), false);
}

TEST_F(Cli, DegenerateTrianglesAreDroppedWithACount)
{
    const std::string path = input("tetra.obj");
    writeFile(path, kTetraWithDegenerateObj);
    const CliResult result = runCli(sdf(path));
    ASSERT_EQ(result.status, 0) << result.err;
    EXPECT_NE(result.err.find(path + ": dropped 1 degenerate"), std::string::npos) << result.err;
}

TEST_F(Cli, OptimizeWritesTheBestViewItsPictureAndTheVisitedViews)
{
    const CliResult result = runCli("optimize scene:sphere --volume-res 64 --method inversevis-adaptive --opt-res 24 "
                                    "--steps 3 --finalists 3 --finalist-res 48 --res 48x48 --cache-dir " + quoted(output("")) + " -o " +
                                    quoted(output("best.png")) + " --json " + quoted(output("best.json")) +
                                    " --plot " + quoted(output("views.png")) + " --exr " + quoted(output("best.exr")));
    ASSERT_EQ(result.status, 0) << result.err;
    const nlohmann::json report = nlohmann::json::parse(std::ifstream(output("best.json")));
    ASSERT_EQ(report.at("visited").size(), 41u);  // the 26 cube views, 3 proposals, the compass search's 12
    int polish = 0;
    for (const auto& view : report.at("visited")) polish += view.at("polish").get<bool>() ? 1 : 0;
    EXPECT_EQ(polish, 12);
    // The best view is the finalist (one of the 3 of highest energy) of highest finalist energy.
    const nlohmann::json* best = nullptr;
    int finalists = 0;
    for (const auto& view : report.at("visited")) {
        if (!view.contains("finalist_energy")) continue;
        ++finalists;
        if (!best || view.at("finalist_energy").get<double>() > best->at("finalist_energy").get<double>()) best = &view;
    }
    EXPECT_EQ(finalists, 3);
    ASSERT_NE(best, nullptr);
    EXPECT_EQ(report.at("energy_value").get<double>(), best->at("energy").get<double>());
    EXPECT_EQ(report.at("theta"), best->at("theta"));
    EXPECT_EQ(report.at("params").at("method"), "inversevis-adaptive");
    EXPECT_EQ(report.at("params").at("alpha_profile").size(), 3u);
    EXPECT_GT(report.at("display_energy_value").get<double>(), report.at("display_front_energy_value").get<double>());
    const nlohmann::json& measures = report.at("measures");
    EXPECT_EQ(measures.at("visibility"), report.at("display_energy_value")) << "the energy is the surface visibility";
    for (const char* key : {"paper_literal", "front_visibility", "coherence"}) EXPECT_TRUE(measures.contains(key)) << key;
    for (const char* file : {"best.png", "views.png"}) EXPECT_TRUE(fs::exists(output(file))) << file;
    // The best view is framed, and its camera file says so.
    EXPECT_TRUE(report.at("framed").get<bool>());
    const nlohmann::json camera = nlohmann::json::parse(std::ifstream(output("best.png.camera.json")));
    EXPECT_EQ(camera.at("fov_y_deg"), report.at("fov_y_deg"));
    EXPECT_NE(report.at("fov_y_deg").get<double>(), 75.0);
    // The EXR holds the best view's layers, as render --exr would write them from its camera file.
    const CliResult again = runCli("render scene:sphere --volume-res 64 --method inversevis-adaptive --alpha-profile " +
                                   [&] {
                                       std::string p;
                                       for (const auto& a : report.at("params").at("alpha_profile")) p += a.dump() + " ";
                                       return p;
                                   }() + "--res 48x48 --camera " + quoted(output("best.png.camera.json")) + " --cache-dir " +
                                   quoted(output("")) + " -o " + quoted(output("again.png")) + " --exr " + quoted(output("again.exr")));
    ASSERT_EQ(again.status, 0) << again.err;
    EXPECT_EQ(core::readExrChannel(output("best.exr"), "R"), core::readExrChannel(output("again.exr"), "R"));
}

TEST_F(Cli, OptimizeViewsShowsSeveralPicturesSideBySideAndTheirUnion)
{
    const std::string common = "optimize scene:sphere --volume-res 64 --opt-res 24 --steps 3 --finalists 0 "
                               "--min-coherence 0 --res 64x64 --no-legend --cache-dir " + quoted(output("")) + " -o " +
                               quoted(output("best.png")) + " --json " + quoted(output("best.json"));
    const CliResult result = runCli(common + " --views 3");
    ASSERT_EQ(result.status, 0) << result.err;
    const nlohmann::json report = nlohmann::json::parse(std::ifstream(output("best.json")));
    const nlohmann::json& views = report.at("several_views").at("views");
    ASSERT_GE(views.size(), 2u);
    ASSERT_LE(views.size(), 3u);
    EXPECT_EQ(views.at(0).at("theta"), report.at("theta")) << "the best view first";
    EXPECT_EQ(views.at(0).at("visibility"), report.at("measures").at("visibility"));
    double largest = 0.0;
    for (const nlohmann::json& view : views) largest = std::max(largest, view.at("visibility").get<double>());
    const double together = report.at("several_views").at("union").at("visibility").get<double>();
    EXPECT_GT(together, largest) << "each further view adds surface";
    EXPECT_LE(together, 1.0);
    // The pictures side by side (a gap of 4 pixels between them), and a view file for each further view.
    const core::Image figure = core::readPng(output("best.png"));
    EXPECT_EQ(figure.width(), int(views.size()) * 64 + 4 * int(views.size() - 1));
    EXPECT_EQ(figure.height(), 64);
    for (std::size_t k = 2; k <= views.size(); ++k) {
        const std::string file = output("best.png.view" + std::to_string(k) + ".json");
        ASSERT_TRUE(fs::exists(file)) << file;
        const CliResult again = runCli("render scene:sphere --volume-res 64 --res 64x64 --no-legend --cache-dir " +
                                       quoted(output("")) + " --view " + quoted(file) + " -o " + quoted(output("again.png")));
        ASSERT_EQ(again.status, 0) << again.err;
        // render draws the view as the figure's panel shows it.
        const core::Image panel = core::readPng(output("again.png"));
        int differing = 0;
        for (int y = 0; y < 64; ++y)
            for (int x = 0; x < 64; ++x)
                differing += glm::length(panel.at(x, y) - figure.at(int(k - 1) * 68 + x, y)) > 1e-3f ? 1 : 0;
        EXPECT_EQ(differing, 0) << file;
    }
    fs::remove_all(output(""));
    fs::create_directories(output(""));
    expectRejected(common + " --views 2 --energy scalar", {"--views", "--energy visibility"});
}

TEST_F(Cli, OptimizeLoosensTheWrapsRuleAsFarAsThePictureStaysReadable)
{
    // Asking for 0.55 lets the rule loosen beyond the default (0.1), 0 leaves it as given. The rule
    // is judged on the measure's 1000 x 1000 picture of the best view, whatever the picture's size
    // (it was judged on the 64 x 64 picture, which tears far more), as render judges it. The search
    // starts at a given view, whose neighbourhood needs a looser rule than the default.
    auto optimizeTree = [&](const std::string& minCoherence, const std::string& json) {
        return runCli("optimize scene:vessel-tree --volume-res 64 --method inversevis-wrap --opt-res 24 --steps 1 "
                      "--theta 90 --phi 90 --finalists 0 --res 64x64 --fov 63 --min-coherence " + minCoherence +
                      " --cache-dir " + quoted(output("")) +
                      " -o " + quoted(output("best.png")) + " --json " + quoted(output(json)));
    };
    ASSERT_EQ(optimizeTree("0.55", "readable.json").status, 0);
    const nlohmann::json readable = nlohmann::json::parse(std::ifstream(output("readable.json")));
    const nlohmann::json& choice = readable.at("readability");
    EXPECT_EQ(choice.at("parameter"), "stable_shift");
    EXPECT_EQ(choice.at("value"), readable.at("params").at("stable_shift")) << "the best view's rule is the chosen one";
    EXPECT_GT(choice.at("value").get<double>(), 0.1001) << "loosened";
    EXPECT_GE(choice.at("estimated_coherence").get<double>(), 0.55);
    EXPECT_EQ(choice.at("picture_size"), nlohmann::json::array({1000, 1000}));
    // render, given the best view, chooses the same rule from the same estimate.
    const CliResult rendered =
        runCli("render scene:vessel-tree --volume-res 64 --res 64x64 --fov 63 --min-coherence 0.55 --theta " +
               readable.at("theta").dump() + " --phi " + readable.at("phi").dump() + " --cache-dir " +
               quoted(output("")) + " -o " + quoted(output("r.png")) + " --stats-json " + quoted(output("r.json")));
    ASSERT_EQ(rendered.status, 0) << rendered.err;
    const nlohmann::json renderedChoice = nlohmann::json::parse(std::ifstream(output("r.json"))).at("readability");
    EXPECT_EQ(renderedChoice.at("value"), choice.at("value"));
    EXPECT_NEAR(renderedChoice.at("estimated_coherence").get<double>(), choice.at("estimated_coherence").get<double>(), 1e-9);

    ASSERT_EQ(optimizeTree("0", "given.json").status, 0);
    const nlohmann::json given = nlohmann::json::parse(std::ifstream(output("given.json")));
    EXPECT_FALSE(given.contains("readability")) << "0: no readability step";
    EXPECT_FLOAT_EQ(given.at("params").at("stable_shift").get<float>(), 0.1f);
    EXPECT_LT(given.at("measures").at("visibility").get<double>(), readable.at("measures").at("visibility").get<double>())
        << "the looser rule shows more";
}

TEST_F(Cli, RenderDrawsTheWrapWithItsReadableRuleUnlessTheRuleIsGiven)
{
    // The rule is chosen on the 1000 x 1000 picture of the same view, whatever the picture's size:
    // asking for 0.5 lets it loosen beyond the default (0.1), asking for all but perfect coherence
    // tightens it.
    auto renderTree = [&](const std::string& name, const std::string& extra, const std::string& size = "64x64") {
        const CliResult result = runCli("render scene:vessel-tree --volume-res 64 --res " + size + " --cache-dir " +
                                        quoted(output("")) + " -o " + quoted(output(name + ".png")) + " --stats-json " +
                                        quoted(output(name + ".json")) + " " + extra);
        EXPECT_EQ(result.status, 0) << result.err;
        return nlohmann::json::parse(std::ifstream(output(name + ".json")));
    };
    const nlohmann::json readable = renderTree("readable", "--fov 63 --min-coherence 0.5 --view-out " + quoted(output("v.json")));
    const nlohmann::json& choice = readable.at("readability");
    EXPECT_EQ(choice.at("parameter"), "stable_shift");
    EXPECT_GT(choice.at("value").get<double>(), 0.1001) << "loosened";
    EXPECT_EQ(choice.at("value"), readable.at("stable_shift")) << "the picture is drawn with the chosen rule";
    EXPECT_GE(choice.at("estimated_coherence").get<double>(), 0.5);
    EXPECT_EQ(choice.at("picture_size"), nlohmann::json::array({1000, 1000}));
    // The 1000 x 1000 picture of the same view gets the same rule, from the same estimate; a wide
    // picture is judged in its own aspect.
    const nlohmann::json large = renderTree("large", "--fov 63 --min-coherence 0.5", "1000x1000");
    EXPECT_EQ(large.at("readability"), choice);
    const nlohmann::json wide = renderTree("wide", "--fov 63 --min-coherence 0.5", "96x64");
    EXPECT_EQ(wide.at("readability").at("picture_size"), nlohmann::json::array({1500, 1000}));

    const nlohmann::json given = renderTree("given", "--fov 63 --min-coherence 0.5 --stable-shift 0.005");
    EXPECT_FALSE(given.contains("readability")) << "a rule given is drawn as given";
    EXPECT_FLOAT_EQ(given.at("stable_shift").get<float>(), 0.005f);
    EXPECT_LT(given.at("pixels_indirect").get<int>(), readable.at("pixels_indirect").get<int>()) << "the looser rule draws more";
    const nlohmann::json off = renderTree("off", "--fov 63 --min-coherence 0");
    EXPECT_FALSE(off.contains("readability"));
    EXPECT_FLOAT_EQ(off.at("stable_shift").get<float>(), 0.1f) << "the default rule";
    const nlohmann::json tight = renderTree("tight", "--fov 63 --min-coherence 0.9999");
    EXPECT_FLOAT_EQ(tight.at("readability").at("value").get<float>(), 0.0125f) << "tightened to the ladder's foot";
    EXPECT_FALSE(tight.at("readability").at("keeps_min_coherence").get<bool>()) << "and still short of 0.9999";
    EXPECT_TRUE(choice.at("keeps_min_coherence").get<bool>());
    EXPECT_LT(tight.at("pixels_indirect").get<int>(), off.at("pixels_indirect").get<int>()) << "the tighter rule draws less";
    expectBadInput(runCli("render scene:vessel-tree --volume-res 64 --min-coherence 0.5 --method inversevis -o " +
                          quoted(output("faithful.png"))),
                   {"--min-coherence: inversevis has no rule"});  // a method without such a rule: it did nothing

    const nlohmann::json again = renderTree("again", "--min-coherence 0.5 --view " + quoted(output("v.json")));
    EXPECT_FALSE(again.contains("readability")) << "the view file gives the rule";
    EXPECT_EQ(again.at("stable_shift"), readable.at("stable_shift"));
    EXPECT_EQ(core::readPng(output("again.png")).pixels(), core::readPng(output("readable.png")).pixels());
}

TEST_F(Cli, RenderStatsCarryTheMethodsOwnParametersAndTheCoherence)
{
    const CliResult result = runCli(render("scene:vessel-tree", "--method inversevis-adaptive --stats-json " +
                                                                 quoted(output("s.json"))));
    ASSERT_EQ(result.status, 0) << result.err;
    const nlohmann::json stats = nlohmann::json::parse(std::ifstream(output("s.json")));
    EXPECT_EQ(stats.at("method"), "inversevis-adaptive");
    EXPECT_EQ(stats.at("alpha_profile").size(), 3u);
    EXPECT_FALSE(stats.contains("alpha")) << "only the method's own parameters";
    EXPECT_FALSE(stats.contains("mirror_w"));
    EXPECT_GT(stats.at("coherence").get<double>(), 0.0);
    EXPECT_LE(stats.at("coherence").get<double>(), 1.0);
}

TEST_F(Cli, RenderTakesItsMeshAfterOptionsWithValues)
{
    // An option takes exactly its own values (one, two, three or five), so the mesh may follow it;
    // each picture's stats show the values were read.
    const std::string tail = " scene:sphere --volume-res 48 --res 32x32 --cache-dir " + quoted(output("")) +
                             " -o " + quoted(output("x.png")) + " --stats-json " + quoted(output("s.json"));
    const std::vector<std::pair<std::string, std::pair<std::string, nlohmann::json>>> cases = {
        {"--method inversevis --alpha 0.75", {"alpha", 0.75}},
        {"--method inversevis-adaptive --alpha-profile 0 2 1", {"alpha_profile", {0.0, 2.0, 1.0}}},
        {"--method mirror --mirror-w 0.5 0.25 0 0 0", {"mirror_w", {0.5, 0.25, 0.0, 0.0, 0.0}}},
        {"--wrap-speed 2", {"wrap_speed", 2.0}}};
    for (const auto& [options, expected] : cases) {
        const CliResult result = runCli("render " + options + tail);
        ASSERT_EQ(result.status, 0) << options << ": " << result.err;
        const nlohmann::json stats = nlohmann::json::parse(std::ifstream(output("s.json")));
        EXPECT_EQ(stats.at(expected.first), expected.second) << options;
    }
    const CliResult ranged = runCli("render --range 0 1" + tail);
    EXPECT_EQ(ranged.status, 0) << ranged.err;
    const CliResult probed = runCli("render --probe 0,0 --probe 1,1" + tail);  // one X,Y per --probe
    EXPECT_EQ(probed.status, 0) << probed.err;
    EXPECT_EQ(probed.out, "pixel 0,0: background\npixel 1,1: background\n");
    expectBadInput(runCli("render --alpha-profile 0 3" + tail), {"--alpha-profile"});
}

TEST_F(Cli, RenderTearMapMarksTheTornPixelsInRed)
{
    const CliResult result = runCli(render("scene:vessel-tree", "--method inversevis-adaptive --stats-json " +
                                                                 quoted(output("s.json")) + " --tear-map " +
                                                                 quoted(output("tears.png"))));
    ASSERT_EQ(result.status, 0) << result.err;
    const double coherence = nlohmann::json::parse(std::ifstream(output("s.json"))).at("coherence").get<double>();
    ASSERT_LT(coherence, 1.0) << "the adaptive picture of the tree tears, or the test means nothing";
    const core::Image map = core::readPng(output("tears.png"));
    ASSERT_EQ(map.width(), 32) << "the picture's size, without the colour bar's margin";
    ASSERT_EQ(map.height(), 32);
    std::size_t red = 0;
    for (int y = 0; y < map.height(); ++y)
        for (int x = 0; x < map.width(); ++x) {
            const glm::vec4 c = map.at(x, y);
            if (c.r > 0.99f && c.g < 0.01f && c.b < 0.01f) ++red;
            else EXPECT_TRUE(c.r == c.g && c.g == c.b) << "grey elsewhere, at " << x << ", " << y;
        }
    EXPECT_GT(red, 0u);
}

// render --unseen-map draws what --measure counts: the surface from both sides, red where unseen;
// the front method leaves the sphere's back unseen and shows its front.
TEST_F(Cli, RenderUnseenMapShowsTheSurfaceThePictureMisses)
{
    const CliResult result = runCli(render("scene:sphere", "--method front --stats-json " +
                                                             quoted(output("s.json")) + " --unseen-map " +
                                                             quoted(output("unseen.png"))));
    ASSERT_EQ(result.status, 0) << result.err;
    EXPECT_TRUE(nlohmann::json::parse(std::ifstream(output("s.json"))).contains("measures")) << "it measures the picture";
    const core::Image map = core::readPng(output("unseen.png"));
    ASSERT_EQ(map.width(), 64) << "two panels as high as the picture";
    ASSERT_EQ(map.height(), 32);
    int red[2] = {0, 0}, surface[2] = {0, 0};
    for (int y = 0; y < map.height(); ++y)
        for (int x = 0; x < map.width(); ++x) {
            const glm::vec4 c = map.at(x, y);
            if (c == glm::vec4(1.0f)) continue;
            ++surface[x / 32];
            if (c.g < 0.1f && c.r > 0.3f) ++red[x / 32];
        }
    EXPECT_LT(red[0], surface[0] / 4) << "the front is seen";
    EXPECT_GT(red[1], surface[1] * 3 / 4) << "the back is not";
}

// render --probe tells what each probed pixel of the picture shows, as the EXR's layers record it,
// and names a view from which the point is seen directly: a far-side point of the rings lies in
// the direct part of that view's picture.
TEST_F(Cli, RenderProbeTellsWhatAPixelShowsAndAViewThatShowsItDirectly)
{
    const std::string common = " --volume-res 64 --hotspots 2 --res 64x64 --cache-dir " + quoted(output(""));
    std::string probes;
    for (int x = 0; x < 64; ++x) probes += " --probe " + std::to_string(x) + ",32";
    const CliResult result = runCli("render scene:sphere --method inversevis-wrap --theta 90 --phi 0" + common +
                                    probes + " -o " + quoted(output("p.png")) + " --exr " + quoted(output("p.exr")) +
                                    " --stats-json " + quoted(output("p.json")));
    ASSERT_EQ(result.status, 0) << result.err;
    const nlohmann::json reports = nlohmann::json::parse(std::ifstream(output("p.json"))).at("probes");
    ASSERT_EQ(reports.size(), 64u);
    EXPECT_EQ(std::count(result.out.begin(), result.out.end(), '\n'), 64) << result.out;
    EXPECT_EQ(result.out.rfind("pixel 0,32: background; its ray from ", 0), 0u) << "the margin's rays do not land\n"
                                                                             << result.out;

    const core::Similarity units = core::readExrMeshUnits(output("p.exr"));
    std::vector<std::vector<float>> layers;
    for (const char* name : {"region", "P.X", "P.Y", "P.Z", "scalar"}) layers.push_back(core::readExrChannel(output("p.exr"), name));
    std::optional<glm::dvec3> farSide;  // a point of the rings on the sphere's far half, in normalised units
    nlohmann::json farReport;
    int indirect = 0, refused = 0;
    for (int x = 0; x < 64; ++x) {
        const nlohmann::json& report = reports[std::size_t(x)];
        const std::size_t i = 32u * 64u + std::size_t(x);
        EXPECT_EQ(report.at("pixel"), nlohmann::json({x, 32}));
        const char* regions[] = {"background", "direct", "indirect"};
        ASSERT_EQ(report.at("region"), regions[int(layers[0][i])]) << x;
        // A ray drawn tells where it starts; a ray not drawn, why (the direct part has none).
        if (layers[0][i] == 2.0f) {
            EXPECT_EQ(report.at("launch").at("drawn"), true) << x;
            EXPECT_TRUE(report.at("launch").at("refusal").is_null()) << x;
            EXPECT_LT(report.at("launch").at("ring").get<double>(), 1.0) << x;
        } else if (report.contains("launch")) {
            EXPECT_EQ(layers[0][i], 0.0f) << x;
            EXPECT_EQ(report.at("launch").at("drawn"), false) << x;
            EXPECT_TRUE(report.at("launch").at("refusal").is_string()) << x;
            ++refused;
        }
        if (layers[0][i] == 0.0f) {
            EXPECT_FALSE(report.contains("position")) << x;
            continue;
        }
        const glm::dvec3 drawn(layers[1][i], layers[2][i], layers[3][i]);
        const std::vector<double> position = report.at("position").get<std::vector<double>>();
        const glm::dvec3 told = units.normalizedFromMesh({position[0], position[1], position[2]});
        EXPECT_LT(glm::length(told - drawn), 1e-5) << x;
        EXPECT_NEAR(report.at("scalar").get<double>(), layers[4][i], 1e-6) << x;
        ASSERT_TRUE(report.at("view").is_object()) << x << ": every point of a sphere is seen from outside";
        if (layers[0][i] == 2.0f) ++indirect;
        if (layers[0][i] == 2.0f && drawn.z < -0.3) farSide = drawn, farReport = report;
    }
    EXPECT_GT(indirect, 4);
    EXPECT_GT(refused, 0) << "the picture's margin: rays that do not land";
    ASSERT_TRUE(farSide.has_value()) << "the rings show the far half";

    // The view it names shows the point in its direct part.
    const std::string theta = std::to_string(farReport.at("view").at("theta").get<double>());
    const std::string phi = std::to_string(farReport.at("view").at("phi").get<double>());
    const CliResult turned = runCli("render scene:sphere --method front --theta " + theta + " --phi " + phi + common +
                                    " -o " + quoted(output("t.png")) + " --exr " + quoted(output("t.exr")));
    ASSERT_EQ(turned.status, 0) << turned.err;
    const core::CameraFrame frame(core::readCameraJson(output("t.png.camera.json")), 64, 64);
    const glm::dvec2 at = frame.project(*farSide);
    const std::size_t i = std::size_t(at.y) * 64u + std::size_t(at.x);
    ASSERT_TRUE(at.x >= 0.0 && at.y >= 0.0 && at.x < 64.0 && at.y < 64.0) << at.x << " " << at.y;
    EXPECT_EQ(core::readExrChannel(output("t.exr"), "region")[i], 1.0f);
    const glm::dvec3 shown(core::readExrChannel(output("t.exr"), "P.X")[i], core::readExrChannel(output("t.exr"), "P.Y")[i],
                           core::readExrChannel(output("t.exr"), "P.Z")[i]);
    EXPECT_LT(glm::length(shown - *farSide), 0.05) << "within two pixels (0.022 each) of the probed point";
    EXPECT_LT(std::abs(frame.camera().angles().x - farReport.at("view").at("theta").get<double>()), 1e-3);
}

// render --measure measures a picture as optimize measures its best view: rendering optimize's view
// file gives the very figures optimize reported, and the even-spread bound of as many points.
TEST_F(Cli, RenderMeasuresThePictureAsOptimizeMeasuresItsBestView)
{
    const std::string common = " --volume-res 64 --hotspots 2 --res 48x48 --cache-dir " + quoted(output(""));
    const CliResult best = runCli("optimize scene:sphere --method inversevis-wrap --opt-res 24 --steps 2" + common +
                                  " -o " + quoted(output("best.png")) + " --json " + quoted(output("best.json")));
    ASSERT_EQ(best.status, 0) << best.err;
    const CliResult again = runCli("render scene:sphere --measure --view " + quoted(output("best.png.view.json")) +
                                   common + " -o " + quoted(output("again.png")) + " --stats-json " +
                                   quoted(output("again.json")));
    ASSERT_EQ(again.status, 0) << again.err;
    EXPECT_NE(again.err.find("surface visibility"), std::string::npos) << again.err;
    const nlohmann::json reported = nlohmann::json::parse(std::ifstream(output("best.json"))).at("measures");
    const nlohmann::json stats = nlohmann::json::parse(std::ifstream(output("again.json")));
    const nlohmann::json& measured = stats.at("measures");
    for (const char* key : {"visibility", "paper_literal", "front_visibility", "coherence"})
        EXPECT_EQ(measured.at(key), reported.at(key)) << key;
    EXPECT_EQ(measured.at("reveal").at("total"), reported.at("reveal").at("total"));
    EXPECT_EQ(measured.at("surface_pixels").get<std::size_t>(),
              stats.at("pixels_direct").get<std::size_t>() + stats.at("pixels_indirect").get<std::size_t>());
    EXPECT_GT(measured.at("even_bound").get<double>(), 0.0);
    EXPECT_LE(measured.at("even_bound").get<double>(), 1.0);
}

// Each picture is framed for its method (the rings need a wider field of view than the object
// alone); the camera file it writes records that field of view and reproduces the very picture;
// --fov fixes the field of view.
TEST_F(Cli, RenderFramesEachPictureAndItsCameraFileReproducesIt)
{
    auto stats = [&](const std::string& extra, const std::string& name) {
        const CliResult result = runCli("render scene:vessel-tree --volume-res 48 --res 32x32 " +
                                        extra + " -o " + quoted(output(name + ".png")) + " --stats-json " +
                                        quoted(output(name + ".json")));
        EXPECT_EQ(result.status, 0) << result.err;
        return nlohmann::json::parse(std::ifstream(output(name + ".json")));
    };
    const std::string angles = " --theta 60 --phi 40";
    const nlohmann::json ring = stats("--method neugebauer" + angles, "ring"), front = stats("--method front" + angles, "front");
    EXPECT_TRUE(ring.at("framed").get<bool>());
    EXPECT_GT(ring.at("fov_y_deg").get<double>(), front.at("fov_y_deg").get<double>() + 10.0);
    const nlohmann::json camera = nlohmann::json::parse(std::ifstream(output("ring.png.camera.json")));
    EXPECT_EQ(camera.at("fov_y_deg"), ring.at("fov_y_deg"));

    const nlohmann::json again = stats("--method neugebauer --camera " + quoted(output("ring.png.camera.json")), "again");
    EXPECT_FALSE(again.at("framed").get<bool>());
    EXPECT_EQ(again.at("fov_y_deg"), ring.at("fov_y_deg"));
    EXPECT_EQ(test::readFile(output("again.png")), test::readFile(output("ring.png"))) << "the same picture";

    const nlohmann::json fixed = stats("--method neugebauer --fov 40" + angles, "fixed");
    EXPECT_FALSE(fixed.at("framed").get<bool>());
    EXPECT_EQ(fixed.at("fov_y_deg").get<double>(), 40.0);
    fs::remove_all(output(""));
    fs::create_directories(output(""));
    expectRejected(render("scene:vessel-tree", "--method neugebauer --ring-width 1.2"), {"--ring-width", "1.2"});
}

TEST_F(Cli, EvaluateReportsTheMeasuresOfEveryMethod)
{
    const CliResult result = runCli("evaluate scene:sphere --hotspots 2 --volume-res 64 --methods front,inversevis "
                                    "--opt-res 16,24 --ascent-res 16 --steps 2 --display-res 64 --cache-dir " +
                                    quoted(output("")) +
                                    " --json " + quoted(output("e.json")) + " --markdown " + quoted(output("e.md")));
    ASSERT_EQ(result.status, 0) << result.err;
    const nlohmann::json report = nlohmann::json::parse(std::ifstream(output("e.json"))).at("sphere");
    for (const char* method : {"front", "inversevis"}) {
        const nlohmann::json& entry = report.at(method);
        for (const char* key : {"visibility", "paper_literal", "front_visibility", "coherence"}) {
            EXPECT_GE(entry.at(key).get<double>(), 0.0) << method << " " << key;
            EXPECT_LE(entry.at(key).get<double>(), 1.0) << method << " " << key;
        }
        EXPECT_LE(entry.at("front_visibility").get<double>(), entry.at("visibility").get<double>()) << method;
        EXPECT_EQ(entry.at("reveal").at("per_region").size(), 2u) << "two hot spots";
        EXPECT_LE(entry.at("reveal").at("direct").get<double>(), entry.at("reveal").at("total").get<double>());
        EXPECT_EQ(entry.at("seconds").size(), 2u) << method;
        EXPECT_TRUE(entry.at("optimum_shift_deg").contains("24")) << method;
        for (const char* resolution : {"16", "24"}) {
            const nlohmann::json& optimum = entry.at("by_resolution").at(resolution);
            EXPECT_TRUE(optimum.contains("theta") && optimum.contains("phi") && optimum.contains("params"));
        }
        EXPECT_EQ(entry.at("by_resolution").at("16").at("visibility"), entry.at("visibility")) << method;
        // --ascent-res 16 ascends on 16^2 rays below --opt-res 24 only.
        EXPECT_EQ(entry.at("ascent_res"), nlohmann::json({{"16", 16}, {"24", 16}})) << method;
        for (const char* key : {"theta", "phi", "params"}) EXPECT_TRUE(entry.contains(key)) << method << " " << key;
    }
    EXPECT_EQ(report.at("front").at("coherence"), 1.0) << "no indirect pixel, no tear";
    EXPECT_GT(report.at("inversevis").at("visibility").get<double>(), report.at("front").at("visibility").get<double>());
    EXPECT_EQ(report.at("inversevis").at("alpha_scan"), 0) << "the paper's ascent unless --alpha-scan";
    EXPECT_NE(result.out.find("| sphere |"), std::string::npos) << result.out;
    EXPECT_NE(result.out.find("Hot-spot reveal"), std::string::npos) << result.out;
    EXPECT_TRUE(fs::exists(output("e.md")));
    // Each hot spot's shape in the method's picture.
    for (const char* method : {"front", "inversevis"}) {
        const nlohmann::json& shapes = report.at(method).at("reveal").at("shapes");
        ASSERT_EQ(shapes.size(), 2u) << method;
        for (const nlohmann::json& shape : shapes) {
            EXPECT_GE(shape.at("largest_share").get<double>(), 0.0);
            EXPECT_LE(shape.at("largest_share").get<double>(), 1.0);
        }
    }
    EXPECT_GT(report.at("front").at("reveal").at("shapes").at(0).at("pixels").get<int>() +
                  report.at("front").at("reveal").at("shapes").at(1).at("pixels").get<int>(),
              0) << "the front view shows one of the two spots";
}

TEST_F(Cli, EvaluateViewsReportsWhatSeveralViewsShowTogether)
{
    const std::string common = "evaluate scene:sphere --volume-res 64 --methods inversevis-wrap --opt-res 16 --steps 2 "
                               "--finalists 0 --min-coherence 0 --display-res 64 --cache-dir " + quoted(output("")) +
                               " --json " + quoted(output("e.json"));
    const CliResult result = runCli(common + " --views 2");
    ASSERT_EQ(result.status, 0) << result.err;
    const nlohmann::json entry = nlohmann::json::parse(std::ifstream(output("e.json"))).at("sphere").at("inversevis-wrap");
    const nlohmann::json& several = entry.at("several_views");
    ASSERT_EQ(several.at("views").size(), 2u);
    EXPECT_EQ(several.at("views").at(0).at("theta"), entry.at("theta"));
    EXPECT_GT(several.at("union").at("visibility").get<double>(), several.at("views").at(0).at("visibility").get<double>());
    EXPECT_NE(result.out.find("Several views"), std::string::npos) << result.out;
    fs::remove_all(output(""));
    fs::create_directories(output(""));
    expectRejected(common + " --views 2 --energy scalar", {"--views", "--energy visibility"});
}

TEST_F(Cli, EvaluateTakesItsMeshesAfterItsListOptions)
{
    // Each list option takes one comma-separated argument (repeated, --only adds up), so the
    // meshes may follow it instead of being read as more methods or resolutions.
    const CliResult result = runCli("evaluate --methods front,inversevis --opt-res 16 --only sphere:front "
                                    "--only torus:inversevis scene:sphere scene:torus --volume-res 48 --steps 1 "
                                    "--display-res 32 --cache-dir " + quoted(output("")) + " --json " +
                                    quoted(output("e.json")));
    ASSERT_EQ(result.status, 0) << result.err;
    const nlohmann::json report = nlohmann::json::parse(std::ifstream(output("e.json")));
    EXPECT_EQ(report.size(), 2u) << report.dump();
    EXPECT_EQ(report.at("sphere").size(), 1u);
    EXPECT_TRUE(report.at("sphere").contains("front"));
    EXPECT_TRUE(report.at("torus").contains("inversevis"));
    // A space-separated list now names a mesh, which is one line and status 2, not a method.
    expectBadInput(runCli("evaluate --methods front inversevis scene:sphere --volume-res 48"), {"inversevis"});
}

TEST_F(Cli, EvaluateResumesFromItsJsonAndWritesTheSameTables)
{
    const std::string common = "evaluate scene:sphere scene:torus --volume-res 48 --methods front,inversevis --opt-res 16 "
                               "--steps 1 --display-res 32 --cache-dir " + quoted(output("")) + " --json " +
                               quoted(output("e.json")) + " --markdown " + quoted(output("e.md"));
    const CliResult full = runCli(common);
    ASSERT_EQ(full.status, 0) << full.err;
    const std::string tables = test::readFile(output("e.md"));
    nlohmann::json partial = nlohmann::json::parse(std::ifstream(output("e.json")));
    const nlohmann::json torus = partial.at("torus");
    partial.erase("torus");
    std::ofstream(output("e.json")) << partial.dump();

    const CliResult resumed = runCli(common + " --resume");
    ASSERT_EQ(resumed.status, 0) << resumed.err;
    EXPECT_NE(resumed.err.find("sphere: kept from"), std::string::npos) << resumed.err;
    EXPECT_EQ(resumed.err.find("torus: kept from"), std::string::npos) << resumed.err;
    const nlohmann::json again = nlohmann::json::parse(std::ifstream(output("e.json")));
    ASSERT_TRUE(again.contains("torus"));
    EXPECT_EQ(again.at("torus").at("inversevis").at("visibility"), torus.at("inversevis").at("visibility"))
        << "deterministic for the seed";
    EXPECT_EQ(test::readFile(output("e.md")).substr(0, tables.find("## Viewpoint")), tables.substr(0, tables.find("## Viewpoint")))
        << "the same tables (the seconds may differ)";
    expectBadInput(runCli("evaluate scene:sphere --resume"), {"--resume needs --json"});
    // Resumed with other options, the kept meshes' figures would not be this run's (they were kept).
    nlohmann::json another = nlohmann::json::parse(std::ifstream(output("e.json")));  // another mesh of its name
    const nlohmann::json kept = another;
    another.at("sphere").at("front").at("settings")["mesh hash"] = "0123456789abcdef";
    std::ofstream(output("e.json")) << another.dump();
    expectBadInput(runCli(common + " --resume"), {"e.json: sphere:front was evaluated with mesh hash"});
    std::ofstream(output("e.json")) << kept.dump();
    expectBadInput(runCli(common + " --resume --seed 2"),
                   {"e.json: sphere:front was evaluated with --seed 1 against 2 in this run; --resume continues"});
}

#if defined(__SANITIZE_ADDRESS__)
/// A sanitizer build (scripts/test.sh --sanitize) runs two to three times slower and scans the
/// heap for leaks at exit: measured 1.6-2.1 s beside the suite's heaviest tests.
constexpr double kStopSeconds = 4.0;
#else
constexpr double kStopSeconds = 1.0;
#endif

TEST_F(Cli, EvaluateStopsOnCtrlCKeepingTheFinishedMeshes)
{
    const std::string json = output("e.json");
    const std::string common = "--volume-res 64 --methods inversevis-adaptive --opt-res 100 --display-res 32 "
                               "--cache-dir " + quoted(output("")) + " --json " + quoted(json);
    ASSERT_EQ(runCli("evaluate scene:sphere --steps 1 " + common).status, 0);
    nlohmann::json finished = nlohmann::json::parse(std::ifstream(json));  // as if of 1000 steps, resumed with them
    finished.at("sphere").at("inversevis-adaptive").at("settings")["--steps"] = 1000;
    std::ofstream(json) << finished.dump();
    // The sphere is kept; Ctrl-C arrives in the vessel tree's long annealing.
    const test::Child child = test::startCli("evaluate scene:sphere scene:vessel-tree --resume --steps 1000 " + common);
    usleep(2000000);
    const auto pressed = std::chrono::steady_clock::now();
    kill(child.pid, SIGINT);
    const CliResult result = test::waitCli(child);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - pressed).count();
    EXPECT_EQ(result.status, 130) << result.err;
    EXPECT_LT(seconds, kStopSeconds) << "stops within a second (a sanitizer build: " << kStopSeconds << " s)";
    const nlohmann::json report = nlohmann::json::parse(std::ifstream(json));
    EXPECT_TRUE(report.contains("sphere"));
    EXPECT_FALSE(report.contains("vessel-tree"));
    for (const std::string& name : contents(output("")))
        EXPECT_EQ(name.find(".tmp."), std::string::npos) << name << " left behind";
}

TEST_F(Cli, EvaluateRejectsAnUnknownMethodBeforeWork)
{
    expectRejected("evaluate scene:sphere --methods front,ring --json " + quoted(output("e.json")),
                   {"unknown method 'ring'"});
}

// Every mesh is read before any is evaluated (a bad second mesh failed after the first one's
// evaluation, leaving tables of one mesh), and two meshes of one file stem are refused (the second
// got the first one's figures, "kept from (--resume)").
TEST_F(Cli, EvaluateChecksEveryMeshBeforeWork)
{
    const std::string empty = input("empty.ply");
    writeFile(empty, "");
    const std::string args = " --methods front --opt-res 8 --steps 1 --finalists 0 --display-res 16 --volume-res 32 "
                             "--cache-dir " + quoted(output("")) + " --json " + quoted(output("e.json")) +
                             " --pictures " + quoted(output("pictures"));
    expectRejected("evaluate scene:sphere " + quoted(empty) + args, {empty + ":"});
    fs::create_directory(input("other"));
    const std::string sphere = input("sphere.obj"), otherSphere = input("other") + "/sphere.obj";
    for (const std::string& path : {sphere, otherSphere})
        writeFile(path, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
    expectRejected("evaluate " + quoted(sphere) + " " + quoted(otherSphere) + args,
                   {otherSphere + ": its name 'sphere' is also " + sphere + "'s"});
    expectRejected("evaluate scene:sphere --display-res 0" + args, {"--display-res"});
    expectRejected("evaluate scene:sphere --opt-res 8,2" + args, {"--opt-res"});
}

TEST_F(Cli, OptimizeRejectsAnAscentResolutionOutOfRange)
{
    expectRejected("optimize scene:sphere --ascent-res 2 -o " + quoted(output("best.png")),
                   {"--ascent-res", "not in range 4 to 8192"});
}

// A flag that would do nothing for what was asked is refused before work (each was ignored: an
// optimisation or picture that differed from what the user meant, without a word).
TEST_F(Cli, FlagsThatDoNothingHereAreRefused)
{
    const std::string optimize = "optimize scene:sphere --volume-res 48 --cache-dir " + quoted(output("")) + " -o " +
                                 quoted(output("b.png")) + " ";
    expectRejected(optimize + "--gamma 3", {"--gamma weights the directly visible part of the scalar energy"});
    expectRejected(optimize + "--energy scalar --method front --gradient analytic",
                   {"--gradient analytic: front's gradient is not analytic"});
    expectRejected(optimize + "--gradient analytic", {"the gradient is analytic for the scalar energy only"});
    expectRejected(optimize + "--method neugebauer --alpha-scan 5", {"--alpha-scan: no method given has a parameter"});
    expectRejected(optimize + "--opt-res 16 --ascent-res 64", {"--ascent-res 64 is not below --opt-res"});
    expectRejected(optimize + "--method mirror --min-coherence 0.5", {"--min-coherence: no method given has a rule"});
    expectRejected(optimize + "--opt-res 2", {"--opt-res: Value 2 not in range 4 to 8192"});
    expectRejected("evaluate scene:sphere --volume-res 48 --methods front,mirror --alpha-scan 5",
                   {"--alpha-scan: no method given has a parameter"});
    expectRejected(render("scene:sphere", "--method front --min-coherence 0.5"),
                   {"--min-coherence: front has no rule for drawing rays to loosen"});
    const std::string mesh = input("m.obj");
    test::writeFile(mesh, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\n");
    // Each named as given (--linear and --no-invert are the opposites of --log and --invert).
    for (const auto& [flag, name] : std::vector<std::pair<std::string, std::string>>{{"--range 0 1", "--range"},
                                                                                   {"--colormap inferno", "--colormap"},
                                                                                   {"--log", "--log"},
                                                                                   {"--linear", "--linear"},
                                                                                   {"--no-invert", "--no-invert"},
                                                                                   {"--units Pa", "--units"},
                                                                                   {"--legend bottom", "--legend"}})
        expectRejected(render(mesh, flag), {mesh + ": " + name + " colours a scalar, and the mesh shows none"});
    expectRejected(render("scene:sphere", "--legend-only " + quoted(output("bar.svg")) + " --exr " +
                                              quoted(output("x.exr"))),
                   {"--exr excludes --legend-only"});
    expectRejected(render(sharedMesh("vtk/artery_series/artery.pvd"), "--no-video --fps 3"),
                   {"--fps excludes --no-video"});
    expectRejected(render("scene:sphere", "--probe 32,0"), {"--probe '32,0': outside the 32x32 picture"});
    expectRejected(render("scene:sphere", "--probe 3"), {"--probe '3': expected X,Y"});
    for (const char* pixel : {"4294967301,0", "' 5,+5'", "5,-1", "5,5,5"})  // digits only, no wrap-around
        expectRejected(render("scene:sphere", std::string("--probe ") + pixel), {"expected X,Y"});
    expectRejected(render(sharedMesh("vtk/artery_series/artery.pvd"), "--probe 3,3"),
                   {"--probe: a series has one picture per step"});
    expectRejected(render("scene:sphere", "--probe 3,3 --legend-only " + quoted(output("bar.svg"))),
                   {"--probe excludes --legend-only"});
    expectRejected(render(sharedMesh("vtk/artery_series/artery.pvd"), "--fps 0.05"),
                   {"--fps: Value 0.05 not in range [0.1 - 240]"});
    expectRejected("evaluate scene:sphere --volume-res 48 --picture-res 32", {"--picture-res requires --pictures"});
    expectRejected("evaluate scene:sphere --volume-res 48 --opt-res 16,24,16", {"--opt-res: 16 is given twice"});
    expectRejected("merge " + quoted(input("missing.json")), {input("missing.json") + ": file not found"});
    // sdf shows no scalar, and says nothing of one (it named the array a picture would show).
    const CliResult volume = runCli("sdf " + quoted(sharedMesh("vtk/artery_series/artery_t0200.vtp")) +
                                    " --volume-res 48 -o " + quoted(output("v.vdb")));
    EXPECT_EQ(volume.status, 0) << volume.err;
    EXPECT_EQ(volume.err.find("showing"), std::string::npos) << volume.err;
    fs::remove(output("v.vdb"));
    // A series of such meshes: said once its steps are surveyed, before a volume is built.
    const std::string pvd = input("s.pvd");
    test::writeFile(pvd, "<VTKFile type=\"Collection\"><Collection><DataSet file=\"m.obj\"/><DataSet file=\"m.obj\"/>"
                         "</Collection></VTKFile>");
    expectRejected(render(pvd, "--colormap inferno"), {pvd + ": --colormap colours a scalar"});
    expectRejected(render(pvd, "--legend-only " + quoted(output("bar.svg"))), {pvd + ": no scalar to draw a colour bar"});
}

// NaN passed CLI11's range checks (every comparison with it is false): "--gamma nan" optimised a
// NaN energy and reported theta 0, phi 0.
TEST_F(Cli, OptionsRejectNaNAndValuesOutOfRange)
{
    for (const char* option : {"--gamma nan", "--polish nan", "--min-coherence nan", "--cooling 1.5", "--cooling nan",
                               "--opt-visibility-res 0", "--visibility-res -3", "--steps -1", "--polish abc"}) {
        const std::string name = std::string(option).substr(0, std::string(option).find(' '));
        expectRejected("optimize scene:sphere " + std::string(option) + " -o " + quoted(output("best.png")), {name});
    }
    expectRejected(render("scene:sphere", "--min-coherence nan"), {"--min-coherence"});
    expectRejected(render("scene:sphere", "--theta nan"), {"--theta"});  // it said "camera eye ... must be finite"
    // Refused before the volume is built (it was refused after, and left a cache and three lines).
    expectRejected(render("scene:sphere", "--spp 0"), {"--spp"});
}

}  // namespace
}  // namespace ivis::app
