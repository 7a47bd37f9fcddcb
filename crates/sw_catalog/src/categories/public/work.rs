//! Office, classroom, workshop and lab things from the public lists (Objects365, LVIS,
//! YCB, ShapeNet), and the small household odds and ends they name.

use super::{BLACK_C, BLACKS, BRIGHTS, FABRIC, Look, METAL, STEEL_C, TUMBLER, WHITE, WHITE_C, WOOD_C, WOODS, thing};

type Rgba = [f32; 4];

const OFFICE: &[&str] = &["office", "school", "stationery", "tabletop", "small", "graspable"];
const WORKSHOP: &[&str] = &["workshop", "garage", "hardware", "graspable"];
const HOME: &[&str] = &["home", "tabletop", "small", "graspable"];

const WOODS_T: &[Rgba] = WOODS;
const PAPER: &[Rgba] = &[[0.95, 0.93, 0.85, 1.0], [0.9, 0.88, 0.8, 1.0]];
const BARK: &[Rgba] = &[[0.4, 0.28, 0.16, 1.0], [0.35, 0.25, 0.15, 1.0]];
const TARP: &[Rgba] = &[[0.15, 0.3, 0.7, 1.0], [0.2, 0.45, 0.2, 1.0], [0.5, 0.5, 0.48, 1.0]];
const GREEN: &[Rgba] = &[[0.3, 0.55, 0.2, 1.0], [0.35, 0.6, 0.25, 1.0]];
const RED: &[Rgba] = &[[0.75, 0.1, 0.15, 1.0], [0.85, 0.15, 0.25, 1.0]];

// --- office and classroom -----------------------------------------------------------
// 30 cm (12-inch) ruler.
thing!(RULER: "ruler", "ruler", ["straightedge", "school ruler", "steel rule", "measuring ruler", "foot rule", "foot ruler", "12-inch ruler"], OFFICE, "a flat 30 cm ruler",
    ["measuring instrument", "stationery"], HandHeld @ OnSurface, true, [0.30, 0.035, 0.003], 1200.0,
    Look::Flat { body: &[[0.85, 0.88, 0.9, 1.0], [0.7, 0.55, 0.35, 1.0]], panel: BLACK_C });
// Whiteboard eraser: 15 × 5 × 3.5 cm.
thing!(BOARD_ERASER: "board_eraser", "board eraser", ["whiteboard eraser", "blackboard eraser", "chalkboard eraser", "board duster", "board rubber"],
    OFFICE, "a felt-faced eraser block for a whiteboard", ["eraser", "stationery"], HandHeld @ OnSurface, true, [0.15, 0.05, 0.035], 400.0,
    Look::Pack { body: BLACKS, band: [0.85, 0.85, 0.85, 1.0] });
// Desk calendar: 20 × 8 × 15 cm.
thing!(DESK_CALENDAR: "desk_calendar", "desk calendar", ["calendar", "table calendar", "flip calendar"], OFFICE,
    "a standing desk calendar", ["stationery"], Tabletop @ OnSurface, true, [0.20, 0.08, 0.15], 300.0, Look::Pack { body: PAPER, band: [0.8, 0.15, 0.1, 1.0] });
// Folded road map: 13 × 25 × 1 cm.
thing!(MAP: "map", "map", ["folded map", "road map", "street map"], OFFICE, "a folded paper map",
    ["document", "stationery"], Tabletop @ OnSurface, true, [0.13, 0.25, 0.01], 700.0, Look::Flat { body: PAPER, panel: [0.3, 0.55, 0.75, 1.0] });
// MP3 player: 6 × 1 × 10 cm, lying.
thing!(MP3_PLAYER: "media_player", "mp3 player", ["ipod", "music player", "portable music player"], &["home", "electronics", "tabletop", "small", "graspable"],
    "a small portable music player", ["electronics", "gadget"], Tabletop @ OnSurface, true, [0.10, 0.06, 0.01], 1000.0,
    Look::Flat { body: WHITE, panel: BLACK_C });
// Nine-hole peg test board (YCB 071): 15 × 15 × 5 cm.
thing!(PEG_BOARD: "peg_board", "peg board", ["nine hole peg test", "peg test", "pegboard puzzle"], &["lab", "toy", "tabletop", "small"],
    "a square board with nine holes and its pegs", ["toy", "test kit"], Toy @ OnSurface, true, [0.15, 0.15, 0.05], 600.0,
    Look::Flat { body: &[[0.85, 0.85, 0.85, 1.0]], panel: [0.2, 0.35, 0.7, 1.0] });

// --- workshop and hardware ----------------------------------------------------------
// M16 × 80 hex bolt (YCB 046_plastic_bolt is 9 cm).
thing!(BOLT: "bolt", "bolt", ["hex bolt", "machine bolt", "plastic bolt", "carriage bolt"], WORKSHOP, "a hexagon-headed threaded bolt",
    ["fastener", "hardware"], HandHeld @ OnSurface, true, [0.09, 0.025, 0.025], 3000.0,
    Look::Long { grip: 0.82, grip_w: 0.62, grip_h: 0.62, handle: METAL, head: STEEL_C });
// M24 hex nut (YCB 047_plastic_nut): 3.6 cm across flats, 2 cm thick.
thing!(HEX_NUT: "hex_nut", "hex nut", ["hexagon nut", "plastic nut", "threaded nut", "lock nut"], WORKSHOP, "a hexagonal threaded nut",
    ["fastener", "hardware"], HandHeld @ OnSurface, true, [0.036, 0.036, 0.02], 3000.0,
    Look::Turned { profile: &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], body: METAL, top: 1.0, cap_r: 1.0, cap: STEEL_C });
// A length of chain (YCB 059_chain): 50 cm laid out.
thing!(CHAIN: "chain", "chain", ["metal chain", "steel chain", "length of chain"], WORKSHOP, "a length of steel chain lying straight",
    ["hardware"], HandHeld @ OnSurface, true, [0.50, 0.03, 0.015], 2000.0,
    Look::Long { grip: 0.5, grip_w: 1.0, grip_h: 1.0, handle: METAL, head: STEEL_C });
// Petrol chainsaw with a 40 cm bar: 75 × 25 × 28 cm.
thing!(CHAINSAW: "chainsaw", "chainsaw", ["chain saw", "petrol chainsaw", "electric chainsaw"], &["workshop", "garden", "power_tool"],
    "a chainsaw with its engine and a long guide bar", ["power tool", "saw"], Tabletop @ OnSurface, true, [0.75, 0.25, 0.28], 120.0,
    Look::Long { grip: 0.55, grip_w: 0.15, grip_h: 0.3, handle: METAL, head: [0.95, 0.45, 0.1, 1.0] });
// A 60 cm length of 50 mm pipe.
thing!(PIPE: "pipe", "pipe", ["length of pipe", "plumbing pipe", "pvc pipe", "steel pipe", "copper pipe"], WORKSHOP,
    "a straight length of pipe", ["plumbing", "hardware"], HandHeld @ OnSurface, true, [0.60, 0.05, 0.05], 800.0,
    Look::Long { grip: 0.5, grip_w: 1.0, grip_h: 1.0, handle: &[[0.85, 0.85, 0.83, 1.0], [0.72, 0.45, 0.2, 1.0]], head: [0.8, 0.8, 0.78, 1.0] });
// Folded tarpaulin: 40 × 30 × 8 cm.
thing!(TARPAULIN: "tarpaulin", "tarpaulin", ["tarp", "folded tarp"], &["workshop", "garage", "textile"],
    "a folded plastic tarpaulin", ["sheet", "textile"], Textile @ OnSurface, true, [0.40, 0.30, 0.08], 150.0,
    Look::Flat { body: TARP, panel: [0.9, 0.9, 0.9, 1.0] });
// Firewood log: 40 cm, 12 cm across.
thing!(FIREWOOD_LOG: "firewood_log", "firewood log", ["log", "firewood", "log of wood", "wood log"], &["home", "fireplace", "garden"],
    "a split log of firewood", ["fuel", "wood"], Tabletop @ OnSurface, true, [0.40, 0.12, 0.12], 600.0,
    Look::Blob { body: BARK, accent: BLACK_C, stem: false });

// --- odds and ends ------------------------------------------------------------------
// Drum lampshade: 30 cm across, 22 cm tall.
thing!(LAMPSHADE: "lampshade", "lampshade", ["lamp shade", "light shade", "drum shade"], &["home", "decor", "lighting", "tabletop"],
    "a fabric drum lampshade", ["lamp part", "decoration"], Tabletop @ OnSurface, true, [0.30, 0.30, 0.22], 30.0,
    Look::Turned { profile: TUMBLER, body: FABRIC, top: 1.0, cap_r: 1.0, cap: WHITE_C });
// Canvas tote bag: 38 × 12 × 40 cm.
thing!(BAG: "bag", "bag", ["canvas bag", "cloth bag", "bag for life"], &["home", "bag", "graspable"], "a soft fabric bag with handles",
    ["container"], Container @ OnSurface, true, [0.38, 0.12, 0.40], 50.0, Look::Bag { body: FABRIC, strap: [0.85, 0.8, 0.7, 1.0], body_h: 0.7 });
// Wine cork: 2.4 × 4.4 cm.
thing!(CORK: "cork", "cork", ["wine cork", "bottle cork", "stopper", "bottle stopper"], HOME, "a cylindrical wine cork",
    ["closure"], HandHeld @ OnSurface, true, [0.024, 0.024, 0.044], 250.0,
    Look::Turned { profile: &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], body: &[[0.75, 0.6, 0.4, 1.0]], top: 1.0, cap_r: 1.0, cap: WHITE_C });
// Toothpick: 6.5 cm.
thing!(TOOTHPICK: "toothpick", "toothpick", ["cocktail stick", "tooth pick"], HOME, "a thin wooden toothpick",
    ["utensil"], HandHeld @ OnSurface, true, [0.065, 0.003, 0.003], 600.0, Look::Long { grip: 0.5, grip_w: 1.0, grip_h: 1.0, handle: WOODS, head: [0.8, 0.7, 0.5, 1.0] });
// Rubber band, lying flat: 6 cm.
thing!(RUBBER_BAND: "rubber_band", "rubber band", ["elastic band", "rubber ring band"], OFFICE, "a thin loop of rubber lying flat",
    ["office supply"], HandHeld @ OnSurface, true, [0.06, 0.06, 0.003], 900.0, Look::Flat { body: BRIGHTS, panel: [0.85, 0.55, 0.3, 1.0] });
// Brussels sprout: 3.5 cm.
thing!(BRUSSELS_SPROUT: "brussels_sprout", "brussels sprout", ["brussel sprout", "sprout"], &["kitchen", "food", "produce", "tabletop", "small", "graspable", "round"],
    "a small round green brussels sprout", ["vegetable", "food"], Food @ OnSurface, true, [0.035, 0.035, 0.035], 900.0,
    Look::Blob { body: GREEN, accent: BLACK_C, stem: false });
// Raspberry: 2 cm.
thing!(RASPBERRY: "raspberry", "raspberry", ["red raspberry"], &["kitchen", "food", "produce", "tabletop", "small", "graspable", "round"],
    "a small red raspberry", ["fruit", "berry", "food"], Food @ OnSurface, true, [0.02, 0.02, 0.022], 900.0,
    Look::Blob { body: RED, accent: BLACK_C, stem: false });

// --- tables -------------------------------------------------------------------------
// 8 ft pool table: 2.5 × 1.4 m, 80 cm to the cushion top.
thing!(POOL_TABLE: "pool_table", "pool table", ["billiard table", "billiards table", "snooker table"], &["home", "games", "furniture", "large"],
    "a heavy pool table with a green cloth top on legs", ["table", "furniture"], Furniture @ Floor, false, [2.50, 1.40, 0.80], 300.0,
    Look::Table { top: 0.25, wood: &[[0.1, 0.45, 0.2, 1.0], [0.1, 0.3, 0.55, 1.0]], legs: WOOD_C, shelf: false });
// ITTF table: 2.74 × 1.525 × 0.76 m.
thing!(TABLE_TENNIS_TABLE: "table_tennis_table", "table tennis table", ["ping pong table", "table tennis board"], &["home", "games", "furniture", "large"],
    "a dark green table tennis table on legs", ["table", "furniture"], Furniture @ Floor, false, [2.74, 1.525, 0.76], 80.0,
    Look::Table { top: 0.04, wood: &[[0.1, 0.3, 0.2, 1.0], [0.1, 0.2, 0.45, 1.0]], legs: [0.2, 0.2, 0.22, 1.0], shelf: false });
// Console table: 110 × 35 × 78 cm.
thing!(CONSOLE_TABLE: "console_table", "console table", ["hall table", "hallway table", "entryway table"], &["home", "furniture", "surface"],
    "a long narrow table that stands against a wall", ["table", "furniture"], Furniture @ AgainstWall, false, [1.10, 0.35, 0.78], 300.0,
    Look::Table { top: 0.05, wood: WOODS_T, legs: WOOD_C, shelf: true });
