// Atomic outputs: one file through a temporary, and a set of files that appears whole or not at all.
#include <ivis/core/atomic_file.h>
#include <ivis/core/errors.h>

#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <sys/stat.h>

namespace ivis::core {
namespace {

using test::TempDir;

std::vector<std::string> names(const TempDir& dir)
{
    std::vector<std::string> out;
    for (const auto& entry : std::filesystem::directory_iterator(dir.path()))
        out.push_back(entry.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
}

auto writing(const std::string& text)
{
    return [text](const std::string& path) { test::writeFile(path, text); };
}

TEST(AtomicFileSet, FilesAppearOnlyOnCommit)
{
    TempDir dir;
    {
        AtomicFileSet files;
        files.write(dir.file("a_0000.png"), writing("a"));
        files.write(dir.file("a_0001.png"), writing("b"));
        for (const std::string& name : names(dir)) EXPECT_NE(name.find(".tmp."), std::string::npos) << name;
        EXPECT_EQ(names(dir).size(), 2u);
        files.commit();
    }
    EXPECT_EQ(names(dir), (std::vector<std::string>{"a_0000.png", "a_0001.png"}));
    EXPECT_EQ(test::readFile(dir.file("a_0001.png")), "b");
}

TEST(AtomicFileSet, AnUncommittedOrFailedSetLeavesNothing)
{
    TempDir dir;
    {
        AtomicFileSet files;
        files.write(dir.file("a_0000.png"), writing("a"));
        EXPECT_THROW(files.write(dir.file("a_0001.png"),
                                 [](const std::string& path) {
                                     test::writeFile(path, "half");
                                     throw std::runtime_error("disk full");
                                 }),
                     InputError);
    }
    EXPECT_EQ(names(dir), std::vector<std::string>{});
}

// A writer that writes atomically itself (core::writePng into the set's temporary) fails with its
// own temporary's name: the set's error names the output once, and says the reason once.
TEST(AtomicFileSet, ANestedFailureIsReportedOnce)
{
    TempDir dir;
    AtomicFileSet files;
    try {
        files.write(dir.file("a.exr"), [](const std::string& temporary) {
            writeAtomically(temporary, [](const std::string&) { throw std::runtime_error("File too large."); });
        });
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), dir.file("a.exr") + ": cannot write (File too large.)");
    }
    EXPECT_EQ(names(dir), std::vector<std::string>{});
}

// A name near the 255-byte limit still gets a temporary beside it (its suffix used to push it
// past the limit), and a FIFO (as /dev/stdout may be) is written to, not replaced by a file.
TEST(WriteAtomically, ALongNameFitsAndAStreamIsWrittenAsItIs)
{
    TempDir dir;
    const std::string longName = std::string(250, 'n') + ".json";
    writeAtomically(dir.file(longName), writing("long"));
    EXPECT_EQ(names(dir), std::vector<std::string>{longName});
    AtomicFileSet files;
    files.write(dir.file(longName), writing("longer"));
    files.commit();
    EXPECT_EQ(test::readFile(dir.file(longName)), "longer");

    const std::string fifo = dir.file("pipe");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    std::string received;
    std::thread reader([&] { received = test::readFile(fifo); });
    writeAtomically(fifo, writing("through the pipe"));
    reader.join();
    EXPECT_EQ(received, "through the pipe");
    EXPECT_TRUE(std::filesystem::is_fifo(fifo)) << "replaced by a file";
    EXPECT_EQ(names(dir), (std::vector<std::string>{longName, "pipe"}));
}

}  // namespace
}  // namespace ivis::core
