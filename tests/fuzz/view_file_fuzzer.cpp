// libFuzzer target: the view file reader (render --view, optimize --view, the viewer's --view) on
// arbitrary bytes.
#include "fuzz_check.h"

#include "view_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    ivis::fuzz::checkReader(data, size,
                            [](std::string bytes) { ivis::app::detail::parseViewFile("fuzz.view.json", bytes); });
    return 0;
}
