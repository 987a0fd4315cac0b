// libFuzzer target: the font reader ($IVIS_FONT, else DejaVu Sans: core::Font, FreeType underneath)
// on arbitrary bytes (written to a temporary file, as FreeType opens a path): loaded, then a colour
// bar's text measured and drawn with it.
#include "fuzz_check.h"

#include <ivis/core/font.h>
#include <ivis/core/image.h>

#include <unistd.h>

#include <fstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    static const std::string path = "/tmp/ivis_font_fuzzer." + std::to_string(::getpid()) + ".ttf";
    std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), std::streamsize(size));
    ivis::fuzz::checkReader(data, size, [](const std::string&) {
        const ivis::core::Font font(path);
        const std::string text = "pressure_t200 0.7932 \xce\xbcm";
        font.measure(text, 13);
        ivis::core::Image image(64, 24);
        font.draw(image, 2, 18, text, glm::vec3(0.0f), 13);
    });
    return 0;
}
