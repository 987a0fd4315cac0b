/// @file benchmarks.h
/// @brief Subcommands of inversevis-bench; each registers its options and returns its action.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace ivis::bench {

/// @brief A registered benchmark and the action to run when it was chosen.
struct Benchmark {
    CLI::App* parser = nullptr;
    std::function<void()> run;
};

/// @brief `inversevis-bench sdf MESH --res N --json`: full volume build vs OpenVDB's bare conversion.
Benchmark addSdfBenchmark(CLI::App& app);

/// @brief `inversevis-bench render MESH`: frame times and curved-ray steps/s vs a dense array.
Benchmark addRenderBenchmark(CLI::App& app);

/// @brief `inversevis-bench read`: a large compressed binary .vtp read vs the same mesh as binary PLY.
Benchmark addReadBenchmark(CLI::App& app);

}  // namespace ivis::bench
