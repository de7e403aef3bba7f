// SPDX-License-Identifier: MIT
// libFuzzer target for image headers (ds::render::read_image_header, issue
// 35): whatever the bytes, it returns a size that is positive and within
// its format's range, or false with a reason; it never reads past the
// input, loops, or crashes.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <string>

#include "render/image_header.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    ds::render::ImageHeader h;
    std::string why;
    if (ds::render::read_image_header(std::span<const uint8_t>(data, size), h, why)) {
        if (h.width <= 0 || h.height <= 0 || h.width > 0x7fffffff || h.height > 0x7fffffff) std::abort();
    } else if (why.empty()) {
        std::abort();  // every refusal says why
    }
    return 0;
}
