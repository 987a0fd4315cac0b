// `inversevis evaluate` as a user runs it: the measures of every method, several views, resuming,
// Ctrl-C, and its refusals before work.
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

TEST_F(Cli, EvaluateTablesEscapeAMeshNameThatWouldSplitACell)
{
    const std::string mesh = input("left|right.obj");  // its '|' added a column to every row
    test::writeFile(mesh, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
    const CliResult result = runCli("evaluate " + quoted(mesh) + " --volume-res 32 --methods front --opt-res 16 "
                                    "--steps 0 --display-res 32 --cache-dir " + quoted(output("")) + " --markdown " +
                                    quoted(output("e.md")));
    ASSERT_EQ(result.status, 0) << result.err;
    const std::string tables = test::readFile(output("e.md"));
    EXPECT_NE(tables.find("\n| left\\|right | "), std::string::npos) << tables;
    EXPECT_EQ(tables.find("| left|right |"), std::string::npos) << tables;
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
    // A space-separated list now names a mesh, which is one line and status 2, not a method; the
    // line says how to give the list (it said only "inversevis: file not found").
    expectBadInput(runCli("evaluate --methods front inversevis scene:sphere --volume-res 48"),
                   {"inversevis: file not found, and a method's name: --methods takes them comma-separated"});
    expectBadInput(runCli("evaluate --opt-res 16 100 scene:sphere --volume-res 48"),
                   {"100: file not found, and a number: --opt-res takes them comma-separated"});
    expectBadInput(runCli("evaluate --methods front,front scene:sphere --volume-res 48"),
                   {"--methods: front is given twice"});
    // A list of commas only: CLI11 dropped its empty items and took the next argument as the list.
    expectBadInput(runCli("evaluate --opt-res ,, --methods front scene:sphere --volume-res 48"),
                   {"--opt-res: ',,' lists nothing"});
    expectBadInput(runCli("evaluate --methods=, scene:sphere --volume-res 48"), {"--methods: ',' lists nothing"});
    // A seed out of range: "-1" and 2^64 both ran as 2^64 - 1.
    for (const char* seed : {"-1", "18446744073709551616", "1e3"})
        expectBadInput(runCli(std::string("optimize scene:sphere --volume-res 48 --seed ") + seed),
                       {std::string("'") + seed + "' is not a whole number from 0 to 18446744073709551615"});
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
    // Resumed with one mesh and one method, the tables still show every mesh and method the file holds.
    const std::string torusOnly = "evaluate scene:torus --volume-res 48 --methods inversevis --opt-res 16 --steps 1 "
                                  "--display-res 32 --cache-dir " + quoted(output("")) + " --json " +
                                  quoted(output("e.json")) + " --resume";
    const CliResult one = runCli(torusOnly);
    ASSERT_EQ(one.status, 0) << one.err;
    EXPECT_NE(one.err.find("torus: kept from"), std::string::npos) << one.err;
    const std::string first = one.out.substr(0, one.out.find("\n\n", one.out.find("|---")));  // the first table
    for (const char* row : {"| Surface | inversevis | front |", "\n| sphere | ", "\n| torus | "})
        EXPECT_NE(first.find(row), std::string::npos) << row << " in\n" << one.out;
    expectBadInput(runCli("evaluate scene:sphere --resume"), {"--resume needs --json"});
    // A kept entry that is not an evaluation's is found on reading, before any mesh is evaluated.
    nlohmann::json broken = nlohmann::json::parse(std::ifstream(output("e.json")));
    broken.at("sphere").at("front")["visibility"] = "high";
    std::ofstream(output("broken.json")) << broken.dump();
    expectBadInput(runCli(torusOnly.substr(0, torusOnly.find(" --json ")) + " --json " + quoted(output("broken.json")) +
                          " --resume"),
                   {"broken.json: sphere:front is not an evaluation's (its visibility is not a number from 0 to 1)"});
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

}  // namespace
}  // namespace ivis::app
