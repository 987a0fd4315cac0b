// `inversevis optimize` as a user runs it: the best view, its picture and files, several views, the
// readable rule, and its refusals.
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

TEST_F(Cli, OptimizeReportsTheHotSpotsShapesInItsPictureAsRenderMeasuresThem)
{
    const std::string files = " --volume-res 64 --hotspots 2 --cache-dir " + quoted(output(""));
    const CliResult result = runCli("optimize scene:torus" + files + " --energy scalar --opt-res 24 --steps 2 "
                                    "--finalists 0 --res 120x120 -o " + quoted(output("best.png")) + " --json " +
                                    quoted(output("best.json")));
    ASSERT_EQ(result.status, 0) << result.err;
    const nlohmann::json shapes = nlohmann::json::parse(std::ifstream(output("best.json"))).at("measures").at("reveal").at("shapes");
    ASSERT_EQ(shapes.size(), 2u);
    // The best view's file draws the same picture, whose shapes render --measure finds the same.
    const CliResult again = runCli("render scene:torus" + files + " --view " + quoted(output("best.png.view.json")) +
                                   " -o " + quoted(output("again.png")) + " --measure --stats-json " + quoted(output("again.json")));
    ASSERT_EQ(again.status, 0) << again.err;
    EXPECT_EQ(shapes, nlohmann::json::parse(std::ifstream(output("again.json"))).at("measures").at("reveal").at("shapes"));
    int shown = 0;
    for (const nlohmann::json& shape : shapes) shown += shape.at("pixels").get<int>();
    EXPECT_GT(shown, 0);
}

TEST_F(Cli, OptimizeTakesTheBestViewWhoseHotSpotsReadAsOnePlace)
{
    // The cow's best view by the scalar energy shows a flank's hot spot in pieces round the rings:
    // the far flank's, facing away from the eye, which the rule does not even judge.
    const std::string common = "optimize " + quoted(test::sharedMesh("cow.ply")) +
                               " --volume-res 64 --hotspots 2 --energy scalar --opt-res 24 --steps 2 --finalists 0 "
                               "--res 120x120 --cache-dir " + quoted(output("")) + " -o " + quoted(output("best.png"));
    ASSERT_EQ(runCli(common + " --json " + quoted(output("rule.json"))).status, 0);
    ASSERT_EQ(runCli(common + " --hot-spot-views 0 --json " + quoted(output("plain.json"))).status, 0);
    const nlohmann::json rule = nlohmann::json::parse(std::ifstream(output("rule.json")));
    const nlohmann::json plain = nlohmann::json::parse(std::ifstream(output("plain.json")));
    EXPECT_FALSE(plain.contains("hot_spot_rule"));
    const nlohmann::json& choice = rule.at("hot_spot_rule");
    ASSERT_FALSE(choice.at("chosen_view").is_null()) << choice.dump();
    EXPECT_TRUE(choice.at("reads").get<bool>()) << choice.dump();
    EXPECT_EQ(choice.at("shortfall").get<double>(), 0.0);
    EXPECT_GE(choice.at("judged").get<int>(), 1);
    const nlohmann::json& chosen = rule.at("visited").at(choice.at("chosen_view").get<std::size_t>());
    EXPECT_EQ(rule.at("theta"), chosen.at("theta"));
    EXPECT_EQ(rule.at("phi"), chosen.at("phi"));
    EXPECT_NE(std::make_pair(rule.at("theta"), rule.at("phi")), std::make_pair(plain.at("theta"), plain.at("phi")));
    EXPECT_GT(choice.at("energy_ratio").get<double>(), 0.0);
    EXPECT_LT(choice.at("energy_ratio").get<double>(), 1.0) << "a view of less energy than the best";
    for (const nlohmann::json& shape : choice.at("shapes")) {
        EXPECT_GE(shape.at("largest_share").get<double>(), 0.9);
        EXPECT_LE(shape.at("outline_ratio").get<double>(), 1.6);
    }
    // The rule chooses among views by the scalar energy only.
    fs::remove_all(output(""));
    fs::create_directories(output(""));
    expectRejected("optimize scene:sphere --volume-res 64 --opt-res 24 --hot-spot-views 3 -o " + quoted(output("s.png")),
                   {"--hot-spot-views", "--energy"});
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
    const nlohmann::json& choice = readable.at("readable_rule");
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
    const nlohmann::json renderedChoice = nlohmann::json::parse(std::ifstream(output("r.json"))).at("readable_rule");
    EXPECT_EQ(renderedChoice.at("value"), choice.at("value"));
    EXPECT_NEAR(renderedChoice.at("estimated_coherence").get<double>(), choice.at("estimated_coherence").get<double>(), 1e-9);

    ASSERT_EQ(optimizeTree("0", "given.json").status, 0);
    const nlohmann::json given = nlohmann::json::parse(std::ifstream(output("given.json")));
    EXPECT_FALSE(given.contains("readable_rule")) << "0: no readable rule";
    EXPECT_FLOAT_EQ(given.at("params").at("stable_shift").get<float>(), 0.1f);
    EXPECT_LT(given.at("measures").at("visibility").get<double>(), readable.at("measures").at("visibility").get<double>())
        << "the looser rule shows more";
}

TEST_F(Cli, OptimizeRejectsAnAscentResolutionOutOfRange)
{
    expectRejected("optimize scene:sphere --ascent-res 2 -o " + quoted(output("best.png")),
                   {"--ascent-res", "not in range 4 to 8192"});
}

}  // namespace
}  // namespace ivis::app
