// `render` over a time series (a .pvd, several files, a --scalar pattern): one frame per step,
// one colour range over all steps, the volume built once per geometry, numbered outputs written
// together, a video when ffmpeg is on PATH, and nothing written for a bad series.
#include "cli_series_fixture.h"
#include "vtk_files.h"

#include <ivis/core/content_hash.h>
#include <ivis/core/image_io.h>
#include <ivis/core/surface_series.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

namespace ivis::app {
namespace {

/// A closed tetrahedron (other geometry than the artery) as an ASCII .vtp, with a point array @a array.
std::string tetrahedron(const std::string& array)
{
    test::VtkDataSet d;
    d.points = {33, 31, 41, 34, 31, 41, 33, 32, 41, 33, 31, 42};  // inside the artery's frame (its steps' units)
    d.polys.connectivity = {0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2};
    d.polys.offsets = {3, 6, 9, 12};
    d.pointData = {{array, "Float32", 1, {0.3, 0.4, 0.5, 0.6}}};
    test::VtkXmlLayout layout;
    layout.format = test::VtkXmlLayout::Ascii;
    return test::vtpText(d, layout);
}

/// A ParaView collection of @a files (absolute paths), timesteps 0, 1, ...
std::string collection(const std::vector<std::string>& files)
{
    std::string text = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
    for (std::size_t k = 0; k < files.size(); ++k)
        text += "<DataSet timestep=\"" + std::to_string(k) + "\" file=\"" + files[k] + "\"/>\n";
    return text + "</Collection>\n</VTKFile>\n";
}

/// The finite range of the shown scalar over every step of the series.
std::pair<float, float> unionRange(const std::vector<std::string>& sources, const core::SurfaceLoadOptions& options)
{
    core::SurfaceSeries series(sources, options);
    float lo = INFINITY, hi = -INFINITY;
    for (std::size_t k = 0; k < series.steps().size(); ++k)
        for (const float v : series.load(k).values) {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    return {lo, hi};
}


// --measure measures every frame: one geometry seen from one camera shows the same surface in every
// frame, while each step's scalar has its own important part.
TEST_F(CliSeries, MeasureGivesEveryFrameItsMeasures)
{
    const CliResult result = runCli(renderSeries(quoted(pvd()), "--no-video --measure --method inversevis-wrap"));
    ASSERT_EQ(result.status, 0) << result.err;
    const nlohmann::json s = stats();
    const nlohmann::json& frames = s.at("frames");
    ASSERT_EQ(frames.size(), 5u);
    const nlohmann::json& first = frames[0].at("measures");
    EXPECT_GT(first.at("visibility").get<double>(), first.at("front_visibility").get<double>());
    for (const nlohmann::json& frame : frames) {
        const nlohmann::json& measures = frame.at("measures");
        EXPECT_EQ(measures.at("visibility"), first.at("visibility"));
        EXPECT_EQ(measures.at("coherence"), frame.at("coherence"));
        // null where the series' range leaves a step no important surface (it said 0% revealed)
        ASSERT_TRUE(measures.contains("reveal"));
        if (!measures.at("reveal").is_null()) {
            EXPECT_FALSE(measures.at("reveal").at("per_region").empty());
        }
    }
}

TEST_F(CliSeries, PvdRendersOneFramePerStepOnOneVolumeWithOneRange)
{
    const CliResult result = runCli(renderSeries(quoted(pvd()), "--no-video"));
    ASSERT_EQ(result.status, 0) << result.err;
    const std::string cache = cacheName("artery", arteryStep("0200"), "pressure");
    EXPECT_EQ(contents(mOutputs.path()),
              (std::vector<std::string>{cache, "f.png.camera.json", "f_0000.png", "f_0001.png", "f_0002.png",
                                        "f_0003.png", "f_0004.png", "s.json"}));
    // Every frame the same size: the picture and the widest step's colour-bar margin.
    const core::Image first = core::readPng(output("f_0000.png"));
    EXPECT_GT(first.width(), 48);
    for (int k = 1; k < 5; ++k) {
        const core::Image frame = core::readPng(output("f_000" + std::to_string(k) + ".png"));
        EXPECT_EQ(frame.width(), first.width());
        EXPECT_EQ(frame.height(), first.height());
    }

    const nlohmann::json s = stats();
    EXPECT_EQ(s.at("steps"), 5);
    EXPECT_EQ(s.at("volumes_loaded"), 1);
    const auto [lo, hi] = unionRange({pvd()}, {});
    const auto [firstLo, firstHi] = unionRange({arteryStep("0200")}, {});
    ASSERT_TRUE(lo < firstLo || hi > firstHi) << "the steps' ranges differ, so one shared range is observable";
    const nlohmann::json& frames = s.at("frames");
    ASSERT_EQ(frames.size(), 5u);
    for (std::size_t k = 0; k < 5; ++k) {
        EXPECT_EQ(frames[k].at("step"), k);
        EXPECT_EQ(frames[k].at("time"), 200.0 * double(k + 1));
        EXPECT_EQ(frames[k].at("volume"), k == 0 ? "built" : "kept") << k;
        EXPECT_EQ(frames[k].at("legend"), "pressure, t = " + std::to_string(200 * (k + 1)));
        EXPECT_EQ(frames[k].at("volume_cache"), output(cache));
        EXPECT_FLOAT_EQ(frames[k].at("range")[0].get<float>(), lo);
        EXPECT_FLOAT_EQ(frames[k].at("range")[1].get<float>(), hi);
    }
    EXPECT_NE(result.err.find("frame 5/5 (artery_t1000.vtp): volume kept"), std::string::npos) << result.err;
    const std::string note = "showing the point array 'pressure'";
    EXPECT_NE(result.err.find(note), std::string::npos) << result.err;
    EXPECT_EQ(result.err.find(note), result.err.rfind(note)) << "said once for the series: " << result.err;

    // Run again: the cache named by the geometry's hash is read, not rebuilt.
    ASSERT_EQ(runCli(renderSeries(quoted(pvd()), "--no-video")).status, 0);
    EXPECT_EQ(stats().at("frames")[0].at("volume"), "reused");
    EXPECT_EQ(contents(mOutputs.path()).size(), 8u);
}

TEST_F(CliSeries, SeveralFilesAreASeriesInTheOrderGiven)
{
    const CliResult result =
        runCli(renderSeries(quoted(arteryStep("0800")) + " " + quoted(arteryStep("0200")), "--no-video --scalar pressure_cell"));
    ASSERT_EQ(result.status, 0) << result.err;
    const nlohmann::json frames = stats().at("frames");
    ASSERT_EQ(frames.size(), 2u);
    EXPECT_EQ(frames[0].at("label"), "artery_t0800.vtp");
    EXPECT_EQ(frames[1].at("legend"), "pressure_cell, artery_t0200.vtp");
    EXPECT_EQ(frames[1].at("volume"), "kept");
    EXPECT_TRUE(std::filesystem::exists(output("f_0001.png")));
    EXPECT_FALSE(std::filesystem::exists(output("f_0002.png")));
}

TEST_F(CliSeries, EachGeometryGetsItsOwnVolumeAndCache)
{
    const std::string tet = input("tet.vtp");
    test::writeFile(tet, tetrahedron("pressure"));
    const std::string series = input("mixed.pvd");
    test::writeFile(series, collection({arteryStep("0200"), tet, arteryStep("0400"), arteryStep("0600")}));
    const CliResult result = runCli(renderSeries(quoted(series), "--no-video --scalar pressure"));
    ASSERT_EQ(result.status, 0) << result.err;
    const nlohmann::json frames = stats().at("frames");
    ASSERT_EQ(frames.size(), 4u);
    EXPECT_EQ(frames[0].at("volume"), "built");
    EXPECT_EQ(frames[1].at("volume"), "built");   // other geometry: rebuilt, not an error
    EXPECT_EQ(frames[2].at("volume"), "reused");  // the artery again: its cache from step 0
    EXPECT_EQ(frames[3].at("volume"), "kept");
    EXPECT_EQ(frames[1].at("legend"), "pressure, t = 1");
    EXPECT_EQ(stats().at("volumes_loaded"), 3);
    EXPECT_NE(frames[0].at("volume_cache"), frames[1].at("volume_cache"));
    EXPECT_EQ(frames[0].at("volume_cache"), frames[2].at("volume_cache"));
    int caches = 0;
    for (const std::string& name : contents(mOutputs.path())) caches += name.size() > 4 && name.substr(name.size() - 4) == ".vdb";
    EXPECT_EQ(caches, 2);
}

// `info` of a series counts the steps that carry each array: the tetrahedron has no cell array, so
// the artery's pressure_cell is in 2 of 3 steps, and the tetrahedron's pressure (0.3 to 0.6) lies
// inside the artery's range, which the series' range stays.
TEST_F(CliSeries, InfoCountsTheStepsThatCarryEachArray)
{
    const std::string tet = input("tet.vtp"), series = input("mixed.pvd");
    test::writeFile(tet, tetrahedron("pressure"));
    test::writeFile(series, collection({arteryStep("0200"), tet, arteryStep("0400")}));
    const CliResult json = runCli("info " + quoted(series) + " --json");
    ASSERT_EQ(json.status, 0) << json.err;
    const nlohmann::json arrays = nlohmann::json::parse(json.out).at("arrays");
    ASSERT_EQ(arrays.size(), 2u) << arrays.dump();
    EXPECT_EQ(arrays[0].at("name"), "pressure");
    EXPECT_EQ(arrays[0].at("steps"), 3);
    EXPECT_EQ(arrays[1].at("name"), "pressure_cell");
    EXPECT_EQ(arrays[1].at("steps"), 2);
    const CliResult text = runCli("info " + quoted(series));
    ASSERT_EQ(text.status, 0) << text.err;
    EXPECT_NE(text.out.find("(in 2 of 3 steps)"), std::string::npos) << text.out;
    // An array only a later step carries, shown by default there, is not the series' default: the
    // first step's is, which the series' pictures show (both were marked).
    test::writeFile(tet, tetrahedron("other"));
    const CliResult later = runCli("info " + quoted(series) + " --json");
    ASSERT_EQ(later.status, 0) << later.err;
    std::vector<std::string> shown;
    const nlohmann::json laterInfo = nlohmann::json::parse(later.out);
    for (const nlohmann::json& a : laterInfo.at("arrays"))
        if (a.at("shown_by_default").get<bool>()) shown.push_back(a.at("name"));
    EXPECT_EQ(shown, std::vector<std::string>{"pressure"});
    // A step that cannot be read is one line naming it, as every command says it.
    test::writeFile(tet, "not a vtp");
    expectBadInput(runCli("info " + quoted(series)), {tet + ":"});
}

/// (scalar value, PNG colour) of every unshaded indirect pixel of frame @a k of the render in @a folder.
std::vector<std::pair<float, std::array<int, 3>>> indirectColours(const std::string& folder, int k)
{
    const std::string stem = folder + "/f_000" + std::to_string(k);
    const core::Image png = core::readPng(stem + ".png");
    const std::vector<float> region = core::readExrChannel(stem + ".exr", "region");
    const std::vector<float> scalar = core::readExrChannel(stem + ".exr", "scalar");
    std::vector<std::pair<float, std::array<int, 3>>> out;
    for (int y = 0; y < png.height(); ++y)
        for (int x = 0; x < png.width(); ++x) {
            const std::size_t i = std::size_t(y) * png.width() + x;
            if (region[i] != 2.0f || std::isnan(scalar[i])) continue;
            const glm::vec4 c = png.at(x, y);
            out.push_back({scalar[i], {int(std::lround(c.r * 255)), int(std::lround(c.g * 255)), int(std::lround(c.b * 255))}});
        }
    std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    return out;
}

/// For each pixel of @a a, the pixel of @a b with the nearest value when within @a tolerance:
/// the number of such pairs and the largest colour difference (8-bit levels) between them.
std::pair<int, int> sameValueColourDifference(const std::vector<std::pair<float, std::array<int, 3>>>& a,
                                              const std::vector<std::pair<float, std::array<int, 3>>>& b,
                                              float tolerance)
{
    int pairs = 0, worst = 0;
    for (const auto& [value, colour] : a) {
        const auto it = std::lower_bound(b.begin(), b.end(), value, [](const auto& p, float v) { return p.first < v; });
        for (auto near : {it, it == b.begin() ? it : it - 1}) {
            if (near == b.end() || std::abs(near->first - value) > tolerance) continue;
            ++pairs;
            for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(near->second[c] - colour[c]));
            break;
        }
    }
    return {pairs, worst};
}

TEST_F(CliSeries, PatternOnTheArteryMapsOneValueToOneColourInEveryFrame)
{
    const std::string flat = "--scalar 'pressure_t*' --no-video --unshaded-indirect --no-outline --no-legend --exr " +
                             quoted(output("f.exr"));
    const CliResult result = runCli(renderSeries(quoted(artery()), flat, "160x160"));
    ASSERT_EQ(result.status, 0) << result.err;
    const nlohmann::json frames = stats().at("frames");
    ASSERT_EQ(frames.size(), 5u);
    EXPECT_EQ(frames[0].at("label"), "pressure_t200");
    EXPECT_EQ(frames[4].at("label"), "pressure_t1000");
    EXPECT_EQ(frames[4].at("legend"), "pressure_t1000");
    // t600 and t800 share values (-0.0095 .. 0.082; t200 and t1000 do not).
    const auto first = indirectColours(mOutputs.path(), 2), last = indirectColours(mOutputs.path(), 3);
    ASSERT_GT(first.size(), 500u);
    const auto [lo, hi] = unionRange({artery()}, [] {
        core::SurfaceLoadOptions o;
        o.read.scalarName = "pressure_t*";
        return o;
    }());
    const float tolerance = 1e-4f * (hi - lo);
    const auto [pairs, worst] = sameValueColourDifference(first, last, tolerance);
    EXPECT_GT(pairs, 50);
    EXPECT_LE(worst, 2) << "one value, one colour in both frames";

    // Each frame on its own range: the same value no longer has the same colour.
    ASSERT_EQ(runCli(renderSeries(quoted(artery()), flat + " --range-per-frame", "160x160")).status, 0);
    EXPECT_EQ(stats().at("range"), nullptr);
    EXPECT_NE(stats().at("frames")[2].at("range"), stats().at("frames")[3].at("range"));
    const auto [ownPairs, ownWorst] =
        sameValueColourDifference(indirectColours(mOutputs.path(), 2), indirectColours(mOutputs.path(), 3), tolerance);
    EXPECT_GT(ownPairs, 50);
    EXPECT_GT(ownWorst, 10);
    // Beside a view file (its range was every frame's), and on a log scale over steps with negative
    // values (the colour bars were sized on the raw ranges: "out of memory").
    const std::string view = quoted(output("v.json"));
    ASSERT_EQ(runCli(render(arteryStep("0200"), "--view-out " + view)).status, 0);
    ASSERT_EQ(runCli(renderSeries(quoted(artery()), flat + " --range-per-frame --view " + view, "160x160")).status, 0);
    EXPECT_NE(stats().at("frames")[2].at("range"), stats().at("frames")[3].at("range"));
    const CliResult logarithmic = runCli(renderSeries(quoted(pvd()), "--range-per-frame --log", "160x160"));
    ASSERT_EQ(logarithmic.status, 0) << logarithmic.err;
    EXPECT_GT(stats().at("frames")[0].at("range")[0].get<double>(), 0.0);
}

TEST_F(CliSeries, BadSeriesWriteNothing)
{
    const std::string missing = input("missing.pvd");
    test::writeFile(missing, collection({arteryStep("0200"), input("gone.vtp")}));
    expectRejected(render(missing), {missing + ": DataSet 1 names '" + input("gone.vtp") + "', which does not exist"});
    expectRejected(render(artery(), "--scalar 'velocity*'"),
                   {artery() + ": no array matches 'velocity*'; available: pressure_t200 (point)"});

    // A late step without the array, or unreadable: found before the first frame (or volume) is written.
    const std::string tet = input("tet.vtp");
    test::writeFile(tet, tetrahedron("wss"));
    const std::string lacking = input("lacking.pvd");
    test::writeFile(lacking, collection({arteryStep("0200"), arteryStep("0400"), tet}));
    expectRejected(render(lacking, "--scalar pressure"), {tet + ": no array 'pressure'; available: wss (point)"});
    // With no array chosen, the message says which array the first step showed by default.
    expectRejected(render(lacking), {tet + ": step 2 has no point array 'pressure', which the first step shows by "
                                           "default (--scalar chooses one every step has); available: wss (point)"});
    const std::string broken = input("broken.vtp");
    test::writeFile(broken, "<VTKFile type=\"PolyData\"><PolyData><Piece NumberOfPoints=\"3\"");
    const std::string late = input("late.pvd");
    test::writeFile(late, collection({arteryStep("0200"), arteryStep("0400"), broken}));
    expectRejected(render(late), {broken + ": not valid XML"});
    expectRejected("render " + quoted(arteryStep("0200")) + " " + quoted(pvd()) + " -o " + quoted(output("x.png")),
                   {pvd() + ": a .pvd is a series by itself"});

    // Series options on one mesh, or with --range.
    expectRejected(render(arteryStep("0200"), "--range-per-frame"),
                   {"--range-per-frame: applies to a time series"});
    expectRejected(render(arteryStep("0200"), "--fps 3"), {"--fps: applies to a time series"});
    // Said first: "give --view, --camera or --fov" came before it.
    expectRejected(render(arteryStep("0200"), "--frames 0:1"), {"--frames: applies to a time series"});
    expectRejected(render(pvd(), "--range-per-frame --range 0 1"), {"excludes"});
    // A view file holds one range: with each frame's own it held [0, 1], which no frame had.
    expectRejected(render(pvd(), "--range-per-frame --view-out " + quoted(output("v.json"))),
                   {"--view-out excludes --range-per-frame"});
    // One mesh's values for every step (each frame showed them alike).
    const std::string values = input("values.txt");
    test::writeFile(values, "1\n");
    expectRejected(render(pvd(), "--scalar-file " + quoted(values)), {values + ": --scalar-file gives one mesh's values"});
}

TEST_F(CliSeries, OptimizeFindsOneViewForTheWholeSeries)
{
    const std::string common = " --energy scalar --opt-res 24 --steps 2 --res 32x32 --volume-res 48 --no-video -o " +
                               quoted(output("best.png")) + " --json " + quoted(output("best.json"));
    // A series whose geometry changes has no one energy to sum: rejected before anything is written.
    const std::string tet = input("tet.vtp");
    test::writeFile(tet, tetrahedron("pressure"));
    const std::string mixed = input("mixed.pvd");
    test::writeFile(mixed, collection({arteryStep("0200"), tet}));
    expectRejected("optimize " + quoted(mixed) + " --scalar pressure" + common,
                   {tet + ": step 1 (tet.vtp) has other geometry or values than the first step"});
    // With no array chosen, only why (the default array's note came first).
    expectRejected("optimize " + quoted(mixed) + common,
                   {tet + ": step 1 (tet.vtp) has other geometry or values than the first step"});
    expectRejected("optimize " + quoted(artery()) + " --scalar pressure_t200" + common,
                   {"--no-video: applies to a time series"});

    const CliResult result = runCli("optimize " + quoted(artery()) + " --scalar 'pressure_t*'" + common);
    ASSERT_EQ(result.status, 0) << result.err;
    const nlohmann::json json = nlohmann::json::parse(test::readFile(output("best.json")));
    const nlohmann::json& series = json.at("series");
    ASSERT_EQ(series.at("frames").size(), 5u);
    EXPECT_EQ(series.at("volumes_loaded"), 1);
    // Every frame is the best view, with its parameters.
    EXPECT_DOUBLE_EQ(series.at("theta").get<double>(), json.at("theta").get<double>());
    EXPECT_DOUBLE_EQ(series.at("fov_y_deg").get<double>(), json.at("fov_y_deg").get<double>());
    for (const char* key : {"wrap_speed", "stable_shift"})  // the default method, its rule as the readable rule chose it
        EXPECT_EQ(series.at(key), json.at("params").at(key)) << key;
    for (int k = 0; k < 5; ++k) EXPECT_TRUE(std::filesystem::exists(output("best_000" + std::to_string(k) + ".png")));
    EXPECT_FALSE(std::filesystem::exists(output("best.png")));
}

TEST_F(CliSeries, CtrlCOrABatchSystemsStopAfterSomeFramesLeavesNoFrame)
{
    // SIGTERM is what Slurm sends at a job's time limit, and `timeout`; it left the frames' temporaries.
    for (const auto& [signal, status] : {std::pair{SIGINT, 130}, std::pair{SIGTERM, 143}}) {
        const test::Child child = test::startCli(renderSeries(quoted(pvd()), "--no-video", "1600x1600"));
        // Wait until two frames are done (and held back under temporary names), then stop it. The
        // wait is generous: a sanitizer build renders a frame in about 30 s.
        const auto start = std::chrono::steady_clock::now();
        while (test::readFile(child.err).find("frame 2/5") == std::string::npos &&
               std::chrono::steady_clock::now() - start < std::chrono::seconds(300))
            usleep(20000);
        ASSERT_NE(test::readFile(child.err).find("frame 2/5"), std::string::npos) << test::readFile(child.err);
        kill(child.pid, signal);
        const CliResult result = test::waitCli(child);
        ASSERT_EQ(result.status, status) << result.err;
        // The volume cache is a cache; of the outputs, nothing.
        for (const std::string& name : contents(mOutputs.path()))
            EXPECT_EQ(name.substr(name.size() - 4), ".vdb") << name << " left behind after signal " << signal;
    }
}

}  // namespace
}  // namespace ivis::app
