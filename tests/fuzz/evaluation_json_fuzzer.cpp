// libFuzzer target: the evaluate --json reader (merge's parts, evaluate --resume) on arbitrary bytes.
#include "fuzz_check.h"

#include "evaluation_report.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    ivis::fuzz::checkReader(data, size, [](std::string bytes) {
        ivis::app::detail::parseEvaluationJson("fuzz.evaluation.json", bytes);
    });
    return 0;
}
