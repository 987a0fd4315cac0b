// `inversevis render` as a user runs it: the readable rule, statistics, tear and unseen maps, probes,
// measures and framing.
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
    const nlohmann::json& choice = readable.at("readable_rule");
    EXPECT_EQ(choice.at("parameter"), "stable_shift");
    EXPECT_GT(choice.at("value").get<double>(), 0.1001) << "loosened";
    EXPECT_EQ(choice.at("value"), readable.at("stable_shift")) << "the picture is drawn with the chosen rule";
    EXPECT_GE(choice.at("estimated_coherence").get<double>(), 0.5);
    EXPECT_EQ(choice.at("picture_size"), nlohmann::json::array({1000, 1000}));
    // The 1000 x 1000 picture of the same view gets the same rule, from the same estimate; a wide
    // picture is judged in its own aspect.
    const nlohmann::json large = renderTree("large", "--fov 63 --min-coherence 0.5", "1000x1000");
    EXPECT_EQ(large.at("readable_rule"), choice);
    const nlohmann::json wide = renderTree("wide", "--fov 63 --min-coherence 0.5", "96x64");
    EXPECT_EQ(wide.at("readable_rule").at("picture_size"), nlohmann::json::array({1500, 1000}));

    const nlohmann::json given = renderTree("given", "--fov 63 --min-coherence 0.5 --stable-shift 0.005");
    EXPECT_FALSE(given.contains("readable_rule")) << "a rule given is drawn as given";
    EXPECT_FLOAT_EQ(given.at("stable_shift").get<float>(), 0.005f);
    EXPECT_LT(given.at("pixels_indirect").get<int>(), readable.at("pixels_indirect").get<int>()) << "the looser rule draws more";
    const nlohmann::json off = renderTree("off", "--fov 63 --min-coherence 0");
    EXPECT_FALSE(off.contains("readable_rule"));
    EXPECT_FLOAT_EQ(off.at("stable_shift").get<float>(), 0.1f) << "the default rule";
    const nlohmann::json tight = renderTree("tight", "--fov 63 --min-coherence 0.9999");
    EXPECT_FLOAT_EQ(tight.at("readable_rule").at("value").get<float>(), 0.0125f) << "tightened to the ladder's foot";
    EXPECT_FALSE(tight.at("readable_rule").at("keeps_min_coherence").get<bool>()) << "and still short of 0.9999";
    EXPECT_TRUE(choice.at("keeps_min_coherence").get<bool>());
    EXPECT_LT(tight.at("pixels_indirect").get<int>(), off.at("pixels_indirect").get<int>()) << "the tighter rule draws less";
    expectBadInput(runCli("render scene:vessel-tree --volume-res 64 --min-coherence 0.5 --method inversevis -o " +
                          quoted(output("faithful.png"))),
                   {"--min-coherence: inversevis has no rule"});  // a method without such a rule: it did nothing

    const nlohmann::json again = renderTree("again", "--min-coherence 0.5 --view " + quoted(output("v.json")));
    EXPECT_FALSE(again.contains("readable_rule")) << "the view file gives the rule";
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

// The ring map's rays start inside the object and see a wall from within; a view from outside sees
// its other side (every ring pixel of a sphere said that no view did).
TEST_F(Cli, RenderProbeOfTheRingMapNamesAViewFromOutside)
{
    std::string probes;
    for (int x = 0; x < 64; ++x) probes += " --probe " + std::to_string(x) + ",32";
    const CliResult result = runCli("render scene:sphere --method neugebauer --volume-res 64 --hotspots 2 --res 64x64 "
                                    "--cache-dir " + quoted(output("")) + probes + " -o " + quoted(output("p.png")) +
                                    " --stats-json " + quoted(output("p.json")));
    ASSERT_EQ(result.status, 0) << result.err;
    int indirect = 0;
    const nlohmann::json stats = nlohmann::json::parse(std::ifstream(output("p.json")));
    for (const nlohmann::json& report : stats.at("probes")) {
        if (!report.contains("position")) continue;
        EXPECT_TRUE(report.at("view").is_object()) << report.dump();
        indirect += report.at("region") == "indirect";
    }
    EXPECT_GT(indirect, 4);
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

}  // namespace
}  // namespace ivis::app
