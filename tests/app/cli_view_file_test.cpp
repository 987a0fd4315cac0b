// View files: optimize writes one for its best view, render --view reproduces the picture.
#include "cli_fixture.h"

#include <ivis/core/image_io.h>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <fstream>
#include <functional>

namespace ivis::app {
namespace {

TEST_F(Cli, RenderFromTheOptimisedViewFileReproducesThePicture)
{
    const std::string cache = " --volume-res 48 --cache-dir " + quoted(output(""));
    const test::CliResult optimized =
        test::runCli("optimize scene:vessel-tree --hotspots 2 --opt-res 16 --res 64x48 --steps 3 --method inversevis-wrap "
                     "--colormap magma --invert --range-percentile 5 95 --legend bottom --units 'a.u.'" + cache +
                     " -o " + quoted(output("best.png")));
    ASSERT_EQ(optimized.status, 0) << optimized.err;
    const nlohmann::json view = nlohmann::json::parse(std::ifstream(output("best.png.view.json")));
    EXPECT_EQ(view.at("method").at("method"), "inversevis-wrap");
    EXPECT_EQ(view.at("hotspots"), 2);
    EXPECT_EQ(view.at("colormap"), "magma");
    EXPECT_EQ(view.at("legend"), "bottom");
    EXPECT_EQ(view.at("size"), nlohmann::json::array({64, 48}));

    // Nothing but the mesh and the view file: the same picture, byte for byte after decoding.
    const test::CliResult rendered = test::runCli("render scene:vessel-tree --view " + quoted(output("best.png.view.json")) + cache +
                                            " -o " + quoted(output("again.png")) + " --view-out " + quoted(output("again.json")));
    ASSERT_EQ(rendered.status, 0) << rendered.err;
    const core::Image best = core::readPng(output("best.png")), again = core::readPng(output("again.png"));
    ASSERT_EQ(best.width(), again.width());
    ASSERT_EQ(best.height(), again.height());
    EXPECT_EQ(best.pixels(), again.pixels());
    nlohmann::json written = nlohmann::json::parse(std::ifstream(output("again.json")));
    EXPECT_EQ(written, view);  // the view of the re-rendered picture is the same view

    // A flag given with --view overrides the file.
    const test::CliResult grey = test::runCli("render scene:vessel-tree --view " + quoted(output("best.png.view.json")) + cache +
                                        " --colormap grey -o " + quoted(output("grey.png")));
    ASSERT_EQ(grey.status, 0) << grey.err;
    EXPECT_NE(core::readPng(output("grey.png")).pixels(), best.pixels());
}

// A method parameter given with --view overrides that parameter alone: the file's method and its
// other parameters stay (they fell back to the default method and its defaults); --method naming
// another method takes that method's defaults.
TEST_F(Cli, AParameterGivenWithAViewOverridesOnlyItself)
{
    const std::string view = quoted(output("v.json")), stats = quoted(output("s.json"));
    auto statsOf = [&](const std::string& extra) {
        const test::CliResult result = test::runCli(render("scene:sphere", extra + " --stats-json " + stats));
        EXPECT_EQ(result.status, 0) << extra << ": " << result.err;
        return nlohmann::json::parse(std::ifstream(output("s.json")));
    };
    statsOf("--method inversevis --alpha 0.3 --step 0.2 --view-out " + view);

    nlohmann::json s = statsOf("--view " + view + " --step 0.05");
    EXPECT_EQ(s.at("method"), "inversevis");
    EXPECT_FLOAT_EQ(s.at("alpha").get<float>(), 0.3f);
    EXPECT_FLOAT_EQ(s.at("step").get<float>(), 0.05f);
    s = statsOf("--view " + view + " --alpha 0.2");  // was "--alpha does not apply to the method inversevis-wrap"
    EXPECT_EQ(s.at("method"), "inversevis");
    EXPECT_FLOAT_EQ(s.at("alpha").get<float>(), 0.2f);
    EXPECT_FLOAT_EQ(s.at("step").get<float>(), 0.2f);
    s = statsOf("--view " + view + " --method inversevis --hull-offset 0.3");  // the same method, named
    EXPECT_FLOAT_EQ(s.at("alpha").get<float>(), 0.3f);
    EXPECT_FLOAT_EQ(s.at("hull_offset").get<float>(), 0.3f);
    s = statsOf("--view " + view + " --method mirror");
    EXPECT_EQ(s.at("method"), "mirror");

    // The wrap's rule from the file stays when another of its parameters is given: none is chosen.
    statsOf("--wrap-speed 1.5 --stable-shift 0.05 --ring-scale 8 --view-out " + view);
    s = statsOf("--view " + view + " --hull-offset 0.5");
    EXPECT_EQ(s.at("method"), "inversevis-wrap");
    EXPECT_FLOAT_EQ(s.at("wrap_speed").get<float>(), 1.5f);
    EXPECT_FLOAT_EQ(s.at("ring_scale").get<float>(), 8.0f);
    EXPECT_FLOAT_EQ(s.at("stable_shift").get<float>(), 0.05f);
    EXPECT_FALSE(s.contains("readable_rule"));
}

// A view of a scalar given by --scalar-file shows that scalar again (it showed none: grey).
TEST_F(Cli, AViewKeepsItsScalarFile)
{
    const std::string mesh = input("tetra.obj"), values = input("values.txt");
    test::writeFile(mesh, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
    test::writeFile(values, "1\n2\n3\n4\n");
    const test::CliResult first = test::runCli(render(mesh, "--method front --scalar-file " + quoted(values) +
                                                             " --view-out " + quoted(output("v.json"))));
    ASSERT_EQ(first.status, 0) << first.err;
    const core::Image picture = core::readPng(output("x.png"));
    const test::CliResult again = test::runCli(render(mesh, "--view " + quoted(output("v.json"))));
    ASSERT_EQ(again.status, 0) << again.err;
    EXPECT_EQ(core::readPng(output("x.png")).pixels(), picture.pixels());
}

// A view keeps --cell-to-point, --spp and --transparent (it came back flat, aliased and opaque).
TEST_F(Cli, AViewKeepsCellToPointSupersamplingAndTransparency)
{
    const std::string step = test::sharedMesh("vtk/artery_series/artery_t0200.vtp"), view = quoted(output("v.json"));
    const test::CliResult first = test::runCli(render(step, "--method front --scalar pressure_cell --cell-to-point "
                                                            "--spp 2 --transparent --view-out " + view));
    ASSERT_EQ(first.status, 0) << first.err;
    const core::Image picture = core::readPng(output("x.png"));
    const test::CliResult again = test::runCli(render(step, "--view " + view));
    ASSERT_EQ(again.status, 0) << again.err;
    EXPECT_EQ(core::readPng(output("x.png")).pixels(), picture.pixels());
    ASSERT_EQ(test::runCli(render(step, "--view " + view + " --spp 1")).status, 0);  // a flag still overrides
    EXPECT_NE(core::readPng(output("x.png")).pixels(), picture.pixels());
    // --cell-to-point alone averages the view's array (it took the file's active cell array instead).
    const std::string flat = quoted(output("flat.json"));
    ASSERT_EQ(test::runCli(render(step, "--method front --scalar pressure_cell --view-out " + flat)).status, 0);
    ASSERT_EQ(test::runCli(render(step, "--view " + flat + " --cell-to-point --view-out " + view)).status, 0);
    const nlohmann::json averaged = nlohmann::json::parse(std::ifstream(output("v.json")));
    EXPECT_EQ(averaged.at("scalar"), "pressure_cell");
    EXPECT_EQ(averaged.at("cell_to_point"), true);
}

// A colour-scale or legend flag given with --view overrides its own part of the file: --invert
// kept the file's log scale and range (it threw the whole scale away), --legend SIDE shows a
// legend the file had off (it stayed off), --shadows turns on what the file turned off, and
// --ortho, which the file's camera ignored, is refused.
TEST_F(Cli, AScaleOrLegendFlagGivenWithAViewOverridesOnlyItsPart)
{
    const std::string mesh = input("tetra.obj"), values = input("values.txt");
    test::writeFile(mesh, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
    test::writeFile(values, "1\n2\n3\n4\n");
    const std::string view = quoted(output("v.json")), again = quoted(output("w.json"));
    ASSERT_EQ(test::runCli(render(mesh, "--method front --scalar-file " + quoted(values) +
                                            " --range 2 3 --log --no-legend --no-shadows --view-out " + view))
                  .status,
              0);
    const int bare = core::readPng(output("x.png")).width();
    const test::CliResult inverted = test::runCli(render(mesh, "--view " + view + " --invert --view-out " + again));
    ASSERT_EQ(inverted.status, 0) << inverted.err;
    const nlohmann::json scale = nlohmann::json::parse(std::ifstream(output("w.json"))).at("scale");
    EXPECT_EQ(scale.at("range"), nlohmann::json::array({2.0, 3.0}));
    EXPECT_EQ(scale.at("log"), true);
    EXPECT_EQ(scale.at("invert"), true);
    EXPECT_EQ(core::readPng(output("x.png")).width(), bare);  // the file's legend: none
    ASSERT_EQ(test::runCli(render(mesh, "--view " + view + " --legend left")).status, 0);
    EXPECT_GT(core::readPng(output("x.png")).width(), bare);
    // The file's log scale is kept beside a range of another sign, and says so; --linear drops it.
    expectBadInput(test::runCli(render(mesh, "--view " + view + " --range -1 1")),
                   {"(the --view file's log scale; --linear for a linear one)"});
    ASSERT_EQ(test::runCli(render(mesh, "--view " + view + " --range -1 1 --linear --view-out " + again)).status, 0);
    EXPECT_EQ(nlohmann::json::parse(std::ifstream(output("w.json"))).at("scale").at("log"), false);
    // A look the file turned off is turned on again by its opposite flag (there was none).
    ASSERT_EQ(test::runCli(render(mesh, "--view " + view + " --shadows --view-out " + again)).status, 0);
    EXPECT_EQ(nlohmann::json::parse(std::ifstream(output("w.json"))).at("shadows"), true);
    expectBadInput(test::runCli(render(mesh, "--view " + view + " --ortho")), {"--ortho excludes --view"});
    expectBadInput(test::runCli(render(mesh, "--legend left --no-legend")), {"--legend excludes --no-legend"});
}

// A view file's range and units are its scalar's. Another scalar given beside it takes its own
// data's range and shows no units (the VaMPy artery's pressure at t600 came out in the range of the
// file's t200: one colour), the file's inversion still kept; the file's scalar, named or not, keeps
// the file's range and units.
TEST_F(Cli, AnotherScalarGivenWithAViewTakesItsOwnRange)
{
    const std::string mesh = test::sharedMesh("vampy_artery_cfd_pressure.ply");
    const std::string view = quoted(output("v.json"));
    auto viewOf = [&](const std::string& arguments) {
        const test::CliResult result = test::runCli(render(mesh, arguments + " --view-out " + quoted(output("w.json"))));
        EXPECT_EQ(result.status, 0) << arguments << ": " << result.err;
        return nlohmann::json::parse(std::ifstream(output("w.json")));
    };
    const nlohmann::json own = viewOf("--method front --scalar pressure_t600").at("scale");  // its data's range
    ASSERT_EQ(test::runCli(render(mesh, "--method front --scalar pressure_t200 --range 0.3 0.7 --invert --units kPa "
                                        "--view-out " + view))
                  .status,
              0);
    const nlohmann::json file = nlohmann::json::parse(std::ifstream(output("v.json"))).at("scale");
    ASSERT_NE(file.at("range"), own.at("range"));

    nlohmann::json other = viewOf("--view " + view + " --scalar pressure_t600");
    EXPECT_EQ(other.at("scale").at("range"), own.at("range"));
    EXPECT_EQ(other.at("scale").at("invert"), true);
    EXPECT_EQ(other.at("units"), "");
    for (const char* same : {"", " --scalar pressure_t200"}) {
        const nlohmann::json again = viewOf("--view " + view + same);
        EXPECT_EQ(again.at("scale").at("range"), file.at("range")) << same;
        EXPECT_EQ(again.at("units"), "kPa") << same;
    }
    // A range and units given beside the other scalar are its own.
    other = viewOf("--view " + view + " --scalar pressure_t600 --range 0 0.1 --units Pa");
    EXPECT_EQ(other.at("scale").at("range")[0].get<double>(), 0.0);
    EXPECT_NEAR(other.at("scale").at("range")[1].get<double>(), 0.1, 1e-7);
    EXPECT_EQ(other.at("units"), "Pa");
    // A generated scene carries its own scalar: the view's array is named, not --scalar (never given).
    expectBadInput(test::runCli(render("scene:torus", "--view " + view)),
                   {output("v.json") + ": shows the array 'pressure_t200' of the mesh it was saved from; scene:torus "
                                       "carries its own scalar"});
}

TEST_F(Cli, BadViewFilesAreRejectedWithTheirName)
{
    const std::string bad = input("bad.view.json");
    test::writeFile(bad, R"({"inversevis_view": 1, "camera": {"eye": [0, 0, 2.5]}})");
    // The JSON library's words, without its "[json.exception.out_of_range.403]".
    expectRejected(render("scene:sphere", "--view " + quoted(bad)),
                   {"bad.view.json: bad view file (key 'size' not found)"});
    test::writeFile(bad, R"({"inversevis_view": 7})");
    expectRejected(render("scene:sphere", "--view " + quoted(bad)), {"bad.view.json", "version 7"});
    test::writeFile(bad, "{");
    expectRejected(render("scene:sphere", "--view " + quoted(bad)), {"bad.view.json: bad view file"});
    expectRejected(render("scene:sphere", "--view " + quoted(bad) + " --theta 10"), {"--view"});

    // Numbers that a cast would have truncated (2.5 pixels), made undefined (1e30) or infinite.
    const std::string good = output("good.json");
    ASSERT_EQ(test::runCli(render("scene:sphere", "--method front --view-out " + quoted(good))).status, 0);
    const nlohmann::json view = nlohmann::json::parse(std::ifstream(good));
    auto rejectedWith = [&](const std::function<void(nlohmann::json&)>& change, const std::string& problem) {
        nlohmann::json changed = view;
        change(changed);
        test::writeFile(bad, changed.dump());
        const test::CliResult result = test::runCli(render("scene:sphere", "--view " + quoted(bad)));
        SCOPED_TRACE(changed.dump());
        expectBadInput(result, {"bad.view.json: bad view file", problem});
    };
    rejectedWith([](nlohmann::json& v) { v["inversevis_view"] = 8.9e93; }, "'inversevis_view' must be a whole number");
    // An integer beyond int64, read as unsigned, was named "version -1".
    rejectedWith([](nlohmann::json& v) { v["inversevis_view"] = std::uint64_t(18446744073709551615u); },
                 "version 18446744073709551615 (this program reads 1 to");
    rejectedWith([](nlohmann::json& v) { v["size"] = {2.5, 32}; }, "'size' must be a whole number from 1 to 32768");
    rejectedWith([](nlohmann::json& v) { v["size"] = {1e30, 32}; }, "'size' must be a whole number");
    rejectedWith([](nlohmann::json& v) { v["hotspots"] = 1e30; }, "'hotspots' must be a whole number from 0 to 6");
    rejectedWith([](nlohmann::json& v) { v["scale"]["range"] = {-1e300, 1e300}; }, "'scale.range' must be a finite number");
    rejectedWith([](nlohmann::json& v) { v["method"] = {{"method", "inversevis"}, {"alpha", 1e300}}; },
                 "method parameter 'alpha' is not a finite number");
    // A value of another type names its key (the JSON library's "cannot use at() with null").
    rejectedWith([](nlohmann::json& v) { v["scale"] = nullptr; }, "'scale' must be an object");
    rejectedWith([](nlohmann::json& v) { v["mesh_units"] = "mm"; }, "'mesh_units' must be an object");
    rejectedWith([](nlohmann::json& v) { v["shadows"] = nullptr; }, "'shadows' must be true or false");
    rejectedWith([](nlohmann::json& v) { v["scale"]["log"] = 1; }, "'log' must be true or false");
    rejectedWith([](nlohmann::json& v) { v["units"] = 3; }, "'units' must be a string");
    rejectedWith([](nlohmann::json& v) { v["legend"] = 5; }, "'legend' must be a side's name or null");
}

}  // namespace
}  // namespace ivis::app
