// SPDX-License-Identifier: MIT
// downstroke-bench: how long one physics frame takes, per scene × N × path
// (speed, the default mode); how each demo's memory behaves over many frames
// (soak, soak/); run time against error (accuracy, accuracy/); how
// long the renderer takes to draw a frame (draw, draw/).
//
//   downstroke-bench [speed] [--scene S] [--n N] [--path P] [--frames F]
//                    [--warmup W] [--json FILE] [--org FILE]
//   downstroke-bench soak [--frames N] [--org FILE]
//   downstroke-bench accuracy [--quick] [--org FILE] [--png FILE]
//   downstroke-bench draw [--frames F] [--warmup W] [--rounds R] [--org FILE]
//   downstroke-bench query [--frames F] [--org FILE]
//   downstroke-bench tile-edit [--rounds R] [--org FILE]
//   downstroke-bench map-load [--rounds R] [--org FILE]
//   downstroke-bench slopes [--n N[,N…]] [--rounds R] [--frames F] [--org FILE]
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <stdexcept>
#include <string>

#include "accuracy/accuracy.hpp"
#include "draw/draw.hpp"
#include "map_load/map_loads.hpp"
#include "query/queries.hpp"
#include "slopes/slope_cost.hpp"
#include "soak/soak.hpp"
#include "speed/isolate.hpp"
#include "speed/options.hpp"
#include "speed/speed.hpp"
#include "tile_edit/tile_edits.hpp"

int main(int argc, char** argv) {
    try {
        if (argc > 1 && std::string(argv[1]) == "child") return bench::child_main(argc, argv);
        if (argc > 1 && std::string(argv[1]) == "accuracy") return bench::accuracy_main(argc, argv);
        if (argc > 1 && std::string(argv[1]) == "query") return bench::query_main(argc, argv);
        if (argc > 1 && std::string(argv[1]) == "tile-edit") return bench::tile_edit_main(argc, argv);
        if (argc > 1 && std::string(argv[1]) == "map-load") return bench::map_load_main(argc, argv);
        if (argc > 1 && std::string(argv[1]) == "slopes") return bench::slopes_main(argc, argv);
        if (argc > 1 && std::string(argv[1]) == "draw") {
#if DS_BENCH_HAVE_RENDER
            return bench::draw_main(argc, argv);
#else
            std::fputs("downstroke-bench: draw needs the renderer, and SDL2 was not found at configure time\n", stderr);
            return 2;
#endif
        }
        const bench::Options opts = bench::parse_options(argc, argv);
        if (opts.help) {
            std::fputs(bench::usage().c_str(), stdout);
            return EXIT_SUCCESS;
        }
        if (opts.mode == "soak") return bench::soak(opts);
        if (opts.mode != "speed") {
            std::fprintf(stderr, "downstroke-bench: unknown mode '%s' (modes: speed soak accuracy draw query tile-edit map-load slopes)\n", opts.mode.c_str());
            return 2;
        }
        return bench::speed(opts);
    } catch (const std::invalid_argument& e) {
        std::fprintf(stderr, "downstroke-bench: %s\n%s", e.what(), bench::usage().c_str());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "downstroke-bench: %s\n", e.what());
        return EXIT_FAILURE;
    }
}
