/// @file viewer_run.h
/// @brief Running `inversevis-view` in the tests (under xvfb-run) and comparing its pictures with
///        the CPU renderer's: what viewer_test.cpp and viewer_cpu_match_test.cpp share.
#pragma once

#include "test_support.h"

#include <ivis/core/image.h>
#include <ivis/core/surface_source.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace ivis::test {

/// Side of the pictures compareWithCpu compares.
inline constexpr int kSize = 512;

/// What a viewer run returned.
struct RunResult {
    int status = -1;
    std::string output;  ///< stdout and stderr
};

/// Writes mixed.pvd in @a dir: the artery's first step, a tetrahedron (other geometry, tet.vtp),
/// the artery's second step; returns its path.
std::string writeMixedSeries(const TempDir& dir);

/// Runs `inversevis-view` with @a arguments, under xvfb-run when @a display. Unless @a arguments
/// choose a --tracer, the shaders trace (on Xvfb's software GL the viewer would choose the CPU):
/// these tests compare the shaders with the CPU renderer.
RunResult runViewer(std::string arguments, bool display, const TempDir& dir);

/// True when xvfb-run is on PATH.
bool haveXvfbRun();

/// The fixture of the viewer's tests (built with the viewer alone): each runs it under xvfb-run,
/// whose absence fails the test.
class Viewer : public ::testing::Test {
protected:
    void SetUp() override
    {
        ASSERT_TRUE(haveXvfbRun()) << "xvfb-run is missing: install it with scripts/setup.sh (Debian package xvfb)";
    }
};

/// 8-bit sRGB level of a linear value, as writePng stores it.
int level(float linear);

/// Region of a --region-png grey level (0 background, 128 direct, 255 indirect), decoded by readPng.
int regionOfGrey(float linear);

/// How a viewer picture agrees with the CPU's.
struct Agreement {
    double regionAgreement = 0.0;   ///< fraction of pixels with the same region
    double indirectMeanDiff = 0.0;  ///< mean |difference| in 8-bit levels over channels of pixels both call indirect
    double directMeanDiff = 0.0;    ///< same over pixels both call direct
    std::size_t bothIndirect = 0;
    std::size_t cpuIndirect = 0, gpuIndirect = 0;
};

/// How a viewer screenshot (@a gpu, its --region-png @a gpuRegion) agrees with a CPU picture of the
/// same size (@a cpu, its region layer @a cpuRegion).
Agreement agreement(const core::Image& cpu, const std::vector<float>& cpuRegion, const core::Image& gpu,
                    const core::Image& gpuRegion);

/// Renders @a method on the CPU and in the viewer at 512x512 (theta 90, phi 0, framed) and compares.
/// @param volumeResolution volume resolution of both
/// @param viewerArguments further viewer arguments (with the scalar options matching @a load)
/// @param viewerOutput optional output: what the viewer printed
/// @param source the mesh of both
/// @param load how the CPU side loads it
/// @param shadeIndirect false: both draw the indirect part in the bar's flat colour (--unshaded-indirect)
Agreement compareWithCpu(const std::string& method, int volumeResolution = 200, const std::string& viewerArguments = "",
                         std::string* viewerOutput = nullptr, const std::string& source = "scene:vessel-tree",
                         const core::SurfaceLoadOptions& load = {}, bool shadeIndirect = true);

/// The parameters of the viewer's "inversevis-view: drawing {...}" line (the last one), or null.
nlohmann::json drawnParameters(const std::string& output);

/// The number after "readable rule: stable_shift " in @a output, or -1.
double readableShift(const std::string& output);

}  // namespace ivis::test
