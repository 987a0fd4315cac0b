// Time series: the steps of a .pvd, of a list of files and of a --scalar pattern on one file, and
// each step's surface as loadSurface loads it.
#include <ivis/core/errors.h>
#include <ivis/core/log.h>
#include <ivis/core/surface_series.h>

#include "test_support.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace ivis::core {
namespace {

using test::sharedMesh;

std::string artery() { return sharedMesh("vampy_artery_cfd_pressure.ply"); }
std::string pvd() { return sharedMesh("vtk/artery_series/artery.pvd"); }

SurfaceLoadOptions scalar(const std::string& name)
{
    SurfaceLoadOptions options;
    options.read.scalarName = name;
    return options;
}

/// Expects @a note in @a err exactly once.
void expectSaidOnce(const std::string& err, const std::string& note)
{
    const std::size_t first = err.find(note);
    ASSERT_NE(first, std::string::npos) << err;
    EXPECT_EQ(err.find(note, first + 1), std::string::npos) << err;
}

/// The message of the InputError @a f throws, or a marker.
template <typename F>
std::string errorOf(F f)
{
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "<no error>";
}

TEST(SurfaceSeries, WhatMakesASeries)
{
    EXPECT_TRUE(isSeries({pvd()}, {}));
    EXPECT_TRUE(isSeries({"a.vtp", "b.vtp"}, {}));
    EXPECT_TRUE(isSeries({artery()}, scalar("pressure_t*")));
    EXPECT_FALSE(isSeries({artery()}, scalar("pressure_t200")));
    EXPECT_FALSE(isSeries({"scene:sphere"}, {}));
}

TEST(SurfaceSeries, PvdStepsAreItsFilesInTimeOrderEachAsThePlyStep)
{
    SurfaceSeries series({pvd()}, {});
    ASSERT_EQ(series.steps().size(), 5u);
    EXPECT_EQ(series.source(), pvd());
    EXPECT_TRUE(series.timed());
    const std::vector<std::string> times = {"200", "400", "600", "800", "1000"};
    for (std::size_t k = 0; k < 5; ++k) {
        const SeriesStep& step = series.steps()[k];
        EXPECT_EQ(step.time, std::stod(times[k]));
        EXPECT_EQ(step.label, "artery_t" + std::string(4 - times[k].size(), '0') + times[k] + ".vtp");
        // With no --scalar, every step shows the array the first one shows by default.
        const SurfaceField field = series.load(k);
        EXPECT_EQ(field.name, "pressure");
        // The folder's README: each .vtp is the PLY with its pressure_tNNN values bit for bit.
        const SurfaceField ply = loadSurface(artery(), scalar("pressure_t" + times[k]));
        EXPECT_EQ(field.values, ply.values) << step.label;
        EXPECT_EQ(field.mesh.positions, ply.mesh.positions) << step.label;
    }
}

TEST(SurfaceSeries, APvdWithoutTimestepsIsNotTimed)
{
    test::TempDir dir;
    const std::string step = sharedMesh("vtk/artery_series/artery_t0400.vtp");
    test::writeFile(dir.file("s.pvd"), "<VTKFile type=\"Collection\"><Collection><DataSet file=\"" + step +
                                           "\"/><DataSet file=\"" + step + "\"/></Collection></VTKFile>");
    const SurfaceSeries series({dir.file("s.pvd")}, {});
    EXPECT_FALSE(series.timed());  // its steps are named by their files, not "t = 0"
    ASSERT_EQ(series.steps().size(), 2u);
    EXPECT_EQ(series.steps()[1].time, 1.0);
}

TEST(SurfaceSeries, TheDefaultArrayIsSaidOnce)
{
    // optimize loaded the first step twice where the log was heard (its importance, then its
    // frame): the note came twice. A load under a silenced log (the series' survey) does not count.
    SurfaceSeries series({pvd()}, {});
    {
        const ScopedLogLevel silent(LogLevel::Silent);
        EXPECT_EQ(series.load(0).name, "pressure");
    }
    testing::internal::CaptureStderr();
    for (std::size_t k : {0, 0, 1}) EXPECT_EQ(series.load(k).name, "pressure");
    expectSaidOnce(testing::internal::GetCapturedStderr(), "showing the point array 'pressure'");
}

TEST(SurfaceSeries, APatternFileIsReadOnceAndItsNotesSaidOnce)
{
    // A pattern's file was loaded once, by the survey under a silenced log: its notes were never
    // said. Then it was read again to say them; it is read once, when the series is made.
    test::TempDir dir;
    const std::string ply = dir.file("two.ply");
    test::writeFile(ply, "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                         "property float z\nproperty float p_t1\nproperty float p_t2\nelement face 2\n"
                         "property list uchar int vertex_indices\nend_header\n0 0 0 1 2\n1 0 0 1 2\n0 1 0 1 2\n"
                         "0 0 1 1 2\n3 0 1 2\n3 0 0 3\n");
    SurfaceSeries series({ply}, scalar("p_t*"));
    std::filesystem::remove(ply);
    {
        const ScopedLogLevel silent(LogLevel::Silent);
        EXPECT_EQ(series.load(0).values, std::vector<float>(3, 1.0f));  // point 3 only in the dropped triangle
    }
    testing::internal::CaptureStderr();
    EXPECT_EQ(series.load(1).values, std::vector<float>(3, 2.0f));
    EXPECT_EQ(series.load(0).values, std::vector<float>(3, 1.0f));
    const std::string said = testing::internal::GetCapturedStderr();
    expectSaidOnce(said, "two.ply: dropped 1 degenerate triangles");
    expectSaidOnce(said, "two.ply: left out 1 point that no triangle uses");
}

TEST(SurfaceSeries, PatternStepsAreTheMatchingArraysOfOneFile)
{
    SurfaceSeries series({artery()}, scalar("pressure_t*"));
    ASSERT_EQ(series.steps().size(), 5u);
    EXPECT_FALSE(series.timed());
    const std::vector<std::string> names = {"pressure_t200", "pressure_t400", "pressure_t600", "pressure_t800",
                                            "pressure_t1000"};
    for (std::size_t k = 0; k < 5; ++k) {
        const SeriesStep& step = series.steps()[k];
        EXPECT_EQ(step.label, names[k]);
        EXPECT_EQ(step.array, names[k]);
        EXPECT_EQ(step.time, double(k));
        const SurfaceField field = series.load(k);
        EXPECT_EQ(field.name, names[k]);
        EXPECT_EQ(field.values, loadSurface(artery(), scalar(names[k])).values);
    }
    EXPECT_NE(series.load(0).values, series.load(4).values);
}

TEST(SurfaceSeries, ListStepsAreTheFilesInTheOrderGiven)
{
    const std::string a = sharedMesh("vtk/artery_series/artery_t0800.vtp");
    const std::string b = sharedMesh("vtk/artery_series/artery_t0200.vtp");
    SurfaceSeries series({a, b}, scalar("pressure_cell"));
    ASSERT_EQ(series.steps().size(), 2u);
    EXPECT_EQ(series.steps()[0].label, "artery_t0800.vtp");
    EXPECT_EQ(series.steps()[1].time, 1.0);
    EXPECT_EQ(series.load(1).values, loadSurface(b, scalar("pressure_cell")).values);
    EXPECT_EQ(series.load(1).valuesOn, Association::Cell);
}

/// An OBJ of the unit cube [0, 1]^3 scaled by @a scale and moved by @a shift.
std::string cubeObj(double scale, double shift)
{
    std::string text;
    for (int v = 0; v < 8; ++v)
        text += "v " + std::to_string(shift + scale * (v & 1)) + " " + std::to_string(scale * ((v >> 1) & 1)) + " " +
                std::to_string(scale * ((v >> 2) & 1)) + "\n";
    return text + "f 1 3 2\nf 2 3 4\nf 5 6 7\nf 6 8 7\nf 1 2 5\nf 2 6 5\nf 3 7 4\nf 4 7 8\nf 1 5 3\nf 3 5 7\n"
                  "f 2 4 6\nf 4 8 6\n";
}

TEST(SurfaceSeries, EveryStepIsInTheFirstStepsFrameSoThatMovingGeometryMoves)
{
    test::TempDir dir;
    test::writeFile(dir.file("a.obj"), cubeObj(1.0, 0.0));
    test::writeFile(dir.file("moved.obj"), cubeObj(1.0, 0.25));
    test::writeFile(dir.file("swollen.obj"), cubeObj(1.2, 0.0));
    test::writeFile(dir.file("far.obj"), cubeObj(1.0, 5.0));
    SurfaceSeries series({dir.file("a.obj"), dir.file("moved.obj"), dir.file("swollen.obj"), dir.file("far.obj")}, {});
    const SurfaceField first = series.load(0), moved = series.load(1), swollen = series.load(2);
    // The first step as a mesh alone; the others in its frame: one transform, the move and the swelling kept.
    EXPECT_EQ(first.mesh.positions, loadSurface(dir.file("a.obj")).mesh.positions);
    EXPECT_EQ(moved.normalization.center, first.normalization.center);
    EXPECT_EQ(moved.normalization.scale, first.normalization.scale);
    const float half = float(first.normalization.scale);  // normalised units per mesh unit
    for (std::size_t v = 0; v < 8; ++v) {
        EXPECT_NEAR(moved.mesh.positions[v].x - first.mesh.positions[v].x, 0.25f * half, 1e-6f) << v;
        EXPECT_NEAR(swollen.mesh.positions[v].y + 1.0f, 1.2f * (first.mesh.positions[v].y + 1.0f), 1e-5f) << v;
    }
    // A step beyond the frame's room is refused, naming its file.
    const std::string message = errorOf([&] { series.load(3); });
    EXPECT_NE(message.find(dir.file("far.obj") + ": its geometry reaches 11 of the first step's half size"),
              std::string::npos) << message;
}

TEST(SurfaceSeries, AChosenScalarIsWhatEveryLaterStepShows)
{
    // The viewer's "colour by" on a series: another array for every step, then the opened one back.
    SurfaceSeries series({pvd()}, {});
    EXPECT_EQ(series.load(2).name, "pressure");
    series.chooseScalar(scalar("pressure_cell"));
    for (std::size_t k = 0; k < 5; ++k) {
        const SurfaceField field = series.load(k);
        const SurfaceField direct = loadSurface(series.steps()[k].path, scalar("pressure_cell"));
        EXPECT_EQ(field.name, "pressure_cell");
        EXPECT_EQ(field.valuesOn, Association::Cell);
        EXPECT_EQ(field.values, direct.values) << k;
    }
    SurfaceLoadOptions hotSpots;
    hotSpots.hotSpots = 2;
    series.chooseScalar(hotSpots);
    EXPECT_EQ(series.load(1).name, "hotspots");
    EXPECT_EQ(series.load(1).values, loadSurface(series.steps()[1].path, hotSpots).values);
    series.chooseScalar({});  // as opened: every step the first step's default array
    for (std::size_t k : {0, 4}) {
        const SurfaceField field = series.load(k);
        EXPECT_EQ(field.name, "pressure");
        EXPECT_EQ(field.values, loadSurface(series.steps()[k].path, scalar("pressure")).values);
    }
    // A pattern's steps are its arrays; a series of files takes no scalar file nor pattern.
    SurfaceSeries arrays({artery()}, scalar("pressure_t*"));
    EXPECT_NE(errorOf([&] { arrays.chooseScalar(scalar("pressure_t200")); }).find("the steps of a --scalar pattern"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { series.chooseScalar(scalar("pressure*")); }).find("a pattern picks the steps among"),
              std::string::npos);
    SurfaceLoadOptions file;
    file.read.scalarFile = "values.txt";
    EXPECT_NE(errorOf([&] { series.chooseScalar(file); }).find("--scalar-file gives one mesh's values"),
              std::string::npos);
    EXPECT_EQ(series.load(3).name, "pressure");  // a refused choice changes nothing
}

TEST(SurfaceSeries, BadSeriesAreRejectedNamingTheProblem)
{
    EXPECT_EQ(errorOf([] { SurfaceSeries({artery()}, scalar("velocity*")); }).rfind(
                  artery() + ": no array matches 'velocity*'; available: pressure_t200 (point)", 0),
              0u);
    EXPECT_NE(errorOf([] { SurfaceSeries({pvd()}, scalar("pressure*")); }).find("a pattern picks the steps among"),
              std::string::npos);
    EXPECT_NE(errorOf([] { SurfaceSeries({artery(), artery()}, scalar("p*")); }).find("a pattern picks the steps"),
              std::string::npos);
    EXPECT_EQ(errorOf([] { SurfaceSeries({artery(), pvd()}, {}); }),
              pvd() + ": a .pvd is a series by itself; give it alone, not among other files");
    // A step without the series' array fails when loaded, naming its file.
    SurfaceSeries series({pvd()}, scalar("wss"));
    EXPECT_EQ(errorOf([&] { series.load(3); }).rfind(series.steps()[3].path + ": no array 'wss'", 0), 0u);
    // One-array commands are told that a .pvd or a pattern is a series.
    EXPECT_NE(errorOf([] { loadSurface(pvd()); }).find("a time series of 5 steps; this command takes one step's file"),
              std::string::npos);
    EXPECT_NE(errorOf([] { loadSurface(artery(), scalar("p*")); }).find("is a pattern"), std::string::npos);
}

}  // namespace
}  // namespace ivis::core
