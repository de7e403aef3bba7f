// SPDX-License-Identifier: MIT
// downstroke-bench tile-edit: what one tile edit costs (tile_edits.cpp says
// what is measured).
#pragma once
namespace bench {
// argv[1] is "tile-edit".
int tile_edit_main(int argc, char** argv);
}  // namespace bench
