#include <ivis/core/errors.h>
#include <ivis/core/pvd_reader.h>

#include "test_support.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace ivis::core {
namespace {

using test::TempDir;
using test::writeFile;

std::string collection(const std::string& datasets)
{
    return "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n" + datasets +
           "</Collection>\n</VTKFile>\n";
}

/// The one-line message readPvd throws, or a marker.
std::string pvdError(const std::string& path)
{
    try {
        readPvd(path);
    } catch (const InputError& e) {
        return e.what();
    }
    return "<no error>";
}

TEST(PvdReader, StepsComeInTimeOrderBesideTheCollection)
{
    TempDir dir;
    for (const char* name : {"a.vtp", "b.vtp", "c.vtp", "d.vtp"}) writeFile(dir.file(name), "");
    writeFile(dir.file("s.pvd"), collection("<DataSet timestep=\"2.5\" file=\"c.vtp\"/>\n"
                                            "<DataSet timestep=\"0.5\" part=\"0\" file=\"a.vtp\"/>\n"
                                            "<DataSet timestep=\"1e1\" file=\"d.vtp\"/>\n"
                                            "<DataSet timestep=\"2.5\" file=\"b.vtp\"/>\n"));
    const std::vector<TimeStep> steps = readPvd(dir.file("s.pvd"));
    ASSERT_EQ(steps.size(), 4u);
    EXPECT_EQ(steps[0].time, 0.5);
    EXPECT_EQ(steps[0].path, dir.file("a.vtp"));
    EXPECT_EQ(steps[1].path, dir.file("c.vtp"));  // equal times keep their order in the file
    EXPECT_EQ(steps[2].path, dir.file("b.vtp"));
    EXPECT_EQ(steps[3].time, 10.0);
}

TEST(PvdReader, WithoutTimestepsTheStepsAreTheFilesInOrder)
{
    // Every step was read at time 0 and its colour bar said "t = 0".
    TempDir dir;
    for (const char* name : {"a.vtp", "b.vtp"}) writeFile(dir.file(name), "");
    writeFile(dir.file("s.pvd"), collection("<DataSet file=\"b.vtp\"/>\n<DataSet file=\"a.vtp\"/>\n"));
    const std::vector<TimeStep> steps = readPvd(dir.file("s.pvd"));
    ASSERT_EQ(steps.size(), 2u);
    EXPECT_EQ(steps[0].path, dir.file("b.vtp"));
    EXPECT_EQ(steps[1].time, 1.0);
    EXPECT_FALSE(steps[0].timed);
    EXPECT_FALSE(steps[1].timed);
    writeFile(dir.file("s.pvd"), collection("<DataSet timestep=\"1\" file=\"b.vtp\"/>\n<DataSet file=\"a.vtp\"/>\n"));
    EXPECT_EQ(pvdError(dir.file("s.pvd")),
              dir.file("s.pvd") + ": DataSet 1 has no timestep, and DataSet 0 has one: give every DataSet its time, "
                                  "or none (the steps in the file's order)");
}

TEST(PvdReader, SharedArterySeries)
{
    const std::vector<TimeStep> steps = readPvd(test::sharedMesh("vtk/artery_series/artery.pvd"));
    ASSERT_EQ(steps.size(), 5u);
    for (std::size_t i = 0; i < 5; ++i) {
        EXPECT_EQ(steps[i].time, 200.0 * double(i + 1));
        EXPECT_NE(
            steps[i].path.find("artery_t" + std::string(i < 4 ? "0" : "") + std::to_string(200 * (i + 1)) + ".vtp"),
            std::string::npos)
            << steps[i].path;
    }
}

TEST(PvdReader, BadCollectionsNameTheFileAndTheProblem)
{
    TempDir dir;
    writeFile(dir.file("a.vtp"), "");
    std::filesystem::create_directory(dir.file("steps.vtp"));
    const struct {
        const char* text;
        const char* problem;
    } cases[] = {
        {"<VTKFile type=\"Collection\"><Collection><DataSet file=\"missing.vtp\"/></Collection></VTKFile>",
         "DataSet 0 names 'missing.vtp', which does not exist"},
        {"<VTKFile type=\"Collection\"><Collection><DataSet timestep=\"1\"/></Collection></VTKFile>",
         "DataSet 0 has no file"},
        {"<VTKFile type=\"Collection\"><Collection><DataSet file=\"steps.vtp\"/></Collection></VTKFile>",
         "DataSet 0 names 'steps.vtp', which is a folder"},
        {"<VTKFile type=\"Collection\"><Collection><DataSet timestep=\"one\" file=\"a.vtp\"/></Collection></VTKFile>",
         "DataSet 0 has the timestep 'one', which is not a finite number"},
        {"<VTKFile type=\"Collection\"><Collection><DataSet timestep=\"nan\" file=\"a.vtp\"/></Collection></VTKFile>",
         "DataSet 0 has the timestep 'nan', which is not a finite number"},
        {"<VTKFile type=\"Collection\"><Collection><DataSet timestep=\"-inf\" file=\"a.vtp\"/></Collection></VTKFile>",
         "DataSet 0 has the timestep '-inf', which is not a finite number"},
        {"<VTKFile type=\"Collection\"><Collection><DataSet part=\"1\" file=\"a.vtp\"/></Collection></VTKFile>",
         "DataSet 0 is part 1 of its time step"},
        {"<VTKFile type=\"Collection\"><Collection></Collection></VTKFile>", "the collection lists no DataSet"},
        {"<VTKFile type=\"Collection\"><Collection><DataSet file=\"s.pvd\"/></Collection></VTKFile>",
         "DataSet 0 names 's.pvd', which is not a mesh file ('.pvd')"},
        {"<VTKFile type=\"PolyData\"><PolyData/></VTKFile>", "not a ParaView collection"},
        {"<VTKFile type=\"Collection\"><Collection>", "not valid XML"},
    };
    for (const auto& c : cases) {
        writeFile(dir.file("s.pvd"), c.text);
        const std::string message = pvdError(dir.file("s.pvd"));
        EXPECT_EQ(message.rfind(dir.file("s.pvd") + ": ", 0), 0u) << message;
        EXPECT_NE(message.find(c.problem), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
    EXPECT_EQ(pvdError(dir.file("none.pvd")), dir.file("none.pvd") + ": file not found");
}

}  // namespace
}  // namespace ivis::core
