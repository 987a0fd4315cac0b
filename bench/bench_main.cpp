// inversevis-bench: performance of the engine, each figure a ratio against a reference measured
// in the same run.
#include "benchmarks.h"

#include <ivis/core/errors.h>
#include <ivis/core/log.h>

#include <iostream>
#include <vector>

int main(int argc, char** argv)
{
    CLI::App app{"inversevis-bench: timings against same-run references", "inversevis-bench"};
    app.require_subcommand(1);
    const std::vector<ivis::bench::Benchmark> benchmarks = {
        ivis::bench::addSdfBenchmark(app), ivis::bench::addRenderBenchmark(app), ivis::bench::addReadBenchmark(app)};
    try {
        app.parse(argc, argv);
        ivis::core::setLogLevel(ivis::core::LogLevel::Warning);
        for (const auto& benchmark : benchmarks)
            if (benchmark.parser->parsed()) benchmark.run();
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return app.exit(e);
        std::cerr << "inversevis-bench: error: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "inversevis-bench: error: " << e.what() << "\n";
        return 2;
    }
    return 0;
}
