// The cache folder shared by every command: sdf builds into it, render reuses what sdf built and
// writes nothing beside its picture, `cache list` and `cache clear` see and remove the volumes.
#include "cli_fixture.h"

#include <nlohmann/json.hpp>

#include <filesystem>

#include <unistd.h>

namespace ivis::app {
namespace {

namespace fs = std::filesystem;

TEST_F(Cli, CommandsShareOneCacheFolderThatCacheListsAndClears)
{
    // The default cache folder is the test process's own (test::runCli): empty it of what earlier
    // tests of the same process left (all of ivis_tests run in one process counted their volumes).
    ASSERT_EQ(test::runCli("cache clear").status, 0);
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
    // sdf -o writes its own file: a cache folder beside it would be ignored (it was, without a word).
    expectBadInput(
        test::runCli("sdf scene:sphere --volume-res 48 -o " + quoted(output("v.vdb")) + " --cache-dir /missing"),
        {"--output excludes --cache-dir"});
    // A temporary whose writer still runs is kept (removing it made a render fail); one an
    // interrupted write left is removed.
    const std::string live = output("c") + "/sphere.res48.vdb.tmp." + std::to_string(::getpid()) + ".0";
    const std::string dead = output("c") + "/sphere.res48.vdb.tmp.2147483646.0";  // beyond any pid_max
    test::writeFile(live, "x");
    test::writeFile(dead, "x");
    const test::CliResult spared = test::runCli("cache clear --cache-dir " + quoted(output("c")));
    ASSERT_EQ(spared.status, 0) << spared.err;
    EXPECT_NE(spared.err.find("removed 2 cached volumes"), std::string::npos) << spared.err;
    EXPECT_NE(spared.err.find("kept 1 being written by a running command"), std::string::npos) << spared.err;
    EXPECT_TRUE(fs::exists(live));
    EXPECT_FALSE(fs::exists(dead));
    fs::remove(live);
    // An empty folder (an unset shell variable) is refused: it named the default folder, which clear would empty.
    for (const char* command : {"cache clear --cache-dir ''", "sdf scene:sphere --volume-res 48 --cache-dir ''"})
        expectBadInput(test::runCli(command), {"--cache-dir: empty"});
    // The commands of cache are named (CLI11 said only "A subcommand is required").
    for (const char* command : {"cache", "cache purge", "cache --cache-dir /tmp"})
        expectBadInput(test::runCli(command), {"cache needs one of its commands: list clear"});
    expectBadInput(test::runCli("cache --bogus list"), {"--bogus"});  // the option is what is wrong here
}

TEST_F(Cli, AnUnusableCacheFolderBuildsAndKeepsNothing)
{
    // A read-only home on a cluster: render refused to run ("cache folder ... cannot be created").
    const std::string file = input("plain-file");
    test::writeFile(file, "x");
    const std::string folder = file + "/cache";  // cannot be created, even by root
    const test::CliResult result =
        test::runCli("render scene:sphere --volume-res 48 --res 32x32 --cache-dir " + quoted(folder) + " -o " +
                     quoted(output("x.png")) + " --stats-json " + quoted(output("s.json")));
    ASSERT_EQ(result.status, 0) << result.err;
    EXPECT_NE(result.err.find("warning: cache folder " + folder + " cannot be created"), std::string::npos)
        << result.err;
    EXPECT_NE(result.err.find("the volume is built for this run and not kept"), std::string::npos) << result.err;
    EXPECT_EQ(contents(mOutputs.path()), (std::vector<std::string>{"s.json", "x.png", "x.png.camera.json"}));
    EXPECT_EQ(contents(mInputs.path()), std::vector<std::string>{"plain-file"});
    EXPECT_TRUE(nlohmann::json::parse(test::readFile(output("s.json"))).at("volume_cache").is_null());
    // sdf, whose output the cache is, still refuses.
    expectBadInput(test::runCli("sdf scene:sphere --volume-res 48 --cache-dir " + quoted(folder)),
                   {"cache folder " + folder + " cannot be created"});
}

TEST_F(Cli, CacheClearRemovesOnlyCaches)
{
    // `cache clear --cache-dir .` in a project folder removed every .vdb in it, the user's own too.
    const std::string folder = output("project");
    fs::create_directories(folder);
    const std::vector<std::string> caches = {"sphere.0123456789abcdef.res48.reach1.vdb",
                                             "sphere.0123456789abcdef.res48.vdb",  // the name before the reach
                                             "sphere.res48.vdb",                   // and before the hash
                                             // a temporary of a pid beyond any pid_max: no writer runs
                                             "sphere.0123456789abcdef.res48.reach0.6.vdb.tmp.2147483645.0",
                                             "sphere.0123456789abcdef.res48.reach1.band4.5.unsigned.vdb"};
    const std::vector<std::string> others = {"my_simulation.vdb", "results.vdb.tmp.1.0", "sphere.res48x.vdb",
                                             "notes.txt"};
    for (const std::string& name : caches) test::writeFile(folder + "/" + name, "v");
    for (const std::string& name : others) test::writeFile(folder + "/" + name, "v");
    const test::CliResult listed = test::runCli("cache list --cache-dir " + quoted(folder));
    ASSERT_EQ(listed.status, 0) << listed.err;
    EXPECT_NE(listed.out.find("in 5 files"), std::string::npos) << listed.out;
    ASSERT_EQ(test::runCli("cache clear --cache-dir " + quoted(folder)).status, 0);
    EXPECT_EQ(contents(folder), (std::vector<std::string>{"my_simulation.vdb", "notes.txt", "results.vdb.tmp.1.0",
                                                          "sphere.res48x.vdb"}));
    // Listing or clearing a folder creates none.
    const std::string missing = output("missing");
    for (const char* command : {"cache clear", "cache list"})
        expectBadInput(test::runCli(std::string(command) + " --cache-dir " + quoted(missing)),
                       {missing + ": --cache-dir names no folder"});
    EXPECT_FALSE(fs::exists(missing));
}

// Each far-field reach keeps a cache of its own: switching between the curved-ray methods (reach 1)
// and the others (0.6) reuses both volumes (one file was rebuilt at every switch).
TEST_F(Cli, MethodsOfTwoReachesKeepTwoCaches)
{
    auto volumeOf = [&](const std::string& method) {
        const test::CliResult result = test::runCli(render("scene:sphere", "--method " + method + " --stats-json " +
                                                                               quoted(output("s.json"))));
        EXPECT_EQ(result.status, 0) << result.err;
        return nlohmann::json::parse(test::readFile(output("s.json"))).at("volume_cache").get<std::string>();
    };
    const std::string front = volumeOf("front"), wrap = volumeOf("inversevis-wrap");
    EXPECT_NE(front.find(".res48.reach0.6.vdb"), std::string::npos) << front;
    EXPECT_NE(wrap.find(".res48.reach1.vdb"), std::string::npos) << wrap;
    const auto frontWritten = fs::last_write_time(front), wrapWritten = fs::last_write_time(wrap);
    EXPECT_EQ(volumeOf("front"), front);
    EXPECT_EQ(volumeOf("inversevis-wrap"), wrap);
    EXPECT_EQ(fs::last_write_time(front), frontWritten) << "rebuilt";
    EXPECT_EQ(fs::last_write_time(wrap), wrapWritten) << "rebuilt";
    // So does each band and distance sign asked for (they rebuilt the one file, "stale volume cache").
    EXPECT_NE(volumeOf("front --band 4.5").find(".res48.reach0.6.band4.5.vdb"), std::string::npos);
    EXPECT_NE(volumeOf("front --distance unsigned").find(".res48.reach0.6.unsigned.vdb"), std::string::npos);
    EXPECT_EQ(volumeOf("front"), front);
    EXPECT_EQ(fs::last_write_time(front), frontWritten) << "rebuilt";
}

}  // namespace
}  // namespace ivis::app
