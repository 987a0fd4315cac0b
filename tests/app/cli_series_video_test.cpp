// Time series as videos and as jobs: an MP4 when ffmpeg is on PATH (a fake and the real one), the
// frames alone otherwise, and frame-range jobs that give the frames of one render.
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
#include <vector>

#include <unistd.h>

namespace ivis::app {
namespace {

/// Writes a stand-in `ffmpeg` into @a folder that records its arguments in @a folder/args and
/// writes "video" to its last argument (or fails with @a status and a message).
void writeFakeFfmpeg(const std::string& folder, int status = 0)
{
    const std::string script = folder + "/ffmpeg";
    test::writeFile(script, "#!/bin/sh\necho \"$@\" > '" + folder + "/args'\n" +
                                (status == 0 ? std::string("for last; do :; done\necho video > \"$last\"\n")
                                             : "echo 'Unknown encoder' >&2\nexit " + std::to_string(status) + "\n"));
    std::filesystem::permissions(script, std::filesystem::perms::owner_all);
}

TEST_F(CliSeries, VideoWhenFfmpegIsOnPathAndFramesAlone)
{
    writeFakeFfmpeg(mInputs.path());
    {
        const ScopedPath path(mInputs.path());
        const CliResult result = runCli(renderSeries(quoted(pvd()), "--fps 7"));
        ASSERT_EQ(result.status, 0) << result.err;
    }
    EXPECT_EQ(test::readFile(output("f.mp4")), "video\n");
    EXPECT_EQ(stats().at("video"), output("f.mp4"));
    const std::string args = test::readFile(input("args"));
    EXPECT_NE(args.find("-framerate 7 -i " + output("f_%04d.png") + " -frames:v 5 "), std::string::npos) << args;

    // A slow series: a fraction of a frame per second reaches ffmpeg as given.
    {
        const ScopedPath path(mInputs.path());
        const CliResult result = runCli(renderSeries(quoted(pvd()), "--fps 0.5"));
        ASSERT_EQ(result.status, 0) << result.err;
    }
    EXPECT_NE(test::readFile(input("args")).find("-framerate 0.5 -i "), std::string::npos);

    // No ffmpeg: one line says so; the frames are written all the same.
    const test::TempDir empty;
    std::filesystem::remove(output("f.mp4"));
    {
        const ScopedPath path(empty.path());
        const CliResult result = runCli(renderSeries(quoted(pvd())));
        ASSERT_EQ(result.status, 0) << result.err;
        EXPECT_NE(result.err.find("ffmpeg is not on PATH: no video (the 5 frames are written)\n"), std::string::npos)
            << result.err;
    }
    EXPECT_FALSE(std::filesystem::exists(output("f.mp4")));
    EXPECT_EQ(stats().at("video"), nullptr);

    // ffmpeg fails: a warning with its last line, no video and no temporary left.
    writeFakeFfmpeg(mInputs.path(), 1);
    {
        const ScopedPath path(mInputs.path());
        const CliResult result = runCli(renderSeries(quoted(pvd())));
        ASSERT_EQ(result.status, 0) << result.err;
        EXPECT_NE(result.err.find("no video (ffmpeg exited with status 1: Unknown encoder)"), std::string::npos)
            << result.err;
    }
    for (const std::string& name : contents(mOutputs.path())) EXPECT_EQ(name.find(".tmp."), std::string::npos) << name;
    EXPECT_FALSE(std::filesystem::exists(output("f.mp4")));

    // An earlier run's video beside new frames: said to be stale (it was left without a word).
    test::writeFile(output("f.mp4"), "an older video");
    const CliResult noVideo = runCli(renderSeries(quoted(pvd()), "--no-video"));
    ASSERT_EQ(noVideo.status, 0) << noVideo.err;
    EXPECT_NE(noVideo.err.find(output("f.mp4") + ": an earlier run's video, not made again from these frames"),
              std::string::npos)
        << noVideo.err;
}

TEST_F(CliSeries, RealFfmpegWritesAnMp4OfTheSeriesFramesOnly)
{
    // The tool runs without ffmpeg; this test does not (scripts/setup.sh installs it).
    ASSERT_TRUE(std::filesystem::exists("/usr/bin/ffmpeg") && std::filesystem::exists("/usr/bin/ffprobe"))
        << "ffmpeg is missing: install it with scripts/setup.sh (Debian package ffmpeg)";
    ASSERT_EQ(runCli(renderSeries(quoted(pvd()), "--no-video")).status, 0);
    // A frame left by an older, longer series right after this one's last: not in the video.
    std::filesystem::copy_file(output("f_0000.png"), output("f_0005.png"));
    const CliResult result = runCli(renderSeries(quoted(pvd())));
    ASSERT_EQ(result.status, 0) << result.err;
    EXPECT_NE(result.err.find(output("f_0005.png") + ": an earlier run's frame past this series' 5 (left as it was)"),
              std::string::npos)
        << result.err;
    const std::string video = test::readFile(output("f.mp4"));
    ASSERT_GT(video.size(), 8u);
    EXPECT_EQ(video.substr(4, 4), "ftyp") << "an ISO base media (MP4) file";
    const test::TempDir probe;
    const std::string counted = probe.file("frames");
    ASSERT_EQ(std::system(("ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames "
                           "-of csv=p=0 " + quoted(output("f.mp4")) + " > " + quoted(counted)).c_str()),
              0);
    EXPECT_EQ(test::readFile(counted), "5\n");
}

// A long series rendered as jobs (--frames FIRST:LAST, one fixed camera) gives the frames, names
// and pixels of one render of every step, the readable rule included (chosen on step 0 by every
// job; at 48 x 48 pixels coherence 0.3 loosens it). The last job of equal parts may ask past the
// end: it renders up to the last step and says so.
TEST_F(CliSeries, FrameRangeJobsGiveTheFramesOfOneRender)
{
    const std::string common = "render " + quoted(pvd()) + " --volume-res 48 --res 48x48 --fov 60 --theta 70 --phi 30 "
                               "--no-video --min-coherence 0.3 --cache-dir " + quoted(output(""));
    const test::CliResult whole = test::runCli(common + " -o " + quoted(output("whole.png")));
    ASSERT_EQ(whole.status, 0) << whole.err;
    EXPECT_EQ(whole.err.find("--frames"), std::string::npos) << whole.err;  // not asked, not said
    for (const char* range : {"0:1", "2:99999999999999999999999"}) {
        const test::CliResult job = test::runCli(common + " --frames " + range + " -o " + quoted(output("job.png")) +
                                                 " --stats-json " + quoted(output("job.json")));
        ASSERT_EQ(job.status, 0) << job.err;
        EXPECT_EQ(job.err.find("the series has 5 steps; rendering 2:4") != std::string::npos,
                  std::string(range) != "0:1")
            << job.err;
        const nlohmann::json stats = nlohmann::json::parse(test::readFile(output("job.json")));
        EXPECT_GT(stats.at("readable_rule").at("value").get<double>(), 0.1001) << "loosened beyond the default: " << range;
        EXPECT_EQ(stats.at("readable_rule").at("value"), stats.at("stable_shift")) << range;
    }
    for (int k = 0; k < 5; ++k) {
        const std::string suffix = "_000" + std::to_string(k) + ".png";
        EXPECT_EQ(core::readPng(output("job" + suffix)).pixels(), core::readPng(output("whole" + suffix)).pixels()) << k;
    }
    for (const char* bad : {"3:1", "0:-1", "+1:2", "1: 2", "1", "2:"})
        expectBadInput(test::runCli(common + " --frames '" + bad + "' -o " + quoted(output("bad.png"))),
                       {"--frames '" + std::string(bad) + "': expected FIRST:LAST"});
    expectBadInput(test::runCli(common + " --frames 7:9 -o " + quoted(output("bad.png"))), {"the series has 5 steps"});
    expectBadInput(test::runCli("render " + quoted(pvd()) + " --frames 0:1 -o " + quoted(output("bad.png"))),
                   {"--frames: every job must use one camera"});
    expectBadInput(test::runCli(common + " --tear-map " + quoted(output("tears.png")) + " -o " + quoted(output("bad.png"))),
                   {"--tear-map: a series has one picture per step"});
    EXPECT_FALSE(std::filesystem::exists(output("tears.png")));
    expectBadInput(test::runCli(common + " --unseen-map " + quoted(output("unseen.png")) + " -o " + quoted(output("bad.png"))),
                   {"--unseen-map: a series has one picture per step"});
    EXPECT_FALSE(std::filesystem::exists(output("unseen.png")));
}

}  // namespace
}  // namespace ivis::app
