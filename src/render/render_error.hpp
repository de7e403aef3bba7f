// SPDX-License-Identifier: MIT
// What the renderer throws: an image it cannot read, a window or audio device
// it cannot open. what() names the file or the device and SDL's reason.
#pragma once
#include <stdexcept>
#include <string>

namespace ds::render {

class RenderError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace ds::render
