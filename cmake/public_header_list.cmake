# SPDX-License-Identifier: MIT
# The public headers of the core, relative to src/: what docs/cpp.org
# documents, the umbrella that includes them all, and what they include
# (export.hpp, body_fields.def, which body.hpp expands into Body's members).
# cmake/install.cmake installs exactly these under include/downstroke/, and
# the test core.public-headers checks that they include nothing else.
set(DS_PUBLIC_HEADERS
  downstroke.hpp export.hpp
  body.hpp body_fields.def cell_shape.hpp constants.hpp contacts.hpp ease.hpp frame.hpp
  extent.hpp frame_options.hpp ground.hpp groups.hpp number.hpp settle.hpp shared_cells.hpp
  state_hash.hpp steps.hpp tile_grid.hpp tiles.hpp tween.hpp
  tilemap/map_bounds.hpp tilemap/map_color.hpp tilemap/object_index.hpp tilemap/tilemap.hpp)
