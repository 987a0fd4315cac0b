// The outputs of `inversevis` as a user meets them: files named for their format and apart, nothing
// left on a failure, info and sdf reports, the volume cache.
#include "cli_fixture.h"

#include <gtest/gtest.h>
#include <ivis/core/camera.h>
#include <ivis/core/image_io.h>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <fcntl.h>
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
#include <thread>
#include <utility>
#include <vector>

namespace ivis::app {
namespace {

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
    // JSON and Markdown are named so too: `--view-out fig.png` replaced a figure with JSON.
    expectRejected(render("scene:sphere", "--view-out " + quoted(output("fig.png"))),
                   {output("fig.png") + ": --view-out writes .json files (name it so)"});
    expectRejected(render("scene:sphere", "--camera-out " + quoted(output("c.exr"))),
                   {"c.exr: --camera-out writes .json"});
    expectRejected("merge " + quoted(output("none.json")) + " --markdown " + quoted(output("t.txt")),
                   {output("t.txt") + ": --markdown writes .md or .markdown files"});
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
    // (A JSON output cannot name a frame or the video: it is named .json.)
    expectRejected(render(pvd, "--no-video --stats-json " + quoted(output("x_0001.png"))),
                   {"x_0001.png: --stats-json writes .json files"});
    expectRejected(render(pvd, "--camera-out " + quoted(output("x.mp4"))), {"x.mp4: --camera-out writes .json files"});
    expectRejected("optimize " + quoted(pvd) + " --volume-res 48 -o " + quoted(output("b.png")) + " --plot " +
                       quoted(output("b_0000.png")),
                   {"b_0000.png: named by both --plot and -o (frame 0)"});
    test::writeFile(input("v.json"), "{}");
    expectRejected(render("scene:sphere", "--view-out " + quoted(input("v.json")) + " --view " +
                                              quoted(input("v.json"))),
                   {"--view-out would overwrite --view"});
    fs::create_directory(input("folder.png"));
    expectRejected(render("scene:sphere", "--tear-map " + quoted(input("folder.png"))),
                   {input("folder.png") + ": --tear-map names a folder, not a file"});
    // Any case of the extension; JSON into a named pipe (or /dev/stdout), whatever its name.
    const std::string pipe = output("stats");
    ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
    std::string received;
    std::thread reader([&] { received = test::readFile(pipe); });
    const CliResult upper = runCli("render scene:sphere --volume-res 48 --res 32x32 --cache-dir " + quoted(output("")) +
                                   " -o " + quoted(output("X.PNG")) + " --stats-json " + quoted(pipe));
    // Had the command never opened the pipe, the reader would wait for ever: open it for it.
    if (const int unblock = ::open(pipe.c_str(), O_WRONLY | O_NONBLOCK); unblock >= 0) ::close(unblock);
    reader.join();
    EXPECT_EQ(upper.status, 0) << upper.err;
    EXPECT_TRUE(fs::exists(output("X.PNG")));
    EXPECT_TRUE(nlohmann::json::accept(received)) << received;
    EXPECT_TRUE(fs::is_fifo(pipe));
    // /dev/stdout redirected to a file (as runCli does, and a batch system's log): the JSON goes
    // there after what the command printed before it, and nothing replaces the file.
    const CliResult toFile = runCli("-q render scene:sphere --volume-res 48 --res 32x32 --cache-dir " +
                                    quoted(output("")) + " -o " + quoted(output("Y.png")) + " --stats-json /dev/stdout");
    EXPECT_EQ(toFile.status, 0) << toFile.err;
    EXPECT_TRUE(nlohmann::json::accept(toFile.out)) << toFile.out;
    const CliResult both = runCli("optimize scene:sphere --volume-res 48 --opt-res 16 --steps 1 --cache-dir " +
                                  quoted(output("")) + " -o " + quoted(output("Z.png")) + " --json /dev/stdout");
    EXPECT_EQ(both.status, 0) << both.err;
    const std::size_t brace = both.out.find('{');
    ASSERT_NE(brace, std::string::npos) << both.out;
    EXPECT_TRUE(nlohmann::json::accept(both.out.substr(brace))) << both.out;
}

/// The command prefix that gives the CLI about 2 GB of memory; its sanitizer reports, if any, go
/// to files starting with @a logPath.
std::string memoryLimit(const std::string& logPath)
{
#if defined(__SANITIZE_ADDRESS__)
    // AddressSanitizer reserves terabytes of address space for its shadow, so under `ulimit -v` it
    // cannot start: a sanitizer build (scripts/test.sh --sanitize) caps each allocation at 2000 MB
    // instead, which fails the larger ones as the plain build's allocator does (its warning logged).
    return "export ASAN_OPTIONS=\"$ASAN_OPTIONS:max_allocation_size_mb=2000:allocator_may_return_null=1:log_path=" +
           logPath + "\"; ";
#else
    (void)logPath;
    return "ulimit -v 2000000; ";
#endif
}

// A picture larger than the memory is one line and status 2 (it was "internal error: std::bad_alloc",
// status 1), and leaves nothing.
TEST_F(Cli, APictureLargerThanTheMemoryIsOneLine)
{
    const std::string command = memoryLimit(input("asan")) + "exec '" + std::string(IVIS_CLI_PATH) +
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
    // A name the file system cannot hold is one line too (it was an internal error).
    const std::string tooLong = output(std::string(251, 'a') + ".png");
    expectBadInput(runCli("render scene:sphere --volume-res 32 --res 32x32 -o " + quoted(tooLong)),
                   {".png.camera.json: File name too long"});
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

}  // namespace
}  // namespace ivis::app
