// SPDX-License-Identifier: MIT
// downstroke-bench map-load: how long ds::load_tilemap takes per Tiled
// format and layer encoding (map_loads.cpp).
#pragma once

namespace bench {

int map_load_main(int argc, char** argv);

}  // namespace bench
