//! BEHAVIOR-100's modelled object categories (issue 21, session 8): the in-scope nouns of
//! the 393 object categories BEHAVIOR-100 modelled for iGibson 2.0 (StanfordVL/bddl
//! `utils/objectmodeling.csv`, `bench/vocab/public_lists/behavior.txt`) that the catalog
//! lacked, in the list's order, one category each where the noun names one kind of thing
//! (a bare "toy", "bench" — read as a workbench in this catalog's rooms — "lid" or "glass"
//! name none and are left to the open vocabulary). Same parametric looks as the other
//! public families; sizes from published product ranges, noted per line. Hand-held things
//! are as slim as real ones (a Panda's fingers open 8 cm).

use super::common::{BROWN, FOOD, GOLDEN, HOME, PACKED, TABLEWARE};
use super::{
    BLACK_C, BLACKS, BRIGHTS, CAN, DISC, GREEN_C, JAR, Look, METAL, STEEL_C, WHITE, WHITE_C, WOODS, like, thing,
};
use super::{appliance, blob, capped, flat, long, pack, turned};

type Rgba = [f32; 4];

const TOOL: &[&str] = &["workshop", "tool", "tabletop", "graspable"];
const GARDEN: &[&str] = &["garden", "tool", "graspable"];
const CARE: &[&str] = &["bathroom", "personal_care", "tabletop", "small", "graspable"];
const TECH: &[&str] = &["office", "electronics", "tabletop", "small", "graspable"];
const PLAY: &[&str] = &["home", "toy", "sport", "graspable"];

const TERRACOTTA: &[Rgba] = &[[0.75, 0.4, 0.25, 1.0], [0.92, 0.92, 0.9, 1.0]];
/// A flower pot, narrower at its foot.
const POT: &[[f64; 2]] = &[[0.0, 0.0], [0.8, 0.0], [1.0, 1.0], [0.0, 1.0]];
const HERB: &[Rgba] = &[[0.25, 0.55, 0.2, 1.0], [0.2, 0.45, 0.15, 1.0]];
const CHIVE: &[Rgba] = &[[0.3, 0.6, 0.22, 1.0]];
const NUT_BROWN: &[Rgba] = &[[0.45, 0.25, 0.12, 1.0], [0.4, 0.22, 0.1, 1.0]];
const PALE_GREEN: &[Rgba] = &[[0.7, 0.8, 0.45, 1.0], [0.8, 0.85, 0.5, 1.0]];
const CITRUS: &[Rgba] = &[[0.85, 0.88, 0.45, 1.0], [0.78, 0.85, 0.4, 1.0]];
const HIP_RED: &[Rgba] = &[[0.8, 0.2, 0.1, 1.0], [0.75, 0.3, 0.1, 1.0]];
const BERRY_RED: &[Rgba] = &[[0.7, 0.08, 0.15, 1.0], [0.6, 0.05, 0.12, 1.0]];
const OLIVE: &[Rgba] = &[[0.4, 0.45, 0.15, 1.0], [0.3, 0.35, 0.12, 1.0]];
const SAUCE: &[Rgba] = &[[0.7, 0.12, 0.08, 1.0], [0.62, 0.1, 0.06, 1.0]];
const PUREE_RGB: &[Rgba] = &[[0.95, 0.65, 0.3, 1.0], [0.9, 0.8, 0.45, 1.0]];
const CARD: &[Rgba] = &[[0.9, 0.88, 0.8, 1.0], [0.85, 0.75, 0.45, 1.0]];
const PCB: &[Rgba] = &[[0.1, 0.4, 0.2, 1.0], [0.08, 0.3, 0.15, 1.0]];
const PLY: &[Rgba] = &[[0.85, 0.72, 0.5, 1.0], [0.8, 0.66, 0.45, 1.0]];
const PEG: &[Rgba] = &[[0.72, 0.55, 0.35, 1.0], [0.92, 0.92, 0.9, 1.0]];
const SILVERY: &[Rgba] = &[[0.85, 0.85, 0.9, 1.0], [0.9, 0.75, 0.3, 1.0], [0.75, 0.2, 0.25, 1.0]];
const FIR: &[Rgba] = &[[0.15, 0.35, 0.15, 1.0], [0.12, 0.3, 0.12, 1.0]];
const SUNSCREEN_RGB: &[Rgba] = &[[0.95, 0.75, 0.2, 1.0], [0.95, 0.95, 0.95, 1.0], [0.3, 0.6, 0.9, 1.0]];

/// A bowl seen from the side: a narrow foot widening to the rim (its contents the cap).
const BOWL: &[[f64; 2]] = &[[0.0, 0.0], [0.5, 0.0], [0.85, 0.5], [1.0, 1.0], [0.0, 1.0]];
/// A spool: flanges at both ends, a narrower core between.
const SPOOL: &[[f64; 2]] =
    &[[0.0, 0.0], [1.0, 0.0], [1.0, 0.12], [0.75, 0.14], [0.75, 0.86], [1.0, 0.88], [1.0, 1.0], [0.0, 1.0]];
/// A squeeze tube standing on its cap: the cap, then the body flattening to the crimp.
const TUBE: &[[f64; 2]] = &[[0.0, 0.0], [0.55, 0.0], [0.55, 0.12], [1.0, 0.2], [0.9, 0.9], [0.75, 1.0], [0.0, 1.0]];

// --- furniture and appliances ----------------------------------------------------------------
// The chaise longue is in furniture.rs, on the sofa's builder with its own seat and arm.
// A range hood, 60 × 50 × 60 cm chimney hood (Bosch/IKEA 60 cm hoods), hung over the stove.
thing!(RANGE_HOOD: "range_hood", "range hood", ["cooker hood", "extractor hood", "extractor fan", "kitchen hood", "stove hood", "chimney hood", "exhaust hood"],
    &["kitchen", "appliance"], "a stainless chimney range hood that hangs on the wall above a stove",
    ["kitchen appliance", "appliance"], LargeAppliance @ WallMounted, false, [0.60, 0.50, 0.60], 60.0,
    Look::Turned { profile: &[[0.0, 0.0], [1.0, 0.0], [1.0, 0.1], [0.35, 0.35], [0.35, 1.0], [0.0, 1.0]], body: METAL, top: 1.0, cap_r: 1.0, cap: STEEL_C });
// A single portable gas burner, 34 × 28 × 10 cm (Iwatani / Campingaz butane stoves).
thing!(BURNER: "portable_burner", "portable burner", ["burner", "camping stove", "butane stove", "single burner", "portable stove", "portable hob"],
    &["kitchen", "appliance", "tabletop"], "a portable single gas burner with a pan support and a knob",
    ["cooker", "appliance"], SmallAppliance @ OnSurface, true, [0.34, 0.28, 0.10], 200.0, appliance(BLACKS, STEEL_C, 1));
// A fax machine, 35 × 30 × 15 cm (Brother FAX-2840: 37 × 37 × 31 with trays; desk faxes 30–40 cm).
thing!(FAX_MACHINE: "fax_machine", "fax machine", ["fax", "facsimile", "facsimile machine", "telefax", "fax printer"],
    &["office", "electronics", "tabletop"], "a desktop fax machine with a handset and a paper tray",
    ["office equipment", "electronics"], SmallAppliance @ OnSurface, true, [0.35, 0.30, 0.15], 250.0, appliance(WHITE, BLACK_C, 3));
// A carpet sweeper, 30 × 25 × 110 cm with its handle up (Bissell sweepers).
like!(CARPET_SWEEPER: "carpet_sweeper", "carpet sweeper", ["manual sweeper", "floor sweeper", "push sweeper", "mechanical sweeper"],
    &["home", "cleaning", "tall"], "a push carpet sweeper: a low brush box on a long handle",
    ["cleaning tool"], HandHeld @ Floor, true, [0.30, 0.25, 1.10], super::super::tools::build_broom);
// A drawer unit (a cabinet with drawers) is in bedroom.rs, on the chest of drawers' carcass.

// --- food and drink -------------------------------------------------------------------------
// A sweet chestnut, 3 × 3 × 2.5 cm.
thing!(CHESTNUT: "chestnut", "chestnut", ["chestnuts", "sweet chestnut", "roasted chestnut", "marron"], FOOD,
    "a glossy brown chestnut", ["nut", "food"], Food @ OnSurface, true, [0.03, 0.03, 0.025], 900.0, blob(NUT_BROWN));
// A bunch of chives, 25 × 3 × 2 cm.
thing!(CHIVES: "chives", "chives", ["bunch of chives", "chive", "fresh chives", "spring onion tops"], FOOD,
    "a bunch of thin green chives", ["herb", "vegetable", "food"], Food @ OnSurface, true, [0.25, 0.03, 0.02], 300.0,
    long(0.2, CHIVE, [0.3, 0.62, 0.22, 1.0]));
// A bunch of parsley, 25 × 10 × 5 cm.
thing!(HERB_BUNCH: "herb_bunch", "bunch of herbs", ["parsley", "bunch of parsley", "coriander", "cilantro", "fresh herbs", "dill", "fresh parsley", "bunch of coriander", "herbs"], FOOD,
    "a bunch of fresh leafy herbs such as parsley", ["herb", "vegetable", "food"], Food @ OnSurface, true, [0.25, 0.10, 0.05], 200.0,
    Look::Long { grip: 0.35, grip_w: 0.2, grip_h: 0.4, handle: CHIVE, head: [0.2, 0.5, 0.15, 1.0] });
// A potted basil plant, 12 × 12 × 22 cm (supermarket living herbs in a 12 cm pot).
thing!(BASIL_POT: "potted_herb", "potted herb", ["pot of basil", "basil plant", "potted basil", "basil", "herb pot", "pot of herbs", "potted herbs", "living herbs"],
    &["kitchen", "plant", "tabletop", "small", "graspable"], "a small pot of living basil on the windowsill",
    ["plant", "herb"], Plant @ OnSurface, true, [0.12, 0.12, 0.22], 300.0,
    Look::Turned { profile: POT, body: TERRACOTTA, top: 0.45, cap_r: 1.0, cap: [0.2, 0.5, 0.15, 1.0] });
// A 300 ml carton of cream, 7 × 7 × 12 cm.
thing!(CREAM_CARTON: "cream_carton", "carton of cream", ["cream", "single cream", "double cream", "heavy cream", "whipping cream", "pot of cream", "carton of single cream"], PACKED,
    "a small carton of pouring cream", ["dairy", "carton", "food"], Food @ OnSurface, true, [0.07, 0.07, 0.12], 900.0,
    pack(WHITE, [0.3, 0.45, 0.8, 1.0]));
// A gooseberry, 2.5 × 2.5 × 2.5 cm.
thing!(GOOSEBERRY: "gooseberry", "gooseberry", ["gooseberries", "cape gooseberry", "goosegog"], FOOD,
    "a round pale green gooseberry", ["fruit", "berry", "food"], Food @ OnSurface, true, [0.025, 0.025, 0.025], 950.0, blob(PALE_GREEN));
// A canister of porridge oats, 12.7 × 12.7 × 17.8 cm (Quaker 18 oz).
thing!(OATMEAL: "oatmeal", "oatmeal", ["oats", "porridge oats", "rolled oats", "canister of oats", "box of oats", "tub of oats", "porridge", "tub of oatmeal"], PACKED,
    "a round cardboard canister of rolled oats", ["cereal", "food"], Food @ OnSurface, true, [0.127, 0.127, 0.178], 350.0,
    capped(CAN, CARD, 0.95, 1.0, [0.8, 0.15, 0.15, 1.0]));
// A jar of olives, 8 × 8 × 13 cm (350 g jars).
thing!(OLIVES: "jar_of_olives", "jar of olives", ["olives", "olive jar", "green olives", "black olives", "kalamata olives"], PACKED,
    "a glass jar of green olives with a metal lid", ["jar", "food"], Food @ OnSurface, true, [0.08, 0.08, 0.13], 900.0,
    capped(JAR, OLIVE, 0.9, 0.85, STEEL_C));
// A pistachio in its shell, 2 × 1.3 × 1.2 cm.
thing!(PISTACHIO: "pistachio", "pistachio", ["pistachios", "pistachio nut", "pistachio nuts"], FOOD,
    "a pistachio nut in its split shell", ["nut", "food"], Food @ OnSurface, true, [0.02, 0.013, 0.012], 800.0,
    blob(&[[0.85, 0.78, 0.6, 1.0]]));
// A pomelo, 17 × 17 × 15 cm.
thing!(POMELO: "pomelo", "pomelo", ["pummelo", "shaddock", "pomelos", "chinese grapefruit"], FOOD,
    "a large pale green-yellow pomelo", ["citrus fruit", "fruit", "food"], Food @ OnSurface, true, [0.17, 0.17, 0.15], 700.0,
    Look::Blob { body: CITRUS, accent: GREEN_C, stem: true });
// A case of 12 cans of soda, 27 × 20 × 12 cm.
thing!(DRINKS_CASE: "drinks_case", "case of cans", ["case of soda", "case of pop", "12-pack", "twelve pack", "pack of cans", "soda case", "crate of cans", "multipack of cans", "pop case"], PACKED,
    "a cardboard case of twelve drink cans", ["package", "drink", "food"], Food @ OnSurface, true, [0.27, 0.20, 0.12], 450.0,
    pack(BRIGHTS, WHITE_C));
// A rosehip, 2 × 1.5 × 1.5 cm.
thing!(ROSEHIP: "rosehip", "rosehip", ["rose hip", "rosehips", "rose hips"], FOOD,
    "an oval orange-red rosehip", ["fruit", "berry", "food"], Food @ OnSurface, true, [0.02, 0.015, 0.015], 900.0, blob(HIP_RED));
// A 680 g jar of pasta sauce, 8.5 × 8.5 × 15 cm.
thing!(PASTA_SAUCE: "pasta_sauce", "pasta sauce", ["spaghetti sauce", "jar of pasta sauce", "jar of spaghetti sauce", "marinara sauce", "bolognese sauce", "tomato pasta sauce", "jar of sauce"], PACKED,
    "a glass jar of red tomato pasta sauce", ["sauce", "jar", "food"], Food @ OnSurface, true, [0.085, 0.085, 0.15], 900.0,
    capped(JAR, SAUCE, 0.9, 0.85, [0.85, 0.7, 0.2, 1.0]));
// A 200 g bag of spinach, 25 × 18 × 8 cm.
thing!(SPINACH: "spinach", "bag of spinach", ["baby spinach", "bag of salad", "salad bag", "bagged salad", "bag of lettuce", "salad leaves"], PACKED,
    "a clear bag of green spinach leaves", ["vegetable", "food"], Food @ OnSurface, true, [0.25, 0.18, 0.08], 100.0,
    pack(HERB, [0.9, 0.9, 0.9, 1.0]));
// A serving of salad in a bowl, 22 × 22 × 10 cm.
thing!(SALAD: "salad", "salad", ["bowl of salad", "green salad", "garden salad", "side salad", "caesar salad", "mixed salad"], TABLEWARE,
    "a bowl of green leaf salad", ["dish", "food"], Food @ OnSurface, true, [0.22, 0.22, 0.10], 500.0,
    capped(BOWL, WHITE, 0.8, 0.95, [0.3, 0.6, 0.2, 1.0]));
// A bowl of soup, 16 × 16 × 7 cm.
thing!(SOUP: "soup", "bowl of soup", ["soup in a bowl", "bowl of stew", "bowl of broth", "broth", "stew"], TABLEWARE,
    "a bowl filled with hot soup", ["dish", "food"], Food @ OnSurface, true, [0.16, 0.16, 0.07], 900.0,
    capped(BOWL, WHITE, 0.85, 0.95, [0.85, 0.45, 0.15, 1.0]));
// A 500 g tray of beef mince or pork chops, 25 × 18 × 4 cm.
thing!(MEAT_TRAY: "meat_tray", "pack of meat", ["meat", "beef", "pork", "pork chops", "minced beef", "ground beef", "mince", "pack of mince", "pack of pork chops", "lamb chops", "raw meat"], PACKED,
    "a plastic tray of raw meat under film", ["meat", "food"], Food @ OnSurface, true, [0.25, 0.18, 0.04], 700.0,
    Look::Flat { body: WHITE, panel: [0.82, 0.4, 0.4, 1.0] });
// A rack of pork ribs, 30 × 15 × 5 cm.
thing!(RIBS: "rack_of_ribs", "rack of ribs", ["ribs", "rib", "spare ribs", "spareribs", "pork ribs", "baby back ribs", "bbq ribs"], FOOD,
    "a rack of barbecued pork ribs", ["meat", "food"], Food @ OnSurface, true, [0.30, 0.15, 0.05], 900.0,
    flat(&[[0.55, 0.22, 0.12, 1.0]], [0.45, 0.18, 0.1, 1.0]));
// A 20 cm fruit tart, 3 cm tall.
thing!(TART: "tart", "tart", ["fruit tart", "tartlet", "bakewell tart", "lemon tart", "treacle tart", "jam tart"], FOOD,
    "a round pastry tart with a golden crust", ["baked goods", "food"], Food @ OnSurface, true, [0.20, 0.20, 0.03], 600.0,
    capped(DISC, GOLDEN, 0.7, 0.9, [0.8, 0.2, 0.25, 1.0]));
// Cinnamon sticks, 10 × 1.2 × 1.2 cm.
thing!(CINNAMON: "cinnamon_stick", "cinnamon stick", ["cinnamon", "cinnamon sticks", "cinnamon quill", "cinnamon bark"], FOOD,
    "a rolled brown stick of cinnamon bark", ["spice", "food"], Food @ OnSurface, true, [0.10, 0.012, 0.012], 600.0,
    long(0.5, BROWN, [0.5, 0.3, 0.15, 1.0]));
// A 120 g jar of puree, 6.5 × 6.5 × 8 cm.
thing!(PUREE: "puree_jar", "jar of puree", ["puree", "baby food", "jar of baby food", "baby food jar", "fruit puree", "apple puree", "apple sauce", "applesauce"], PACKED,
    "a small glass jar of fruit puree", ["jar", "food"], Food @ OnSurface, true, [0.065, 0.065, 0.08], 950.0,
    capped(JAR, PUREE_RGB, 0.88, 0.9, WHITE_C));
// An 80 g pack of prosciutto, 22 × 14 × 1.5 cm.
thing!(PROSCIUTTO: "prosciutto", "prosciutto", ["parma ham", "serrano ham", "cured ham", "pack of prosciutto", "sliced ham", "pack of ham", "ham slices", "salami slices", "pack of salami"], PACKED,
    "a flat pack of thinly sliced cured ham", ["meat", "food"], Food @ OnSurface, true, [0.22, 0.14, 0.015], 600.0,
    Look::Flat { body: WHITE, panel: [0.85, 0.45, 0.45, 1.0] });
// A gingerbread man, 12 × 9 × 1 cm.
thing!(GINGERBREAD: "gingerbread_man", "gingerbread man", ["gingerbread", "gingerbread cookie", "gingerbread biscuit", "gingerbread men", "gingerbread person"], FOOD,
    "a gingerbread man biscuit with white icing", ["baked goods", "cookie", "food"], Food @ OnSurface, true, [0.12, 0.09, 0.01], 700.0,
    flat(&[[0.7, 0.42, 0.18, 1.0]], WHITE_C));
// A punnet of cranberries, 12 × 12 × 6 cm.
thing!(CRANBERRIES: "cranberries", "punnet of cranberries", ["cranberry", "dried cranberries", "container of cranberries", "tub of cranberries", "bag of cranberries", "punnet of berries"], PACKED,
    "a small clear punnet of red cranberries", ["fruit", "berry", "food"], Food @ OnSurface, true, [0.12, 0.12, 0.06], 500.0,
    capped(CAN, BERRY_RED, 0.9, 1.0, [0.85, 0.9, 0.92, 1.0]));
// A 250 g box of Medjool dates, 18 × 10 × 4 cm.
thing!(DATES_BOX: "box_of_dates", "box of dates", ["container of dates", "tub of dates", "medjool dates", "pack of dates", "dried dates", "date box"], PACKED,
    "a flat box of brown dried dates", ["fruit", "food"], Food @ OnSurface, true, [0.18, 0.10, 0.04], 600.0,
    pack(&[[0.45, 0.25, 0.12, 1.0]], [0.9, 0.8, 0.5, 1.0]));

// --- tools, home, office ---------------------------------------------------------------------
// A vernier caliper, 23 × 8 × 1.5 cm (150 mm calipers).
thing!(CALIPER: "caliper", "caliper", ["calipers", "callipers", "calliper", "vernier caliper", "vernier calipers", "digital caliper", "digital calipers", "slide caliper"], TOOL,
    "a steel vernier caliper with two jaws and a sliding scale", ["measuring tool", "tool"], HandHeld @ OnSurface, true, [0.23, 0.08, 0.015], 2000.0,
    Look::Long { grip: 0.8, grip_w: 0.25, grip_h: 1.0, handle: METAL, head: STEEL_C });
// A honing steel, 40 × 4 × 4 cm (a 25 cm rod on a handle with a guard).
thing!(HONING_STEEL: "honing_steel", "honing steel", ["sharpening steel", "knife steel", "sharpening rod", "honing rod", "butcher's steel", "sharpening steel rod"], &["kitchen", "utensil", "tabletop", "graspable"],
    "a round steel rod on a handle for honing knives", ["kitchen utensil", "knife sharpener"], HandHeld @ OnSurface, true, [0.40, 0.04, 0.04], 1500.0,
    Look::Long { grip: 0.35, grip_w: 1.0, grip_h: 1.0, handle: BLACKS, head: STEEL_C });
// A dressmaker's pin, 3.2 cm long.
thing!(STRAIGHT_PIN: "straight_pin", "straight pin", ["sewing pin", "dressmaker pin", "dressmaker's pin", "dressmaking pin", "pin", "pins", "sewing pins"], &["home", "sewing", "tabletop", "small", "graspable"],
    "a steel sewing pin with a round head", ["sewing tool"], HandHeld @ OnSurface, true, [0.032, 0.003, 0.003], 3000.0,
    Look::Long { grip: 0.15, grip_w: 1.0, grip_h: 1.0, handle: BRIGHTS, head: STEEL_C });
// A video game in its case, 17 × 13.5 × 1.4 cm.
thing!(VIDEO_GAME: "video_game", "video game", ["video game case", "game case", "console game", "game disc", "video game box", "computer game"], &["home", "toy", "electronics", "tabletop", "small", "graspable"],
    "a video game in a plastic case with a printed cover", ["game", "toy"], Toy @ OnSurface, true, [0.17, 0.135, 0.014], 700.0,
    pack(&[[0.1, 0.3, 0.75, 1.0], [0.8, 0.1, 0.1, 1.0], [0.1, 0.1, 0.12, 1.0]], WHITE_C));
// A printer ink cartridge, 11 × 4 × 7 cm in its box.
thing!(INK_CARTRIDGE: "ink_cartridge", "ink cartridge", ["printer cartridge", "ink cartridges", "printer ink", "inkjet cartridge", "ink refill"], TECH,
    "a boxed inkjet printer cartridge", ["office supply", "electronics accessory"], HandHeld @ OnSurface, true, [0.11, 0.04, 0.07], 500.0,
    pack(BLACKS, [0.2, 0.5, 0.85, 1.0]));
// A motherboard, 30.5 × 24.4 × 3 cm (ATX).
thing!(CIRCUIT_BOARD: "circuit_board", "circuit board", ["motherboard", "cpu board", "pcb", "printed circuit board", "logic board", "mainboard", "main board", "computer board"], TECH,
    "a green printed circuit board with chips and connectors", ["electronics", "computer part"], HandHeld @ OnSurface, true, [0.305, 0.244, 0.03], 400.0,
    flat(PCB, [0.2, 0.2, 0.22, 1.0]));
// A portable hard drive, 12 × 8 × 2 cm (WD / Seagate 2.5-inch).
thing!(HARD_DRIVE: "hard_drive", "hard drive", ["external hard drive", "hdd", "portable hard drive", "external drive", "portable ssd", "external ssd", "hard disk", "disk drive", "hard disk drive"], TECH,
    "a small black portable hard drive", ["storage device", "electronics"], HandHeld @ OnSurface, true, [0.12, 0.08, 0.02], 900.0,
    pack(BLACKS, [0.3, 0.3, 0.32, 1.0]));
// A spool of ribbon, 8 × 8 × 3 cm (25 mm × 20 m).
thing!(RIBBON: "ribbon_spool", "spool of ribbon", ["ribbon", "roll of ribbon", "reel of ribbon", "gift ribbon", "satin ribbon"], HOME,
    "a spool of satin ribbon", ["craft supply"], HandHeld @ OnSurface, true, [0.08, 0.08, 0.03], 500.0,
    turned(SPOOL, BRIGHTS));
// A coiled charging cable, 15 × 15 × 4 cm.
thing!(CABLE: "cable", "cable", ["cord", "power cord", "power cable", "charging cable", "usb cable", "charger cable", "hdmi cable", "coiled cable", "electrical cord", "phone charger cable"], TECH,
    "a coiled black electrical cable", ["electronics accessory"], HandHeld @ OnSurface, true, [0.15, 0.15, 0.04], 600.0,
    capped(DISC, BLACKS, 0.9, 0.35, [0.2, 0.2, 0.22, 1.0]));
// A project panel of plywood, 122 × 61 × 1.8 cm.
thing!(PLYWOOD: "plywood_sheet", "plywood sheet", ["plywood", "sheet of plywood", "plywood board", "plywood panel", "ply board", "mdf board", "sheet of mdf", "chipboard sheet"], &["workshop", "material", "large"],
    "a flat sheet of plywood", ["material", "board"], Tabletop @ Floor, true, [1.22, 0.61, 0.018], 550.0, flat(PLY, [0.8, 0.68, 0.48, 1.0]));
// A clout nail, 4 × 0.8 × 0.8 cm (40 mm galvanised clout nails; the head 8 mm).
thing!(NAIL: "nail", "nail", ["nails", "clout nail", "roofing nail", "wire nail", "round nail", "masonry nail", "panel pin", "clout nails"], &["workshop", "hardware", "tabletop", "small", "graspable"],
    "a steel nail with a flat head", ["fastener", "hardware"], HandHeld @ OnSurface, true, [0.04, 0.008, 0.008], 3000.0,
    Look::Long { grip: 0.1, grip_w: 1.0, grip_h: 1.0, handle: METAL, head: STEEL_C });
// A steel-tip dart, 15 × 3 × 3 cm (flights 3 cm across).
thing!(DART: "dart", "dart", ["darts", "steel tip dart", "soft tip dart", "throwing dart"], PLAY,
    "a dart with a steel tip and coloured flights", ["game", "sports equipment"], Toy @ OnSurface, true, [0.15, 0.03, 0.03], 500.0,
    Look::Long { grip: 0.75, grip_w: 0.3, grip_h: 0.6, handle: METAL, head: [0.85, 0.15, 0.12, 1.0] });
// A dartboard, 45 × 45 × 4 cm (the regulation 451 mm board).
thing!(DARTBOARD: "dartboard", "dartboard", ["dart board", "bristle dartboard", "darts board"], &["home", "toy", "sport"],
    "a round bristle dartboard with black, cream, red and green rings", ["game", "sports equipment"], Toy @ OnSurface, true, [0.45, 0.45, 0.04], 500.0,
    capped(DISC, BLACKS, 0.6, 0.8, [0.85, 0.8, 0.6, 1.0]));
// A wrapped gift, 25 × 20 × 12 cm.
thing!(GIFT: "wrapped_gift", "wrapped gift", ["gift", "gift box", "wrapped present", "birthday present", "christmas present", "wrapped box", "gift-wrapped box", "gifts"], HOME,
    "a box in bright wrapping paper tied with a ribbon", ["package", "box"], Tabletop @ OnSurface, true, [0.25, 0.20, 0.12], 250.0,
    pack(BRIGHTS, [0.95, 0.85, 0.2, 1.0]));
// A Christmas wreath, 45 × 45 × 10 cm.
thing!(WREATH: "wreath", "wreath", ["christmas wreath", "door wreath", "advent wreath", "holly wreath", "festive wreath"], &["home", "decor"],
    "a round green wreath of fir twigs with a red bow", ["decoration"], Tabletop @ OnSurface, true, [0.45, 0.45, 0.10], 150.0,
    Look::Turned { profile: &[[0.0, 0.0], [1.0, 0.0], [1.0, 0.6], [0.7, 1.0], [0.0, 1.0]], body: FIR, top: 0.9, cap_r: 0.45, cap: [0.8, 0.1, 0.1, 1.0] });
// A bundle of tinsel, 20 × 20 × 8 cm.
thing!(TINSEL: "tinsel", "tinsel", ["tinsel garland", "christmas tinsel", "roll of tinsel", "bundle of tinsel"], &["home", "decor", "tabletop", "small", "graspable"],
    "a shiny coiled bundle of tinsel garland", ["decoration"], Tabletop @ OnSurface, true, [0.20, 0.20, 0.08], 60.0, blob(SILVERY));
// A mousetrap, 10 × 5 × 2 cm (Victor snap traps).
thing!(MOUSETRAP: "mousetrap", "mousetrap", ["mouse trap", "rat trap", "snap trap", "mouse traps"], &["home", "tabletop", "small", "graspable"],
    "a wooden snap mousetrap with a wire bar", ["trap"], HandHeld @ OnSurface, true, [0.10, 0.05, 0.02], 500.0, flat(WOODS, STEEL_C));
// A pegboard panel, 60 × 40 × 1 cm, lying flat.
thing!(PEGBOARD: "pegboard", "pegboard", ["pegboard panel", "tool board", "perforated board", "hook board"], &["workshop", "storage"],
    "a perforated hardboard pegboard panel for hanging tools", ["board", "storage"], Tabletop @ OnSurface, true, [0.60, 0.40, 0.01], 700.0, flat(PEG, [0.6, 0.45, 0.28, 1.0]));
// A 9-inch paint roller, 38 × 23 × 6 cm.
thing!(PAINT_ROLLER: "paint_roller", "paint roller", ["roller", "decorating roller", "paint rollers", "foam roller brush"], TOOL,
    "a paint roller: a handle and a wide fluffy roller sleeve", ["painting tool", "tool"], HandHeld @ OnSurface, true, [0.38, 0.23, 0.06], 250.0,
    Look::Long { grip: 0.55, grip_w: 0.15, grip_h: 0.5, handle: BRIGHTS, head: [0.95, 0.95, 0.92, 1.0] });
// A garden trowel, 32 × 8 × 5 cm.
thing!(TROWEL: "trowel", "trowel", ["garden trowel", "hand trowel", "gardening trowel", "plastering trowel", "pointing trowel", "brick trowel"], GARDEN,
    "a hand trowel: a pointed steel blade on a wooden handle", ["garden tool", "tool"], HandHeld @ OnSurface, true, [0.32, 0.08, 0.05], 700.0,
    Look::Long { grip: 0.45, grip_w: 0.4, grip_h: 0.7, handle: WOODS, head: STEEL_C });
// A leaf rake, 160 × 45 × 5 cm lying flat.
thing!(RAKE: "rake", "rake", ["garden rake", "leaf rake", "lawn rake", "bow rake", "rakes"], GARDEN,
    "a long-handled garden rake with a row of tines", ["garden tool", "tool"], HandHeld @ Floor, true, [1.60, 0.45, 0.05], 120.0,
    Look::Long { grip: 0.82, grip_w: 0.06, grip_h: 0.6, handle: WOODS, head: [0.2, 0.5, 0.25, 1.0] });
// A safety razor, 15 × 4 × 3 cm.
thing!(RAZOR: "razor", "razor", ["safety razor", "disposable razor", "shaving razor", "wet razor", "razors", "straight razor", "cut-throat razor"], CARE,
    "a razor with a slim handle and a blade head", ["grooming tool"], HandHeld @ OnSurface, true, [0.15, 0.04, 0.03], 700.0,
    Look::Long { grip: 0.75, grip_w: 0.35, grip_h: 0.5, handle: BRIGHTS, head: STEEL_C });
// A 200 ml tube of sunscreen, 5 × 3.5 × 17 cm, standing on its cap.
thing!(SUNSCREEN: "sunscreen", "sunscreen", ["sun cream", "suncream", "sunblock", "sun lotion", "bottle of sunscreen", "tube of sunscreen", "sun screen", "spf lotion"], CARE,
    "a squeeze tube of sunscreen standing on its cap", ["cosmetic", "lotion"], HandHeld @ OnSurface, true, [0.05, 0.035, 0.17], 800.0,
    turned(TUBE, SUNSCREEN_RGB));
// A tub of protein powder, 15 × 15 × 22 cm (1 kg tubs).
thing!(PROTEIN_POWDER: "protein_powder", "protein powder", ["tub of protein powder", "protein tub", "whey protein", "protein shake powder", "tub of whey"], PACKED,
    "a large plastic tub of protein powder with a screw lid", ["supplement", "food"], Food @ OnSurface, true, [0.15, 0.15, 0.22], 400.0,
    capped(CAN, BLACKS, 0.88, 0.95, [0.85, 0.15, 0.1, 1.0]));
