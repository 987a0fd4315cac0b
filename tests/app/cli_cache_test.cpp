// The cache folder shared by every command: sdf builds into it, render reuses what sdf built and
// writes nothing beside its picture, `cache list` and `cache clear` see and remove the volumes.
#include "cli_fixture.h"

#include <nlohmann/json.hpp>

#include <filesystem>

namespace ivis::app {
namespace {

namespace fs = std::filesystem;

TEST_F(Cli, CommandsShareOneCacheFolderThatCacheListsAndClears)
{
    const test::CliResult built = test::runCli("sdf scene:sphere --volume-res 48 --json");
    ASSERT_EQ(built.status, 0) << built.err;
    const std::string volume = nlohmann::json::parse(built.out).at("output").get<std::string>();
    EXPECT_NE(volume.find("/inversevis/sphere."), std::string::npos) << volume;  // $XDG_CACHE_HOME/inversevis
    const auto writtenAt = fs::last_write_time(volume);

    const test::CliResult rendered =
        test::runCli("render scene:sphere --volume-res 48 --res 32x32 -o " + quoted(output("x.png")));
    ASSERT_EQ(rendered.status, 0) << rendered.err;
    EXPECT_EQ(contents(mOutputs.path()), (std::vector<std::string>{"x.png", "x.png.camera.json"}));
    EXPECT_EQ(fs::last_write_time(volume), writtenAt) << "render rebuilt the volume sdf had built";

    const test::CliResult listed = test::runCli("cache list");
    ASSERT_EQ(listed.status, 0) << listed.err;
    EXPECT_NE(listed.out.find(fs::path(volume).filename().string()), std::string::npos) << listed.out;
    EXPECT_NE(listed.out.find("in 1 file in " + fs::path(volume).parent_path().string()), std::string::npos) << listed.out;

    const test::CliResult cleared = test::runCli("cache clear");
    ASSERT_EQ(cleared.status, 0) << cleared.err;
    EXPECT_FALSE(fs::exists(volume));
    EXPECT_NE(test::runCli("cache list").out.find("in 0 files"), std::string::npos);

    // --cache-dir chooses another folder for every command, cache included.
    const test::CliResult elsewhere = test::runCli("sdf scene:sphere --volume-res 48 --cache-dir " + quoted(output("c")));
    ASSERT_EQ(elsewhere.status, 0) << elsewhere.err;
    EXPECT_NE(test::runCli("cache list --cache-dir " + quoted(output("c"))).out.find("in 1 file"), std::string::npos);
    expectBadInput(test::runCli("cache"), {"subcommand"});
}

}  // namespace
}  // namespace ivis::app
