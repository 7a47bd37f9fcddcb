//! LVIS v1's *common* categories (issue 21, fourth round): the in-scope nouns of LVIS's
//! 461 common classes that the catalog lacked, taken most-imaged first
//! (`bench/vocab/public_lists/lvis_common.txt`, `coverage.py`). Same parametric looks as
//! the other public families; sizes from published product ranges, noted per line.

use super::{
    BLACK_C, BLACKS, BOTTLE, BRIGHTS, CAN, DISC, DOME, FABRIC, GREEN_C, LEATHER, Look, METAL, STEEL_C, TUMBLER, WHITE,
    WHITE_C, WOOD_C, WOODS, like, thing,
};
use super::{appliance, blob, capped, flat, long, pack, turned};

type Rgba = [f32; 4];

pub(crate) const FOOD: &[&str] = &["kitchen", "food", "tabletop", "small", "graspable"];
pub(crate) const PACKED: &[&str] = &["kitchen", "food", "packaging", "tabletop", "small", "graspable"];
pub(crate) const HOME: &[&str] = &["home", "tabletop", "small", "graspable"];
const CARE: &[&str] = &["bathroom", "personal_care", "tabletop", "small", "graspable"];
pub(crate) const OFFICE: &[&str] = &["office", "stationery", "tabletop", "small", "graspable"];
const AUDIO: &[&str] = &["home", "electronics", "audio", "tabletop"];
pub(crate) const TABLEWARE: &[&str] = &["kitchen", "tableware", "tabletop", "small", "graspable"];

pub(crate) const GOLDEN: &[Rgba] = &[[0.85, 0.6, 0.3, 1.0], [0.78, 0.52, 0.25, 1.0]];
pub(crate) const BROWN: &[Rgba] = &[[0.45, 0.3, 0.15, 1.0], [0.38, 0.25, 0.12, 1.0]];
const DARK_BROWN: &[Rgba] = &[[0.3, 0.18, 0.1, 1.0], [0.25, 0.15, 0.08, 1.0]];
pub(crate) const CREAM: &[Rgba] = &[[0.95, 0.92, 0.82, 1.0], [0.97, 0.95, 0.88, 1.0]];
const RED: &[Rgba] = &[[0.75, 0.1, 0.1, 1.0], [0.65, 0.08, 0.08, 1.0]];
const GREEN: &[Rgba] = &[[0.35, 0.6, 0.2, 1.0], [0.3, 0.52, 0.18, 1.0]];
const BERRY: &[Rgba] = &[[0.18, 0.08, 0.2, 1.0], [0.12, 0.05, 0.15, 1.0]];
const SILVER: &[Rgba] = &[[0.75, 0.77, 0.8, 1.0], [0.68, 0.7, 0.74, 1.0]];
pub(crate) const GLASS: &[Rgba] = &[[0.82, 0.88, 0.9, 1.0], [0.9, 0.85, 0.7, 1.0]];
const SHELL: &[Rgba] = &[[0.95, 0.85, 0.78, 1.0], [0.92, 0.9, 0.84, 1.0], [0.9, 0.75, 0.7, 1.0]];
const MONEY: &[Rgba] = &[[0.55, 0.7, 0.55, 1.0], [0.7, 0.6, 0.75, 1.0], [0.85, 0.7, 0.5, 1.0]];
const BURGUNDY: &[Rgba] = &[[0.4, 0.08, 0.12, 1.0], [0.1, 0.15, 0.35, 1.0]];
const GOLD_C: Rgba = [0.85, 0.68, 0.25, 1.0];
const RED_C: Rgba = [0.8, 0.1, 0.1, 1.0];

/// A stemmed glass: a foot, a thin stem and a tall narrow bowl.
const FLUTE: &[[f64; 2]] =
    &[[0.0, 0.0], [0.75, 0.0], [0.75, 0.03], [0.1, 0.06], [0.1, 0.38], [0.6, 0.48], [0.75, 1.0], [0.0, 1.0]];
/// A spool or bobbin: flanges at both ends, a narrower core between.
const SPOOL: &[[f64; 2]] =
    &[[0.0, 0.0], [1.0, 0.0], [1.0, 0.1], [0.7, 0.12], [0.7, 0.88], [1.0, 0.9], [1.0, 1.0], [0.0, 1.0]];
/// A bell flaring to its mouth at the bottom.
const BELL: &[[f64; 2]] = &[[0.0, 0.0], [1.0, 0.0], [0.85, 0.45], [0.6, 0.88], [0.2, 1.0], [0.0, 1.0]];
/// An egg-shaped cone (a pine cone, a bird feeder's roof).
const CONE_EGG: &[[f64; 2]] = &[[0.0, 0.0], [0.45, 0.0], [1.0, 0.35], [0.8, 0.75], [0.3, 0.98], [0.0, 1.0]];
/// A shallow dish with a low rim (an ashtray, a platter).
const DISH: &[[f64; 2]] = &[[0.0, 0.0], [0.85, 0.0], [1.0, 0.9], [0.92, 1.0], [0.0, 1.0]];
/// A pedestal bowl (a bird bath's basin, a trophy's cup).
const CAGE: &[[f64; 2]] =
    &[[0.0, 0.0], [1.0, 0.0], [1.0, 0.08], [0.95, 0.1], [0.95, 0.7], [0.7, 0.9], [0.2, 1.0], [0.0, 1.0]];

// --- food and drink ------------------------------------------------------------------
// Aerosol of whipped cream, 250 g: 6.5 cm across, 22 cm tall.
thing!(WHIPPED_CREAM: "whipped_cream_can", "whipped cream", ["squirty cream", "aerosol cream", "spray cream", "can of whipped cream"], PACKED,
    "an aerosol can of whipped cream with a nozzle cap", ["can", "dairy", "food"], Food @ OnSurface, true, [0.065, 0.065, 0.22], 400.0,
    capped(CAN, WHITE, 0.85, 0.4, [0.85, 0.2, 0.25, 1.0]));
// A pea pod, 8 cm long.
thing!(PEA_POD: "pea_pod", "pea pod", ["pea", "peas", "garden peas", "mangetout", "snow pea", "sugar snap pea"], FOOD,
    "a green pod of peas", ["vegetable", "produce", "food"], Food @ OnSurface, true, [0.08, 0.016, 0.014], 900.0, blob(GREEN));
// A cup of cappuccino, 9 cm across, 8 cm tall (a 180 ml cup).
thing!(CAPPUCCINO: "cappuccino", "cappuccino", ["cup of cappuccino", "latte", "flat white", "cafe latte", "caffe latte", "cup of latte"], TABLEWARE,
    "a cup of cappuccino topped with milk foam", ["drink", "coffee"], Food @ OnSurface, true, [0.09, 0.09, 0.08], 500.0,
    capped(TUMBLER, WHITE, 0.9, 0.95, [0.85, 0.72, 0.55, 1.0]));
// An almond, 2.4 × 1.5 × 1 cm.
thing!(ALMOND: "almond", "almond", ["almonds", "almond nut"], FOOD, "a single almond in its brown skin",
    ["nut", "food"], Food @ OnSurface, true, [0.024, 0.015, 0.010], 1000.0, blob(BROWN));
// A water cracker, 6 cm square.
thing!(CRACKER: "cracker", "cracker", ["crackers", "cream cracker", "saltine", "water biscuit", "rice cracker", "cracker biscuit"], FOOD,
    "a square dry cracker", ["snack", "baked goods", "food"], Food @ OnSurface, true, [0.06, 0.06, 0.006], 500.0,
    flat(GOLDEN, [0.9, 0.75, 0.45, 1.0]));
// A 300 g deli tub of coleslaw, 10 cm across, 7 cm tall.
thing!(COLESLAW: "coleslaw", "coleslaw", ["tub of coleslaw", "potato salad", "pot of coleslaw", "slaw"], PACKED,
    "a round deli tub of coleslaw with a clear lid", ["salad", "food"], Food @ OnSurface, true, [0.10, 0.10, 0.07], 700.0,
    capped(CAN, CREAM, 0.9, 0.98, [0.85, 0.9, 0.92, 1.0]));
// A 300 ml tub of sour cream, 9 cm across, 7 cm tall.
thing!(SOUR_CREAM: "sour_cream", "sour cream", ["soured cream", "tub of sour cream", "creme fraiche", "crème fraîche", "pot of sour cream"], PACKED,
    "a tub of sour cream with a foil lid", ["dairy", "food"], Food @ OnSurface, true, [0.09, 0.09, 0.07], 700.0,
    capped(CAN, WHITE, 0.92, 0.98, [0.3, 0.45, 0.75, 1.0]));
// A slice of toast, 11 × 11 × 1.2 cm.
thing!(TOAST: "toast", "toast", ["slice of toast", "piece of toast", "toast slice", "french toast", "buttered toast"], FOOD,
    "a golden slice of toasted bread", ["bread", "food"], Food @ OnSurface, true, [0.11, 0.11, 0.012], 300.0,
    flat(GOLDEN, [0.9, 0.72, 0.42, 1.0]));
// A blackberry, 2 cm.
thing!(BLACKBERRY: "blackberry", "blackberry", ["blackberries", "bramble berry", "dewberry"], FOOD, "a dark purple blackberry",
    ["berry", "fruit", "produce", "food"], Food @ OnSurface, true, [0.02, 0.02, 0.024], 1000.0, blob(BERRY));
// A roast turkey, 35 × 25 × 18 cm (a 5 kg bird).
thing!(ROAST_TURKEY: "roast_turkey", "roast turkey", ["turkey", "turkey roast", "roasted turkey", "christmas turkey"], FOOD,
    "a golden roast turkey", ["meat", "food"], Food @ OnSurface, true, [0.35, 0.25, 0.18], 500.0, blob(GOLDEN));
// A meatball, 4 cm.
thing!(MEATBALL: "meatball", "meatball", ["meatballs", "meat ball", "rissole"], FOOD, "a round brown meatball",
    ["meat", "food"], Food @ OnSurface, true, [0.04, 0.04, 0.035], 1000.0, blob(DARK_BROWN));
// A jelly dessert, 10 cm across, 7 cm tall.
thing!(JELLY: "jelly_dessert", "jelly", ["gelatin", "gelatine dessert", "jello", "jell-o", "gelatin dessert", "jelly pudding"], FOOD,
    "a wobbly moulded jelly dessert", ["dessert", "food"], Food @ OnSurface, true, [0.10, 0.10, 0.07], 1000.0,
    turned(DOME, RED));
// A soft pretzel, 12 × 10 × 3 cm.
thing!(PRETZEL: "pretzel", "pretzel", ["pretzels", "soft pretzel", "bretzel"], FOOD, "a knotted brown baked pretzel",
    ["snack", "baked goods", "food"], Food @ OnSurface, true, [0.12, 0.10, 0.03], 400.0, blob(BROWN));
// A brownie square, 7 × 7 × 3.5 cm.
thing!(BROWNIE: "brownie", "brownie", ["brownies", "chocolate brownie", "blondie", "traybake"], FOOD, "a square chocolate brownie",
    ["cake", "dessert", "food"], Food @ OnSurface, true, [0.07, 0.07, 0.035], 700.0, pack(DARK_BROWN, [0.35, 0.2, 0.12, 1.0]));
// A chilli pepper, 10 cm long.
thing!(CHILLI: "chilli", "chilli pepper", ["chili", "chile", "chili pepper", "jalapeno", "jalapeño", "red chilli", "hot pepper", "chillies", "chilies"], FOOD,
    "a long red chilli pepper with a green stalk", ["vegetable", "produce", "food"], Food @ OnSurface, true, [0.10, 0.02, 0.02], 800.0,
    Look::Blob { body: RED, accent: GREEN_C, stem: true });
// A whole fish, 30 × 9 × 5 cm (a mackerel).
thing!(WHOLE_FISH: "whole_fish", "fish", ["raw fish", "fish fillet", "mackerel", "trout", "sea bass", "salmon fillet", "fresh fish"], FOOD,
    "a whole raw fish with silver skin", ["seafood", "food"], Food @ OnSurface, true, [0.30, 0.09, 0.05], 1000.0, blob(SILVER));
// A candy cane, 15 cm.
thing!(CANDY_CANE: "candy_cane", "candy cane", ["candy canes", "peppermint stick", "christmas candy"], FOOD,
    "a red and white striped candy cane", ["sweet", "food"], Food @ OnSurface, true, [0.15, 0.04, 0.008], 1000.0,
    long(0.5, &[[0.95, 0.95, 0.95, 1.0]], RED_C));

// --- kitchen and table ---------------------------------------------------------------
// Glass ashtray, 12 cm across, 4 cm tall.
thing!(ASHTRAY: "ashtray", "ashtray", ["ash tray", "cigar ashtray"], HOME, "a round glass ashtray", ["dish", "tableware"],
    Tabletop @ OnSurface, true, [0.12, 0.12, 0.04], 900.0, turned(DISH, GLASS));
// Oval serving platter, 40 × 28 × 3 cm.
thing!(PLATTER: "platter", "serving platter", ["serving dish", "meat platter", "charger plate"], TABLEWARE,
    "a large flat serving platter", ["plate", "tableware", "dish"], Container @ OnSurface, true, [0.40, 0.28, 0.03], 700.0,
    flat(WHITE, [0.96, 0.96, 0.95, 1.0]));
// Kitchen storage canister, 12 cm across, 18 cm tall.
thing!(CANISTER: "canister", "kitchen canister", ["storage canister", "tea canister", "coffee canister", "sugar canister", "tea caddy", "storage tin"], HOME,
    "a round lidded kitchen storage canister", ["container", "kitchenware"], Container @ OnSurface, true, [0.12, 0.12, 0.18], 300.0,
    capped(CAN, &[[0.75, 0.77, 0.8, 1.0], [0.9, 0.9, 0.88, 1.0], [0.2, 0.35, 0.55, 1.0]], 0.88, 1.0, STEEL_C));
// Wall or counter spice rack, 40 × 10 × 30 cm.
thing!(SPICE_RACK: "spice_rack", "spice rack", ["spice shelf", "herb rack", "spice organizer", "spice organiser"], &["kitchen", "storage", "tabletop"],
    "a small wooden rack of shelves for spice jars", ["rack", "shelf", "storage"], Furniture @ OnSurface, false, [0.40, 0.10, 0.30], 250.0,
    Look::Table { top: 0.06, wood: WOODS, legs: WOOD_C, shelf: true });
// Champagne flute, 7 cm across, 23 cm tall.
thing!(CHAMPAGNE_FLUTE: "champagne_flute", "champagne flute", ["flute glass", "prosecco glass", "sparkling wine glass"], TABLEWARE,
    "a tall narrow stemmed champagne glass", ["glass", "glassware", "tableware"], Container @ OnSurface, true, [0.07, 0.07, 0.23], 200.0,
    turned(FLUTE, GLASS));
// Countertop ice maker, 38 × 45 × 40 cm (a 12 kg-a-day unit).
thing!(ICE_MAKER: "ice_maker", "ice maker", ["ice machine", "countertop ice maker", "ice cube maker"], &["kitchen", "appliance", "tabletop"],
    "a countertop ice maker with a lid on top", ["kitchen appliance", "appliance"], SmallAppliance @ OnSurface, false, [0.38, 0.45, 0.40], 180.0,
    appliance(&[[0.85, 0.86, 0.88, 1.0], [0.15, 0.15, 0.17, 1.0]], [0.3, 0.45, 0.6, 1.0], 2));
// Sachet of sugar or sauce, 10 × 7 × 1 cm.
thing!(SACHET: "sachet", "sachet", ["packet", "sugar sachet", "sauce sachet", "ketchup sachet", "sugar packet", "condiment packet"], PACKED,
    "a small sealed paper or foil sachet", ["package", "packaging"], Food @ OnSurface, true, [0.10, 0.07, 0.01], 300.0,
    pack(&[[0.9, 0.9, 0.88, 1.0], [0.85, 0.2, 0.15, 1.0], [0.95, 0.8, 0.2, 1.0]], [0.95, 0.95, 0.9, 1.0]));

// --- home, care and office -------------------------------------------------------------
// A folded handkerchief, 11 cm square.
thing!(HANDKERCHIEF: "handkerchief", "handkerchief", ["hanky", "hankie", "pocket square", "folded handkerchief"], &["home", "textile", "tabletop", "soft"],
    "a folded cotton handkerchief", ["textile", "linen"], Textile @ OnSurface, true, [0.11, 0.11, 0.008], 200.0,
    flat(WHITE, [0.75, 0.82, 0.92, 1.0]));
// A quilted pot holder, 20 cm square.
thing!(POT_HOLDER: "pot_holder", "pot holder", ["potholder", "oven glove", "oven mitt", "hot pad", "trivet mat", "oven gloves"], &["kitchen", "textile", "tabletop", "soft"],
    "a square quilted pot holder", ["textile", "kitchen linen"], Textile @ OnSurface, true, [0.20, 0.20, 0.01], 200.0,
    flat(FABRIC, [0.9, 0.85, 0.75, 1.0]));
// A spool of sewing thread, 3.5 cm across, 4.5 cm tall.
thing!(THREAD_SPOOL: "thread_spool", "spool of thread", ["thread", "bobbin", "cotton reel", "reel of thread", "sewing thread"], HOME,
    "a spool wound with sewing thread", ["sewing supplies"], HandHeld @ OnSurface, true, [0.035, 0.035, 0.045], 600.0,
    turned(SPOOL, BRIGHTS));
// Banknotes, a folded wad, 15.6 × 6.6 × 1 cm.
thing!(BANKNOTES: "banknotes", "banknotes", ["money", "dollar", "dollars", "cash", "banknote", "bank note", "wad of cash", "dollar bill", "paper money", "stack of money"], HOME,
    "a small stack of paper banknotes", ["money"], HandHeld @ OnSurface, true, [0.156, 0.066, 0.01], 800.0,
    flat(MONEY, [0.9, 0.92, 0.85, 1.0]));
// A coin, 2.4 cm across (a 25-cent or £1 coin), 3 mm thick.
thing!(COIN: "coin", "coin", ["coins", "penny", "pound coin", "euro coin"], HOME, "a round metal coin",
    ["money"], HandHeld @ OnSurface, true, [0.024, 0.024, 0.003], 7000.0, turned(DISC, &[[0.8, 0.65, 0.3, 1.0], [0.72, 0.72, 0.74, 1.0]]));
// A bead, 12 mm.
thing!(BEAD: "bead", "bead", ["beads", "glass bead", "wooden bead"], HOME, "a small round bead", ["craft supplies"],
    HandHeld @ OnSurface, true, [0.012, 0.012, 0.012], 1500.0, blob(BRIGHTS));
// A seashell, 8 × 6 × 4 cm.
thing!(SEASHELL: "seashell", "seashell", ["shell", "sea shell", "conch", "conch shell", "scallop shell", "cockle shell"], &["home", "decor", "tabletop", "small", "graspable"],
    "a ridged seashell", ["decoration", "ornament"], Tabletop @ OnSurface, true, [0.08, 0.06, 0.04], 900.0, blob(SHELL));
// A baby's dummy, 6 × 4.5 × 5 cm.
thing!(PACIFIER: "pacifier", "pacifier", ["soother", "baby dummy", "binky"], HOME, "a baby's pacifier with a ring handle",
    ["baby product"], HandHeld @ OnSurface, true, [0.06, 0.045, 0.05], 400.0,
    Look::Blob { body: &[[0.7, 0.85, 0.95, 1.0], [0.95, 0.75, 0.8, 1.0]], accent: WHITE_C, stem: true });
// A clipboard, 23 × 32 × 2 cm (A4).
thing!(CLIPBOARD: "clipboard", "clipboard", ["clip board", "clipboard with paper", "writing board"], OFFICE,
    "a hardboard clipboard with a steel clip and a sheet of paper", ["stationery", "office supplies"], HandHeld @ OnSurface, true, [0.23, 0.32, 0.02], 600.0,
    flat(&[[0.55, 0.38, 0.2, 1.0], [0.1, 0.1, 0.12, 1.0]], WHITE_C));
// A booklet, A5: 14.8 × 21 × 0.5 cm.
thing!(BOOKLET: "booklet", "booklet", ["instruction manual"], OFFICE,
    "a thin stapled booklet", ["paper", "document"], HandHeld @ OnSurface, true, [0.148, 0.21, 0.005], 700.0,
    flat(BRIGHTS, WHITE_C));
// A passport, 12.5 × 8.8 × 0.6 cm.
thing!(PASSPORT: "passport", "passport", ["passport book", "travel document"], OFFICE, "a passport with a dark cover",
    ["document"], HandHeld @ OnSurface, true, [0.125, 0.088, 0.006], 700.0, flat(BURGUNDY, GOLD_C));
// A till receipt, 8 × 15 cm.
thing!(RECEIPT: "receipt", "receipt", ["till receipt", "sales receipt", "invoice"], OFFICE, "a strip of printed paper receipt",
    ["paper", "document"], HandHeld @ OnSurface, true, [0.08, 0.15, 0.005], 300.0, flat(WHITE, [0.8, 0.8, 0.8, 1.0]));
// A painter's palette, 30 × 22 cm.
thing!(PALETTE: "paint_palette", "paint palette", ["artist's palette", "painter's palette", "mixing palette"], OFFICE,
    "a wooden painter's palette with dabs of paint", ["art supplies"], HandHeld @ OnSurface, true, [0.30, 0.22, 0.006], 600.0,
    flat(WOODS, [0.85, 0.25, 0.2, 1.0]));
// A VHS cassette, 18.7 × 10.3 × 2.5 cm.
thing!(VIDEOTAPE: "videotape", "videotape", ["vhs tape", "vhs", "video cassette", "video tape", "vhs cassette"], AUDIO,
    "a black video cassette with a label", ["media"], HandHeld @ OnSurface, true, [0.187, 0.103, 0.025], 500.0, pack(BLACKS, WHITE_C));
// A 12-inch vinyl record in its sleeve, 31.5 cm square.
thing!(VINYL_RECORD: "vinyl_record", "vinyl record", ["phonograph record", "lp", "vinyl", "gramophone record", "record sleeve"], AUDIO,
    "a 12-inch vinyl record in a printed sleeve", ["media"], HandHeld @ OnSurface, true, [0.315, 0.315, 0.006], 700.0,
    flat(BRIGHTS, BLACK_C));
// A razor blade, 4.3 × 2.2 cm.
thing!(RAZOR_BLADE: "razor_blade", "razor blade", ["razorblade", "safety razor blade", "utility blade"], CARE,
    "a thin steel double-edged razor blade", ["blade"], HandHeld @ OnSurface, true, [0.043, 0.022, 0.003], 3000.0, flat(SILVER, STEEL_C));
// A 500 ml bottle of mouthwash, 9 × 6 × 22 cm.
thing!(MOUTHWASH: "mouthwash", "mouthwash", ["mouthwash bottle", "gargle", "mouth rinse", "bottle of mouthwash", "listerine"], CARE,
    "a bottle of mouthwash with a cap", ["bottle", "toiletry"], Container @ OnSurface, true, [0.09, 0.06, 0.22], 700.0,
    capped(BOTTLE, &[[0.2, 0.55, 0.45, 1.0], [0.25, 0.4, 0.8, 1.0]], 0.85, 0.45, WHITE_C));
// A can of shaving foam, 6.5 cm across, 19 cm tall.
thing!(SHAVING_CREAM: "shaving_cream", "shaving cream", ["shaving foam", "shaving gel", "can of shaving foam", "shave gel"], CARE,
    "an aerosol can of shaving foam", ["toiletry", "can"], Container @ OnSurface, true, [0.065, 0.065, 0.19], 400.0,
    capped(CAN, &[[0.2, 0.35, 0.7, 1.0], [0.85, 0.85, 0.88, 1.0]], 0.85, 0.9, WHITE_C));
// A lip balm stick, 1.6 cm across, 7 cm tall.
thing!(LIP_BALM: "lip_balm", "lip balm", ["chapstick", "lip salve", "lip balm stick", "lip gloss"], CARE, "a small stick of lip balm",
    ["cosmetic", "toiletry"], HandHeld @ OnSurface, true, [0.016, 0.016, 0.07], 900.0,
    capped(CAN, &[[0.25, 0.45, 0.8, 1.0], [0.9, 0.9, 0.88, 1.0]], 0.6, 1.0, WHITE_C));
// A perfume bottle, 7 × 4 × 10 cm (50 ml).
thing!(PERFUME: "perfume", "perfume bottle", ["cologne", "eau de toilette", "fragrance", "scent bottle", "aftershave"], CARE,
    "a glass perfume bottle with a cap", ["bottle", "cosmetic"], Container @ OnSurface, true, [0.07, 0.04, 0.10], 900.0,
    pack(&[[0.9, 0.8, 0.55, 1.0], [0.8, 0.85, 0.9, 1.0]], GOLD_C));
// A dental floss dispenser, 5 × 1.5 × 5 cm.
thing!(DENTAL_FLOSS: "dental_floss", "dental floss", ["floss", "tooth floss", "flossers"], CARE, "a small dental floss dispenser",
    ["toiletry"], HandHeld @ OnSurface, true, [0.05, 0.015, 0.05], 600.0, pack(WHITE, [0.3, 0.6, 0.8, 1.0]));
// An adhesive plaster, 7.2 × 1.9 cm.
thing!(PLASTER: "adhesive_bandage", "plaster", ["band-aid", "band aid", "bandaid", "sticking plaster", "elastoplast"], CARE,
    "a small adhesive plaster with a pad", ["first aid"], HandHeld @ OnSurface, true, [0.072, 0.019, 0.003], 800.0,
    flat(&[[0.85, 0.65, 0.5, 1.0]], [0.95, 0.9, 0.85, 1.0]));
// A roll of crepe bandage, 7.5 cm wide roll, 5 cm across.
thing!(BANDAGE: "bandage", "bandage", ["bandage roll", "crepe bandage", "gauze", "gauze roll", "roll of bandage", "elastic bandage"], CARE,
    "a rolled cotton bandage", ["first aid"], HandHeld @ OnSurface, true, [0.05, 0.05, 0.075], 400.0, turned(CAN, CREAM));
// An air freshener aerosol, 6.5 cm across, 20 cm tall.
thing!(AIR_FRESHENER: "air_freshener", "air freshener", ["freshener", "room spray", "air spray", "room freshener", "plug-in air freshener"], HOME,
    "an aerosol can of air freshener", ["can", "cleaning product"], Container @ OnSurface, true, [0.065, 0.065, 0.20], 400.0,
    capped(CAN, &[[0.55, 0.3, 0.65, 1.0], [0.3, 0.65, 0.4, 1.0]], 0.85, 0.9, WHITE_C));
// A cigarette case, 9 × 6 × 1.5 cm.
thing!(CIGARETTE_CASE: "cigarette_case", "cigarette case", ["cigarette box", "pack of cigarettes", "cigarettes", "cigarette pack", "cigar box"], HOME,
    "a flat metal cigarette case", ["case"], HandHeld @ OnSurface, true, [0.09, 0.06, 0.015], 700.0, pack(SILVER, STEEL_C));
// A thumbtack, 1.1 cm head, 1 cm tall.
thing!(THUMBTACK: "thumbtack", "thumbtack", ["drawing pin", "push pin", "pushpin", "tack", "thumb tack"], OFFICE,
    "a drawing pin with a round head", ["office supplies", "fastener"], HandHeld @ OnSurface, true, [0.011, 0.011, 0.01], 2000.0,
    capped(DISC, BRIGHTS, 0.35, 0.15, STEEL_C));
// A binder clip, 3.2 × 2 × 2.5 cm.
thing!(BINDER_CLIP: "binder_clip", "binder clip", ["clip", "bulldog clip", "foldback clip", "fold-back clip", "paper clamp", "bag clip"], OFFICE,
    "a black steel binder clip with wire handles", ["office supplies", "fastener"], HandHeld @ OnSurface, true, [0.032, 0.02, 0.025], 1500.0,
    Look::Case { body: BLACKS, handle: STEEL_C, handle_h: 0.4 });
// A yardstick, 1 m × 3 cm × 6 mm.
thing!(YARDSTICK: "yardstick", "yardstick", ["measuring stick", "metre stick", "meter stick", "metre rule", "meter rule", "measuring rod"], OFFICE,
    "a long wooden measuring stick with a scale", ["measuring tool"], HandHeld @ OnSurface, true, [1.0, 0.03, 0.008], 600.0,
    long(0.02, WOODS, [0.9, 0.8, 0.5, 1.0]));
// A walking stick, 90 cm.
thing!(WALKING_STICK: "walking_stick", "walking stick", ["walking cane", "cane", "hiking stick", "walking pole"], HOME,
    "a wooden walking stick with a curved handle", ["mobility aid"], HandHeld @ OnSurface, true, [0.90, 0.10, 0.03], 500.0,
    long(0.12, DARK_BROWN, [0.45, 0.3, 0.15, 1.0]));
// A fire poker, 70 cm.
thing!(FIRE_POKER: "fire_poker", "fire poker", ["poker", "fireplace poker", "fire iron", "fireplace tools", "companion set"], HOME,
    "a black iron fire poker", ["fireplace tool", "tool"], HandHeld @ OnSurface, true, [0.70, 0.05, 0.03], 900.0,
    long(0.15, BLACKS, [0.15, 0.15, 0.16, 1.0]));
// A long gas lighter, 27 cm.
thing!(UTILITY_LIGHTER: "utility_lighter", "utility lighter", ["igniter", "barbecue lighter", "bbq lighter", "long lighter", "candle lighter", "gas igniter", "stove lighter"], HOME,
    "a long-nosed gas lighter", ["lighter", "tool"], HandHeld @ OnSurface, true, [0.27, 0.03, 0.025], 500.0,
    long(0.45, BRIGHTS, STEEL_C));
// A pocket knife, 10 cm folded.
thing!(POCKET_KNIFE: "pocket_knife", "pocket knife", ["pocketknife", "penknife", "pen knife", "swiss army knife", "folding knife", "jackknife", "multitool"], HOME,
    "a folded pocket knife with a red handle", ["knife", "tool"], HandHeld @ OnSurface, true, [0.10, 0.025, 0.018], 1500.0,
    long(0.8, &[[0.8, 0.1, 0.1, 1.0], [0.2, 0.2, 0.22, 1.0]], STEEL_C));
// A camera lens, 7.5 cm across, 10 cm long.
thing!(CAMERA_LENS: "camera_lens", "camera lens", ["lens", "zoom lens", "telephoto lens", "prime lens", "dslr lens"], &["home", "electronics", "tabletop", "small", "graspable"],
    "a black camera lens standing on its mount", ["camera accessory", "electronics"], HandHeld @ OnSurface, true, [0.075, 0.075, 0.10], 700.0,
    capped(CAN, BLACKS, 0.9, 0.9, [0.3, 0.3, 0.35, 1.0]));
// A whistle, 5 × 2 × 2.5 cm.
thing!(WHISTLE: "whistle", "whistle", ["referee whistle", "sports whistle", "pea whistle", "coach whistle"], HOME,
    "a metal pea whistle", ["signal device"], HandHeld @ OnSurface, true, [0.05, 0.02, 0.025], 1000.0, long(0.35, SILVER, STEEL_C));
// A cowbell, 12 × 8 × 15 cm.
thing!(COWBELL: "cowbell", "cowbell", ["cow bell", "alpine bell", "swiss cow bell"], &["home", "music", "instrument", "tabletop"],
    "a metal cowbell", ["bell", "musical instrument"], Tabletop @ OnSurface, true, [0.12, 0.08, 0.15], 500.0, turned(BELL, METAL));

// --- audio and larger things -------------------------------------------------------------
// A hi-fi stereo system, 45 × 30 × 20 cm.
thing!(STEREO: "stereo", "stereo", ["stereo system", "hi-fi", "hifi", "sound system", "boombox", "ghetto blaster", "music system", "mini hi-fi", "speaker system", "hi-fi system"], AUDIO,
    "a stereo system with a display, knobs and a CD tray", ["audio device", "electronics"], SmallAppliance @ OnSurface, false, [0.45, 0.30, 0.20], 300.0,
    appliance(BLACKS, [0.2, 0.35, 0.45, 1.0], 3));
// A CD player, 43 × 30 × 9 cm (a full-width hi-fi unit).
thing!(CD_PLAYER: "cd_player", "CD player", ["compact disc player", "disc player", "dvd player", "blu-ray player", "cd deck"], AUDIO,
    "a hi-fi CD player with a disc tray", ["audio device", "electronics"], SmallAppliance @ OnSurface, false, [0.43, 0.30, 0.09], 300.0,
    Look::Appliance { body: &[[0.15, 0.15, 0.16, 1.0], [0.7, 0.72, 0.74, 1.0]], front: BLACK_C, door: [-0.4, 0.1, 0.55, 0.75], knobs: 2, top: true });
// A guitar amplifier, 45 × 25 × 40 cm (a 30 W combo).
thing!(AMPLIFIER: "amplifier", "amplifier", ["amp", "guitar amp", "guitar amplifier", "bass amp", "combo amp", "hi-fi amplifier", "amplifier speaker"], &["home", "music", "electronics"],
    "a guitar amplifier: a speaker grille and a row of knobs", ["audio device", "electronics"], SmallAppliance @ Floor, false, [0.45, 0.25, 0.40], 250.0,
    Look::Appliance { body: BLACKS, front: [0.25, 0.22, 0.2, 1.0], door: [-0.42, 0.42, 0.08, 0.78], knobs: 5, top: true });
// A standing spotlight on a tripod, 40 × 40 × 160 cm.
thing!(SPOTLIGHT: "spotlight", "spotlight", ["spot light", "stage light", "studio light", "spot lamp", "floodlight", "flood light"], &["home", "lighting", "studio"],
    "a spotlight head on a tall stand", ["lamp", "lighting"], SmallAppliance @ Floor, false, [0.40, 0.40, 1.60], 40.0,
    Look::Stand { foot: BLACK_C, pole: STEEL_C, head: BLACKS, head_h: 0.15 });
// A bird cage, 35 cm across, 50 cm tall.
thing!(BIRDCAGE: "birdcage", "birdcage", ["bird cage", "parrot cage", "budgie cage", "pet cage"], &["home", "pet", "decor"],
    "a round domed wire bird cage", ["cage", "pet supplies"], Container @ OnSurface, false, [0.35, 0.35, 0.50], 60.0,
    turned(CAGE, &[[0.85, 0.85, 0.82, 1.0], [0.8, 0.65, 0.3, 1.0]]));
// A hanging bird feeder, 15 cm across, 30 cm tall.
thing!(BIRDFEEDER: "birdfeeder", "bird feeder", ["seed feeder", "nut feeder"], &["garden", "pet", "tabletop"],
    "a tube bird feeder with a roof", ["pet supplies", "garden"], Tabletop @ OnSurface, true, [0.15, 0.15, 0.30], 150.0,
    capped(CAN, GLASS, 0.8, 1.0, GREEN_C));
// A garden bird bath, 50 cm across, 70 cm tall.
thing!(BIRDBATH: "birdbath", "bird bath", ["garden bird bath", "bird bath bowl"], &["garden", "outdoor"],
    "a stone bird bath: a bowl on a pedestal", ["garden ornament"], Fixture @ Floor, false, [0.50, 0.50, 0.70], 400.0,
    Look::Stand { foot: [0.7, 0.68, 0.64, 1.0], pole: [0.7, 0.68, 0.64, 1.0], head: &[[0.75, 0.73, 0.7, 1.0]], head_h: 0.18 });
// A pine cone, 6 cm across, 9 cm tall.
thing!(PINECONE: "pinecone", "pine cone", ["fir cone", "pine cones", "conifer cone"], &["home", "decor", "tabletop", "small", "graspable"],
    "a brown woody pine cone", ["decoration", "natural object"], Tabletop @ OnSurface, true, [0.06, 0.06, 0.09], 400.0,
    turned(CONE_EGG, BROWN));
// A manger or feeding trough, 120 × 50 × 50 cm.
thing!(MANGER: "manger", "manger", ["feeding trough", "trough", "feed trough"], &["farm", "agriculture"],
    "a wooden feeding trough on legs", ["container", "farm equipment"], Container @ Floor, false, [1.20, 0.50, 0.50], 200.0,
    Look::Table { top: 0.45, wood: WOODS, legs: WOOD_C, shelf: false });
// A leather pouch, 20 × 5 × 13 cm.
thing!(POUCH: "pouch", "pouch", ["zip pouch", "zipper pouch", "cosmetic bag", "toiletry bag", "wash bag"], &["home", "bag", "graspable"],
    "a small zipped fabric pouch", ["bag", "case"], HandHeld @ OnSurface, true, [0.20, 0.05, 0.13], 200.0,
    Look::Bag { body: LEATHER, strap: BLACK_C, body_h: 0.9 });
// A gift wrap roll, 76 cm long, 7 cm across.
thing!(GIFT_WRAP: "gift_wrap", "gift wrap", ["wrapping paper", "roll of wrapping paper", "gift wrapping", "wrapping paper roll", "christmas wrapping paper"], HOME,
    "a roll of printed gift wrapping paper", ["paper", "craft supplies"], HandHeld @ OnSurface, true, [0.76, 0.07, 0.07], 150.0,
    long(0.03, BRIGHTS, [0.85, 0.2, 0.3, 1.0]));

// --- things drawn by an existing family's builder ------------------------------------------
// A child's high chair: IKEA ANTILOP 58 × 62 × 90 cm, seat at about 58 cm.
pub(crate) const HIGH_CHAIR: crate::Category = crate::Category {
    name: "high_chair",
    display: "highchair",
    synonyms: &["baby high chair", "baby chair", "feeding chair", "child's high chair", "toddler chair"],
    tags: &["furniture", "seating", "home", "kitchen"],
    description: "a child's high chair: a seat with a backrest raised on long legs",
    is_a: &["chair", "seat", "furniture"],
    params: &[
        crate::ParamDef::new("width", 0.58, 0.45, 0.7, 0.05, "along X"),
        crate::ParamDef::new("depth", 0.62, 0.5, 0.7, 0.05, "along Y, backrest included"),
        crate::ParamDef::new("height", 0.90, 0.8, 1.1, 0.05, "floor to the top of the backrest"),
        crate::ParamDef::new("seat_height", 0.58, 0.5, 0.65, 0.04, "floor to the top of the seat"),
        crate::ParamDef::new("leg", 0.03, 0.02, 0.04, 0.1, "leg section"),
    ],
    ..super::super::furniture::CHAIR
};
// A child's tricycle, 70 × 50 × 60 cm (drawn as a small cycle).
like!(TRICYCLE: "tricycle", "tricycle", ["trike", "kids tricycle", "children's tricycle", "toddler trike"],
    &["home", "toy", "outdoor"], "a child's tricycle: wheels, a small frame, a saddle and handlebars", ["cycle", "ride-on toy", "toy"],
    Toy @ Floor, false, [0.70, 0.50, 0.60], super::super::tools::build_bicycle);
