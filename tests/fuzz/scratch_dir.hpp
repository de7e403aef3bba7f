// SPDX-License-Identifier: MIT
// A private folder for the map harnesses: each input is written to a file
// there (the loader reads paths, not bytes), next to the fixed files it may
// name. On tmpfs when there is one, so a run's millions of writes stay in memory.
#pragma once
#include <string>
#include <string_view>

namespace ds::fuzz {

class ScratchDir {
public:
    explicit ScratchDir(std::string_view label);  // makes it; aborts if it cannot
    ~ScratchDir();                                 // removes it and all it holds
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;

    // Writes (replaces) the file at `relative` (folders made as needed); returns its full path.
    std::string write(std::string_view relative, std::string_view bytes) const;
    const std::string& path() const { return path_; }

private:
    std::string path_;
};

}  // namespace ds::fuzz
