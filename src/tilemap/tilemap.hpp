// SPDX-License-Identifier: MIT
// A Tiled map in memory: tilesets, tile layers (raw gids, flip bits kept for
// drawing), object layers, and the solidity rules of semantics §7 that turn it
// into the TileGrid physics reads.
#pragma once
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "../shared_cells.hpp"
#include "../tile_grid.hpp"
#include "map_bounds.hpp"
#include "map_color.hpp"
#include "object_index.hpp"
#include "../export.hpp"

namespace ds {

// The four high bits of a gid: horizontal, vertical and diagonal flip, and
// hexagonal 120° rotation. The rest is the tile's global id.
constexpr uint32_t kFlipHorizontal = 0x80000000u;
constexpr uint32_t kFlipVertical = 0x40000000u;
constexpr uint32_t kFlipDiagonal = 0x20000000u;
constexpr uint32_t kRotateHex120 = 0x10000000u;
constexpr uint32_t kGidMask = 0x0FFFFFFFu;

// A Tiled custom property. type is Tiled's name: "string", "int", "float",
// "bool", "color", "file", "object", "class" or "list". A scalar keeps its
// value as written (TMX's text, or the JSON value's text); a class keeps its
// members and a list its items (whose names are empty) in `members`, in file
// order. property_type is the custom type's name (propertytype=): a class's,
// or an enum's for a string or int.
struct Property {
    std::string name;
    std::string type = "string";
    std::string value;
    std::string property_type;
    std::vector<Property> members;
};
using Properties = std::vector<Property>;

DOWNSTROKE_API const Property* find_property(const Properties& props, std::string_view name);
// "true"/"1" (any case) — Tiled writes bools as true/false.
DOWNSTROKE_API bool property_is_true(const Property& p);

// One frame of a tile's animation: show local tile `tile_id` for `duration_ms`.
struct AnimationFrame {
    uint32_t tile_id = 0;
    int duration_ms = 0;
};

// What an object is, as Tiled draws it. A tile object is one with a gid
// (object_kind in map_objects.hpp decides).
enum class ObjectShape : uint8_t { Rectangle, Ellipse, Capsule, Point, Polygon, Polyline, Text, Tile };

// The point of a tile object's picture its (x, y) names (Tiled's
// objectalignment). Unspecified: BottomLeft on an orthogonal map.
enum class ObjectAlignment : uint8_t {
    Unspecified, TopLeft, Top, TopRight, Left, Center, Right, BottomLeft, Bottom, BottomRight
};
enum class TileRenderSize : uint8_t { Tile, Grid };
enum class FillMode : uint8_t { Stretch, PreserveAspectFit };
enum class RenderOrder : uint8_t { RightDown, RightUp, LeftDown, LeftUp };

struct ObjectPoint {
    double x = 0, y = 0;  // px, relative to the object's x, y
};

// A text object's text and the attributes Tiled writes for it.
struct ObjectText {
    std::string text;
    std::string font_family = "sans-serif";
    int pixel_size = 16;
    bool wrap = false, bold = false, italic = false, underline = false, strikeout = false;
    bool kerning = true;
    std::string color = "#000000";  // as written: #RRGGBB or #AARRGGBB
    std::string halign = "left", valign = "top";
};

struct MapObject {
    int id = 0;
    std::string name, type;  // type= or class=
    double x = 0, y = 0, width = 0, height = 0, rotation = 0;  // rotation in degrees, clockwise
    uint32_t gid = 0;  // raw (flip bits kept), for tile objects
    bool visible = true;
    ObjectShape shape = ObjectShape::Rectangle;
    std::vector<ObjectPoint> points;  // a polygon's or polyline's
    ObjectText text;                  // a text object's
    // The template it was made from, resolved against the map's folder (empty
    // when none); its fields are already merged in (template, then instance).
    std::string template_path;
    Properties properties;
};

struct TileInfo {  // a tileset's <tile> that carries something
    uint32_t id = 0;  // local id within its tileset
    std::string type; // type= (Tiled ≤1.8) or class= (≥1.9)
    Properties properties;
    bool has_collision_shapes = false;  // a non-empty <objectgroup>
    // An image-collection tile's own picture, as written (relative to image_dir
    // of its tileset); empty in a single-image tileset.
    std::string image;
    int image_width = 0, image_height = 0;
    std::vector<AnimationFrame> animation;  // empty when the tile is still
    // The shapes of its <objectgroup> (templates merged in), in tile px.
    std::vector<MapObject> objects;
};

struct DOWNSTROKE_API Tileset {
    uint32_t firstgid = 1;
    std::string name;
    std::string source;  // the .tsx path as written, or empty when embedded
    int tile_width = 0, tile_height = 0;
    int tile_count = 0;  // 0 when the file does not say
    int columns = 0, spacing = 0, margin = 0;
    std::string image;   // as written, relative to the file that names it
    int image_width = 0, image_height = 0;
    // The folder image paths are relative to: the .tsx's, or the map's when
    // the tileset is embedded. Empty for maps made in memory. Loading a map
    // opens each of its images only to see that it can be read
    // (image_files.hpp); a renderer decodes it when it first draws a tile.
    std::string image_dir;
    std::vector<TileInfo> tiles;  // sorted by id
    std::string type;  // class= of the tileset itself
    Properties properties;  // the tileset's own
    int tile_offset_x = 0, tile_offset_y = 0;  // <tileoffset>, px
    // The image's colour key (<image trans=>): pixels of this colour are
    // clear. Not set when the file gives none.
    std::optional<MapColor> trans;
    // Where a tile object's (x, y) sits on its picture (objectalignment=);
    // Unspecified is bottom-left on an orthogonal map.
    ObjectAlignment object_alignment = ObjectAlignment::Unspecified;
    // Tiled 1.9: tiles drawn at their own size or at the map's grid size
    // (tilerendersize=), and how a picture fills a size not its own (fillmode=).
    TileRenderSize render_size = TileRenderSize::Tile;
    FillMode fill_mode = FillMode::Stretch;

    // An image collection: no single image, each tile brings its own. Its
    // tile ids may have gaps (Tiled keeps ids of deleted tiles unused).
    bool image_collection() const;
    // Whether local id names one of its tiles: any id when tile_count is
    // unknown (0), else one of `tiles` in an image collection and an id
    // below tile_count in an image atlas.
    bool has_tile(uint32_t local_id) const;

    const TileInfo* tile(uint32_t local_id) const;
    // Solid by metadata: a true solid/collision/collides property, or collision shapes.
    bool tile_solid(uint32_t local_id) const;
    // A one-way platform by metadata: a true one-way property (semantics §9).
    bool tile_one_way(uint32_t local_id) const;
};

enum class LayerSolidity : uint8_t {
    FromTiles,  // no solid/collision property: each tile's metadata decides
    All,        // property true: every non-empty cell is solid
    None,       // property false: this layer adds no solidity
};

struct DOWNSTROKE_API TileLayer {
    std::string name;
    int64_t origin_col = 0, origin_row = 0;  // map cell of cells[0]
    int width = 0, height = 0;
    // Row-major raw gids, 0 = empty; a copied layer shares them until one
    // of the two is edited.
    SharedCells<uint32_t> cells;
    Properties properties;
    LayerSolidity solidity = LayerSolidity::FromTiles;
    // As drawn: its own and every enclosing group's, multiplied (visible,
    // opacity) or summed (offsets, px).
    bool visible = true;
    double opacity = 1.0;
    double offset_x = 0, offset_y = 0;

    uint32_t raw_gid(int64_t col, int64_t row) const;  // 0 outside the layer
};

struct ObjectLayer {
    std::string name;
    Properties properties;
    std::vector<MapObject> objects;
    // Drawn by y (stable), as Tiled's default draworder "topdown" says;
    // false for draworder="index": in the file's order.
    bool top_down = true;
    // Its tile objects by area, for drawing (object_index.hpp): built by the
    // loader once the map is whole; a layer made by hand has none, and is
    // drawn by visiting every object.
    ObjectIndex index;
};

// Every layer as the file nests it, for renderers and level scripts; physics
// reads `layers`. A tile or object layer points into Tilemap::layers or
// Tilemap::object_layers by `index`; an image layer holds its picture; a
// group holds its children. visible, opacity and offsets are the layer's own
// (TileLayer holds them combined with its groups').
enum class LayerKind : uint8_t { Tile, Object, Image, Group };

struct LayerInfo {
    LayerKind kind = LayerKind::Tile;
    int id = 0;
    std::string name, type;  // type= is class=
    bool visible = true;
    double opacity = 1.0;
    double offset_x = 0, offset_y = 0;    // px
    double parallax_x = 1, parallax_y = 1;
    std::string tint_color;  // as written, empty when none
    std::optional<MapColor> tint;  // tint_color read
    Properties properties;
    size_t index = 0;  // Tile: into layers; Object: into object_layers
    std::string image;  // Image: as written, relative to the map's folder
    int image_width = 0, image_height = 0;
    std::optional<MapColor> image_trans;  // Image: its colour key
    bool repeat_x = false, repeat_y = false;
    std::vector<LayerInfo> children;  // Group
};

// What a gid, or a cell over all its layers, makes of the cell (semantics
// §7, §9, §12): kEmptyCell, kSolidCell, kOneWayCell, or kShapedCell with
// `shape` (one-way or not).
struct CellPart {
    uint8_t kind = kEmptyCell;
    CellShape shape;
};

// A shape given to a gid of a map made in memory (make_tilemap): a
// rectangle or a polygon in tile px, read as a tile's collision object is.
struct GidShape {
    uint32_t gid = 0;
    MapObject object;
};

struct DOWNSTROKE_API Tilemap {
    std::string path;  // empty for maps made in memory
    int width = 0, height = 0;  // in cells (the bounding box of all chunks when infinite)
    int tile_width = 0, tile_height = 0;
    bool infinite = false;
    Properties properties;
    std::vector<Tileset> tilesets;  // sorted by firstgid
    std::vector<TileLayer> layers;  // in file order, groups flattened
    std::vector<ObjectLayer> object_layers;
    std::vector<LayerInfo> layer_tree;  // every layer, groups nested
    std::string type;  // class= of the map
    std::string background_color;  // as written, empty when none
    std::optional<MapColor> background;  // background_color read
    // The point parallax layers line up at when it is the view's centre
    // (parallaxoriginx/y, Tiled 1.8), px.
    double parallax_origin_x = 0, parallax_origin_y = 0;
    // renderorder=: the order a tile layer's cells are drawn in, which shows
    // where tiles larger than a cell overlap.
    RenderOrder render_order = RenderOrder::RightDown;
    // Things the map does that Tiled allows but the loader had to interpret
    // (a gid beyond every tileset, loaded as an empty, non-solid cell; a
    // picture that cannot be opened). Each names the file and where in it:
    // the layer and the cell, the tileset or layer and the picture.
    std::vector<std::string> warnings;
    std::vector<uint32_t> extra_solid_gids;  // solid-gids: from the script
    std::vector<uint32_t> extra_one_way_gids;  // one-way-gids: from the script
    std::vector<GidShape> extra_shapes;  // shapes: from the script (maps made in memory)

    // The tileset a gid (flip bits ignored) belongs to: the largest firstgid ≤ gid.
    const Tileset* tileset_for(uint32_t gid) const;
    // Solid by its tileset's metadata or by extra_solid_gids.
    bool gid_solid(uint32_t gid) const;
    // Solid, wholly or in part (a solid shape), when any layer makes it so
    // (semantics §7, §12).
    bool cell_solid(int64_t col, int64_t row) const;
    // A one-way platform by its tileset's metadata or extra_one_way_gids
    // (solid wins, for a gid and for a cell whose layers disagree).
    bool gid_one_way(uint32_t gid) const;
    bool cell_one_way(int64_t col, int64_t row) const;
    // The physics grid over the bounding box of every layer.
    TileGrid solid_grid() const;
    // What the grid holds for a cell: kSolidCell, kOneWayCell, kShapedCell
    // or kEmptyCell.
    uint8_t cell_kind(int64_t col, int64_t row) const { return cell_part(col, row).kind; }
    // The same with the shape (semantics §12): over the cell's layers, a
    // whole solid cell wins, then a solid shape (two different ones: the
    // whole cell), then a whole one-way cell, then a one-way shape (two
    // different ones: a whole one-way cell).
    CellPart cell_part(int64_t col, int64_t row) const;
    // What one raw gid (flip bits turning its shape) makes of a cell in a
    // layer whose tiles decide (LayerSolidity::FromTiles).
    CellPart gid_part(uint32_t raw_gid) const;
    // Whether a gid (flip bits ignored) may stand in a layer: 0, any gid of a
    // map without tilesets (made in memory), else one of a tileset's tiles.
    bool gid_known(uint32_t gid) const;
    // Puts a raw gid into a cell of tile layer `layer`; std::out_of_range
    // outside the layer. The grid is the caller's to update (cell_kind):
    // TileGrid::set_cell in place, or on a copy.
    void set_gid(size_t layer, int64_t col, int64_t row, uint32_t gid);
};

// How many tiles an atlas image of image_w × image_h px holds, cut as
// Tiled cuts it (`columns` columns, 0: as many as fit; the tileset's margin
// and spacing): the local id of the first tile whose rectangle reaches past
// the image's right or bottom edge. A tileset whose tilecount is larger
// names tiles it has no picture for, which are drawn as missing tiles.
DOWNSTROKE_API uint32_t tiles_in_image(const Tileset& ts, int image_w, int image_h, int columns);

// Where a picture the map names is opened (the loader checks it there, the
// renderer decodes it there): a tileset's `image` (its own, or one of its
// collection tiles') joined to the tileset's folder (image_dir), and an
// image layer's joined to the map's folder; an absolute path, or one of a
// map or tileset made in memory, as written.
DOWNSTROKE_API std::string tileset_image_path(const Tileset& ts, const std::string& image);
DOWNSTROKE_API std::string layer_image_path(const Tilemap& map, const std::string& image);

// Edits a map and its physics grid in place: cell (col, row) of tile layer
// `layer` holds the raw gid `gid` (0 clears it), and the grid's cell becomes
// what the map now makes it (cell_kind), which gives the grid a new revision
// so that no settled body sleeps through the edit. `grid` is the map's
// solid_grid() (or a copy edited alike). Throws, with map and grid
// untouched: std::out_of_range for a cell outside the layer or the grid,
// std::invalid_argument for a gid of none of the map's tilesets (gid_known).
DOWNSTROKE_API void set_tile(Tilemap& map, TileGrid& grid, size_t layer, int64_t col, int64_t row, uint32_t gid);

// A malformed or unreadable map. what() names the file, and the line where
// the XML parser gave one.
class DOWNSTROKE_API MapError : public std::runtime_error {
public:
    MapError(const std::string& file, int line, const std::string& message);
    const std::string& file() const { return file_; }
    int line() const { return line_; }

private:
    std::string file_;
    int line_;
};

// How load_tilemap reads a map beyond its limits.
struct LoadOptions {
    std::vector<uint32_t> solid_gids;  // more solid gids (extra_solid_gids)
    MapLimits limits;
    // A gid beyond every tileset, a tileset that says nothing or a picture
    // that cannot be opened is an error (MapError) instead of a warning.
    bool strict = false;
    // A Tiled project file (.tiled-project), for the members a class
    // property leaves at its defaults; empty reads none and leaves them out.
    std::string project_path;
};

// Reads a .tmx file and the external .tsx tilesets it names (paths relative
// to the map). Only regular files are read (a tileset naming /dev/zero or a
// FIFO is an error), the map and its tilesets at most limits.max_bytes
// together, and the tile layers (chunks included) at most limits.max_cells
// cells together, checked from the attributes before anything is decoded.
// Throws MapError (semantics §7).
DOWNSTROKE_API Tilemap load_tilemap(const std::string& path, std::vector<uint32_t> solid_gids = {},
                     const MapLimits& limits = {});

// The same, with LoadOptions; the map may be TMX (XML) or JSON (.tmj),
// told apart by its content, and so may each tileset and template it names.
DOWNSTROKE_API Tilemap load_tilemap(const std::string& path, const LoadOptions& options);

// The same for a map already in memory (`text`, counted against max_bytes):
// `path` names it in messages and is where its .tsx paths are relative to.
// For fuzzing and for maps that do not come from a file.
DOWNSTROKE_API Tilemap parse_tilemap(std::string_view text, const std::string& path,
                      std::vector<uint32_t> solid_gids = {}, const MapLimits& limits = {});

// A map made in memory: width × height cells of tile_w × tile_h px, gids
// row-major (width*height of them), solid exactly where a gid is listed in
// solid_gids. Sizes are checked as a loaded map's (map_size_problem, with
// max_cells). Throws std::invalid_argument on a bad size or a size mismatch.
// `shapes` gives gids a collision shape as a tile's collision object would
// (semantics §12; flip bits on the cells' gids turn it); a shaped gid also in
// one_way_gids is a one-way shape.
DOWNSTROKE_API Tilemap make_tilemap(int width, int height, int tile_w, int tile_h, std::vector<uint32_t> gids,
                     std::vector<uint32_t> solid_gids, int64_t max_cells = kMaxMapCells,
                     std::vector<uint32_t> one_way_gids = {}, std::vector<GidShape> shapes = {});

}  // namespace ds
