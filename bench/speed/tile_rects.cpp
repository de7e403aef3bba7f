// SPDX-License-Identifier: MIT
#include "speed/tile_rects.hpp"

#include <utility>

namespace bench {

std::vector<Rect> tile_rects(const Scene& s) {
    std::vector<Rect> done, open;
    for (int r = 0; r <= s.rows; ++r) {
        std::vector<std::pair<int, int>> runs;
        if (r < s.rows)
            for (int c = 0; c < s.cols;) {
                if (!s.solid[static_cast<size_t>(r) * s.cols + c]) {
                    ++c;
                    continue;
                }
                int e = c;
                while (e + 1 < s.cols && s.solid[static_cast<size_t>(r) * s.cols + e + 1]) ++e;
                runs.push_back({c, e});
                c = e + 1;
            }
        std::vector<Rect> still;
        for (Rect& rect : open) {
            bool extended = false;
            for (auto& run : runs)
                if (run.first == rect.c0 && run.second == rect.c1) {
                    rect.r1 = r;
                    run = {-1, -1};
                    extended = true;
                    break;
                }
            (extended ? still : done).push_back(rect);
        }
        for (auto& run : runs)
            if (run.first >= 0) still.push_back({run.first, run.second, r, r});
        open = std::move(still);
    }
    return done;
}

}  // namespace bench
