/// @file fuzz_check.h
/// @brief What every reader must do with any bytes: return, or throw one InputError whose message
///        is a single line. Anything else (another exception, a crash, a sanitizer report, an
///        allocation beyond libFuzzer's limit) is a finding.
#pragma once

#include <ivis/core/errors.h>
#include <ivis/core/raw_mesh.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

namespace ivis::fuzz {

/// Runs @a read on the bytes [@a data, @a data + @a size) and checks the contract.
template <typename Reader>
void checkReader(const std::uint8_t* data, std::size_t size, Reader read)
{
    try {
        read(std::string(reinterpret_cast<const char*>(data), size));
    } catch (const InputError& e) {
        if (std::strchr(e.what(), '\n') != nullptr) std::abort();  // the message must stay one line
    }
}

}  // namespace ivis::fuzz
