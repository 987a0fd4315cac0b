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
    const std::string pipe = input("mesh.ply");  // opening a FIFO would wait for a writer for ever
    ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
    expectMeshRejected(pipe, {pipe + ": not a regular file (a pipe or device)"});
    fs::remove(pipe);

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
    expectRejected(sdf(mesh, "--scalar-file " + quoted(values)), {values + ": line 1: value 2 'x' is not a number"});
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
    expectRejected(render(mesh, "--fov 180"), {"field of view 180 is out of range (0 to 180 degrees)"});
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
    // A reach outside (0, 2] names the option (it said only "far-field reach -1.000000 is out of range").
    for (const char* reach : {"-1", "0", "2.5", "nan"})
        expectRejected(render(mesh, std::string("--reach ") + reach), {"--reach: "});
    EXPECT_EQ(runCli(render(mesh, "--hull-offset 0.7 --reach 0.8")).status, 0);
    // Without --reach the far field reaches as far as the method's rays need.
    EXPECT_EQ(runCli(render(mesh, "--hull-offset 1.5")).status, 0);
    EXPECT_EQ(runCli(render(mesh, "--method inversevis --hull-offset 1.3")).status, 0);
    // Beyond the volume's largest reach, the message names the hull offset, not a reach never given.
    expectBadInput(runCli(render(mesh, "--method inversevis --hull-offset 1.9")),
                   {"inversevis --hull-offset 1.9 needs a volume reaching 2.5, beyond the largest (2): at most 1.4"});
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
    expectRejected(render(mesh, "--camera " + quoted(shape)),
                   {shape + ": bad camera file ('eye' must be [x, y, z] of numbers)"});
    // A value of the wrong type names its key (nlohmann's "[json.exception.type_error.302] type
    // must be number, but is string" named none).
    writeFile(shape, R"({"eye": [0, 0, 2.5], "fov_y_deg": "wide"})");
    expectRejected(render(mesh, "--camera " + quoted(shape)),
                   {shape + ": bad camera file ('fov_y_deg' must be a number)"});
    writeFile(shape, R"({"eye": [0, "0", 2.5]})");
    expectRejected(render(mesh, "--camera " + quoted(shape)),
                   {shape + ": bad camera file ('eye' must be [x, y, z] of numbers)"});
    writeFile(shape, R"({"eye": [0, 0, 2.5], "orthographic": 1})");
    expectRejected(render(mesh, "--camera " + quoted(shape)),
                   {shape + ": bad camera file ('orthographic' must be true or false)"});
    // Named as every other missing file is (CLI11 said "File does not exist: PATH").
    expectRejected(render(mesh, "--camera " + quoted(input("none.json"))), {input("none.json") + ": file not found"});
    fs::create_directory(input("folder.json"));
    expectRejected(render(mesh, "--view " + quoted(input("folder.json"))),
                   {input("folder.json") + ": a folder, not a file"});
}

TEST_F(Cli, BadFlagFailsBeforeTheMeshIsReadAndLogged)
{
    // Reading this mesh logs a line (dropped triangle), capping another; neither may precede the error.
    const std::string path = input("tetra.obj");
    writeFile(path, kTetraWithDegenerateObj);
    expectRejected(render(path, "--colormap jet"), {"unknown colour map 'jet'"});
    expectRejected(render("scene:vessel-tree", "--cap-holes --range 2 1"), {"invalid range [2, 1]"});
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
    expectRejected(renderLegendOnly("scene:sphere", output("bar.svg"), "--exr " + quoted(output("x.exr"))),
                   {"--exr excludes --legend-only"});
    expectRejected(render(sharedMesh("vtk/artery_series/artery.pvd"), "--no-video --fps 3"),
                   {"--fps excludes --no-video"});
    expectRejected(render("scene:sphere", "--probe 32,0"), {"--probe '32,0': outside the 32x32 picture"});
    expectRejected(render("scene:sphere", "--probe 3"), {"--probe '3': expected X,Y"});
    for (const char* pixel : {"4294967301,0", "' 5,+5'", "5,-1", "5,5,5"})  // digits only, no wrap-around
        expectRejected(render("scene:sphere", std::string("--probe ") + pixel), {"expected X,Y"});
    expectRejected(render(sharedMesh("vtk/artery_series/artery.pvd"), "--probe 3,3"),
                   {"--probe: a series has one picture per step"});
    expectRejected(renderLegendOnly("scene:sphere", output("bar.svg"), "--probe 3,3"),
                   {"--probe excludes --legend-only"});
    expectRejected(render(sharedMesh("vtk/artery_series/artery.pvd"), "--fps 0.05"),
                   {"--fps: Value 0.05 not in range [0.1 - 240]"});
    expectRejected("rendr scene:sphere", {"'rendr' is not a command; the commands are info sdf render optimize"});
    expectRejected("evaluate scene:sphere --volume-res 48 --picture-res 32", {"--picture-res requires --pictures"});
    expectRejected(renderLegendOnly("scene:sphere", output("bar.svg"), "-o " + quoted(output("x.png"))),
                   {"--output excludes --legend-only"});
    for (const char* ignored : {"--no-legend", "--theta 30", "--spp 4", "--method mirror", "--ortho"})
        expectRejected(renderLegendOnly("scene:sphere", output("bar.svg"), ignored),
                       {std::string(ignored).substr(0, std::string(ignored).find(' ')) + " excludes --legend-only"});
    expectRejected(renderLegendOnly(sharedMesh("vtk/artery_series/artery.pvd"), output("bar.svg"), "--range-per-frame"),
                   {"--legend-only excludes --range-per-frame"});
    // --pictures is a folder: naming the same path as a table is refused before the evaluation (it
    // ran, wrote the pictures, then failed to write the table).
    expectRejected("evaluate scene:sphere --volume-res 48 --pictures " + quoted(output("p.md")) + " --markdown " +
                       quoted(output("p.md")),
                   {output("p.md") + ": --pictures and --markdown name the same path"});
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
    expectRejected(renderLegendOnly(pvd, output("bar.svg")), {pvd + ": no scalar to draw a colour bar"});
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
    // A value that is no number of the option's type, in words (CLI11 said "Could not convert: --step = abc").
    expectRejected(render("scene:sphere", "--step abc"), {"--step: 'abc' is not a number"});
    expectRejected(render("scene:sphere", "--theta 0x10"), {"--theta: '0x10' is not a number"});  // it was 16 degrees
    expectRejected(render("scene:sphere", "--spp 1.5"), {"--spp: '1.5' is not a whole number from 1 to 1024"});
    expectRejected(render("scene:sphere", "--volume-res x"), {"--volume-res: 'x' is not a whole number from 16 to 4096"});
    expectRejected(render("scene:sphere", "--spp 2000"), {"--spp: Value 2000 not in range 1 to 1024"});
    expectRejected("info scene:bogus", {"unknown scene 'bogus' (known: sphere, torus, vessel-tree)"});
    // Refused before the volume is built (it was refused after, and left a cache and three lines).
    expectRejected(render("scene:sphere", "--spp 0"), {"--spp"});
}

}  // namespace
}  // namespace ivis::app
