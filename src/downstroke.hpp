// SPDX-License-Identifier: MIT
// The whole public C++ API of the core in one include, as Box2D's box2d.h
// is: #include <downstroke/downstroke.hpp>. Each header also stands alone
// (<downstroke/frame.hpp>, <downstroke/tilemap/tilemap.hpp>) for a program
// that wants one concern; docs/cpp.org says what each holds.
#pragma once
#include "body.hpp"
#include "cell_shape.hpp"
#include "constants.hpp"
#include "contacts.hpp"
#include "ease.hpp"
#include "frame.hpp"
#include "frame_options.hpp"
#include "ground.hpp"
#include "groups.hpp"
#include "number.hpp"
#include "settle.hpp"
#include "shared_cells.hpp"
#include "state_hash.hpp"
#include "steps.hpp"
#include "tile_grid.hpp"
#include "tiles.hpp"
#include "tween.hpp"
#include "tilemap/map_bounds.hpp"
#include "tilemap/tilemap.hpp"
