//! Household things from the public lists: kitchenware and table linen, cleaning, bathroom
//! and fixtures, decoration and lighting, bags and cases. Sizes from published product
//! ranges, noted per line.

use super::{
    BLACK_C, BLACKS, BOTTLE, BRIGHTS, CAN, DOME, FABRIC, LEATHER, Look, METAL, STEEL_C, URN, WHITE, WHITE_C, WOOD_C,
    WOODS, thing,
};

type Rgba = [f32; 4];

const UTENSIL: &[&str] = &["kitchen", "utensil", "tabletop", "small", "graspable"];
const TABLEWARE: &[&str] = &["kitchen", "tableware", "tabletop", "small", "graspable"];
const LINEN: &[&str] = &["home", "textile", "tabletop", "soft"];
const HOME: &[&str] = &["home", "tabletop", "small", "graspable"];
const DECOR: &[&str] = &["home", "decor", "tabletop"];
const BATH: &[&str] = &["bathroom", "fixture", "plumbing"];
const BAGS: &[&str] = &["home", "bag", "luggage", "graspable"];

const GOLD: Rgba = [0.85, 0.68, 0.25, 1.0];
const BRASS: &[Rgba] = &[[0.8, 0.62, 0.28, 1.0], [0.72, 0.55, 0.25, 1.0]];
const STONE: &[Rgba] = &[[0.8, 0.78, 0.74, 1.0], [0.6, 0.6, 0.58, 1.0], [0.3, 0.3, 0.32, 1.0]];
const PASTEL: &[Rgba] =
    &[[0.85, 0.9, 0.95, 1.0], [0.95, 0.88, 0.8, 1.0], [0.88, 0.95, 0.88, 1.0], [0.95, 0.95, 0.93, 1.0]];
const GLASSY: &[Rgba] = &[[0.85, 0.9, 0.92, 1.0]];
const BULB: &[[f64; 2]] = &[[0.0, 0.0], [0.3, 0.0], [0.3, 0.3], [0.7, 0.45], [1.0, 0.7], [0.85, 0.92], [0.0, 1.0]];
/// Flowers: a round head of blooms above a narrow bunch of stems.
const BOUQUET_SHAPE: &[[f64; 2]] =
    &[[0.0, 0.0], [0.12, 0.0], [0.12, 0.4], [0.8, 0.55], [1.0, 0.75], [0.7, 0.95], [0.0, 1.0]];
const BELL_CURVE: &[[f64; 2]] =
    &[[0.0, 0.0], [1.0, 0.0], [0.8, 0.2], [0.55, 0.6], [0.5, 0.85], [0.15, 0.9], [0.12, 1.0], [0.0, 1.0]];
const HAT_CROWN: &[[f64; 2]] = &[[0.0, 0.0], [1.0, 0.0], [1.0, 0.08], [0.6, 0.1], [0.58, 0.9], [0.45, 1.0], [0.0, 1.0]];

const fn long(grip: f64, handle: &'static [Rgba], head: Rgba) -> Look {
    Look::Long { grip, grip_w: 0.35, grip_h: 0.6, handle, head }
}
const fn flat(body: &'static [Rgba], panel: Rgba) -> Look {
    Look::Flat { body, panel }
}

// --- kitchenware and table linen ----------------------------------------------------
// Kitchen tongs, 24 cm (OXO 9-inch).
thing!(TONGS: "tongs", "tongs", ["kitchen tongs", "salad tongs", "serving tongs", "pair of tongs", "tong"], UTENSIL,
    "a pair of sprung metal kitchen tongs", ["kitchen utensil", "utensil"], HandHeld @ OnSurface, true, [0.24, 0.04, 0.03], 300.0,
    long(0.45, BLACKS, STEEL_C));
// Chopsticks, 24 cm.
thing!(CHOPSTICKS: "chopsticks", "chopsticks", ["chopstick", "pair of chopsticks"], TABLEWARE, "a pair of thin wooden chopsticks",
    ["cutlery", "utensil"], HandHeld @ OnSurface, true, [0.24, 0.02, 0.008], 600.0, long(0.5, WOODS, WOOD_C));
// Pizza cutter wheel, 20 cm.
thing!(PIZZA_CUTTER: "pizza_cutter", "pizza cutter", ["pizza wheel"], UTENSIL, "a round steel cutting wheel on a handle",
    ["kitchen utensil", "utensil"], HandHeld @ OnSurface, true, [0.20, 0.07, 0.025], 400.0, long(0.6, BLACKS, STEEL_C));
// Box grater, 10 × 8 × 24 cm.
thing!(CHEESE_GRATER: "cheese_grater", "cheese grater", ["grater", "box grater"], UTENSIL, "a four-sided steel box grater with a handle on top",
    ["kitchen utensil", "utensil"], HandHeld @ OnSurface, true, [0.10, 0.08, 0.24], 200.0,
    Look::Case { body: METAL, handle: BLACK_C, handle_h: 0.12 });
// Half-sheet baking tray, 43 × 30 × 2 cm.
thing!(BAKING_SHEET: "baking_sheet", "baking sheet", ["baking tray", "cookie sheet", "oven tray", "sheet pan", "roasting tray"],
    &["kitchen", "cookware", "tabletop"], "a flat rimmed metal baking sheet", ["cookware", "tray"], Container @ OnSurface, true,
    [0.43, 0.30, 0.02], 300.0, flat(METAL, [0.5, 0.5, 0.52, 1.0]));
// Glass pan lid, 26 cm.
thing!(PAN_LID: "pan_lid", "pan lid", ["pot lid", "saucepan lid", "skillet lid", "frying pan lid"], UTENSIL,
    "a round glass pan lid with a knob", ["cookware"], HandHeld @ OnSurface, true, [0.26, 0.26, 0.05], 300.0,
    Look::Turned { profile: DOME, body: GLASSY, top: 0.75, cap_r: 0.15, cap: BLACK_C });
// Stovetop whistling kettle, 22 × 20 × 22 cm.
thing!(STOVETOP_KETTLE: "stovetop_kettle", "stovetop kettle", ["teakettle", "whistling kettle", "hob kettle", "kettle non electric"],
    &["kitchen", "cookware", "tabletop"], "a round steel kettle heated on the hob, with a spout and a handle",
    ["kettle", "cookware"], Tabletop @ OnSurface, true, [0.22, 0.22, 0.22], 150.0,
    Look::Turned { profile: URN, body: METAL, top: 0.85, cap_r: 0.3, cap: BLACK_C });
// Food storage box, 18 × 12 × 7 cm (1 l).
thing!(FOOD_CONTAINER: "food_container", "food container", ["tupperware", "lunch box", "lunchbox", "plastic food container", "food storage container", "sandwich box"],
    TABLEWARE, "a clear plastic food storage box with a coloured lid", ["container", "kitchenware"], Container @ OnSurface, true,
    [0.18, 0.12, 0.07], 150.0, Look::Pack { body: GLASSY, band: [0.2, 0.45, 0.8, 1.0] });
// Kitchen foil roll, 32 cm box.
thing!(KITCHEN_FOIL: "kitchen_foil", "kitchen foil", ["aluminum foil", "aluminium foil", "tin foil", "tinfoil", "foil roll", "roll of foil"],
    UTENSIL, "a long box holding a roll of aluminium foil", ["kitchenware"], HandHeld @ OnSurface, true, [0.32, 0.05, 0.05], 300.0,
    Look::Pack { body: &[[0.75, 0.77, 0.8, 1.0]], band: [0.2, 0.3, 0.7, 1.0] });
// Drinking straw, 21 cm × 6 mm.
thing!(DRINKING_STRAW: "drinking_straw", "drinking straw", ["straw", "paper straw", "plastic straw"], TABLEWARE, "a thin drinking straw",
    ["tableware"], HandHeld @ OnSurface, true, [0.21, 0.007, 0.007], 300.0, long(0.5, BRIGHTS, [0.95, 0.95, 0.95, 1.0]));
// Barbecue skewer, 30 cm.
thing!(SKEWER: "skewer", "skewer", ["kebab skewer", "bbq skewer", "kebab stick"], UTENSIL, "a long thin metal or bamboo skewer",
    ["kitchen utensil", "utensil"], HandHeld @ OnSurface, true, [0.30, 0.008, 0.008], 600.0, long(0.2, WOODS, STEEL_C));
// Cork-backed placemat, 45 × 33 × 0.6 cm. (Thinner and lighter, its box's inertia written
// to six decimals no longer satisfies A + B ≥ C: MuJoCo refuses it.)
thing!(PLACEMAT: "placemat", "placemat", ["place mat", "table mat"], LINEN, "a flat rectangular table placemat",
    ["table linen", "textile"], Textile @ OnSurface, true, [0.45, 0.33, 0.006], 600.0, flat(FABRIC, [0.9, 0.88, 0.8, 1.0]));
// Folded napkin, 20 cm square.
thing!(NAPKIN: "napkin", "napkin", ["serviette", "paper napkin", "table napkin", "cloth napkin"], LINEN, "a folded square napkin",
    ["table linen", "textile"], Textile @ OnSurface, true, [0.20, 0.20, 0.01], 300.0, flat(PASTEL, [0.95, 0.95, 0.95, 1.0]));
// Drinks coaster, 10 cm.
thing!(COASTER: "coaster", "coaster", ["drink coaster", "drinks mat", "beer mat", "cup coaster"], LINEN, "a flat square drinks coaster",
    ["tableware"], Tabletop @ OnSurface, true, [0.10, 0.10, 0.006], 600.0, flat(WOODS, [0.3, 0.3, 0.32, 1.0]));
// Kitchen timer (YCB 076_timer), 7 × 7 × 6 cm.
thing!(KITCHEN_TIMER: "kitchen_timer", "kitchen timer", ["timer", "cooking timer"], UTENSIL, "a small round wind-up kitchen timer",
    ["timer", "kitchen utensil"], Tabletop @ OnSurface, true, [0.07, 0.07, 0.06], 400.0,
    Look::Turned { profile: DOME, body: BRIGHTS, top: 0.85, cap_r: 0.3, cap: WHITE_C });
// Cool box, 30 l: 50 × 33 × 35 cm.
thing!(COOL_BOX: "cool_box", "cool box", ["cooler", "cooler box", "ice chest", "picnic cooler", "esky"], &["home", "container", "outdoor", "storage"],
    "an insulated plastic cool box with a carrying handle", ["container", "box"], Container @ OnSurface, true, [0.50, 0.33, 0.35], 60.0,
    Look::Case { body: &[[0.15, 0.35, 0.7, 1.0], [0.8, 0.15, 0.12, 1.0]], handle: WHITE_C, handle_h: 0.12 });
// Bleach bottle (YCB 021_bleach_cleanser): 10 × 7 × 25 cm.
thing!(BLEACH_BOTTLE: "bleach_bottle", "bleach bottle", ["bleach", "bleach cleanser", "household bleach"],
    &["home", "cleaning", "tabletop", "small", "graspable"], "a white plastic bottle of bleach with a child-proof cap",
    ["bottle", "cleaning product"], Tabletop @ OnSurface, true, [0.10, 0.07, 0.25], 800.0,
    Look::Turned { profile: BOTTLE, body: WHITE, top: 0.9, cap_r: 0.4, cap: [0.2, 0.4, 0.85, 1.0] });

// --- bathroom and fixtures ----------------------------------------------------------
// Mixer tap, 6 × 20 × 30 cm.
thing!(FAUCET: "faucet", "faucet", ["tap", "mixer tap", "kitchen tap", "bathroom tap", "basin tap", "spigot"], BATH,
    "a chrome tap with a curved spout", ["plumbing fixture", "fixture"], Fixture @ OnSurface, false, [0.06, 0.22, 0.30], 3000.0,
    Look::Stand { foot: STEEL_C, pole: STEEL_C, head: METAL, head_h: 0.18 });
// Hand shower head, 25 cm.
thing!(SHOWER_HEAD: "shower_head", "shower head", ["showerhead", "shower rose", "hand shower"], &["bathroom", "plumbing", "graspable"],
    "a chrome hand shower head", ["plumbing fixture"], HandHeld @ OnSurface, true, [0.25, 0.11, 0.04], 300.0, long(0.55, METAL, STEEL_C));
// Wall urinal, 38 × 35 × 60 cm.
thing!(URINAL: "urinal", "urinal", ["wall urinal", "urinal bowl"], BATH, "a white ceramic wall urinal",
    ["sanitary ware", "fixture"], Fixture @ AgainstWall, false, [0.38, 0.35, 0.60], 300.0,
    Look::Appliance { body: WHITE, front: [0.85, 0.86, 0.86, 1.0], door: [-0.35, 0.35, 0.1, 0.7], knobs: 0, top: false });
// Light bulb, A60: 6 cm across, 11 cm tall.
thing!(LIGHT_BULB: "light_bulb", "light bulb", ["lightbulb", "bulb", "led bulb"], HOME, "a pear-shaped light bulb on its screw base",
    ["lamp part", "electrical"], Tabletop @ OnSurface, true, [0.06, 0.06, 0.11], 200.0,
    Look::Turned { profile: BULB, body: &[[0.95, 0.95, 0.9, 1.0]], top: 1.0, cap_r: 1.0, cap: STEEL_C });

// --- decoration ---------------------------------------------------------------------
// Candlestick, 10 cm foot, 15 cm tall.
thing!(CANDLESTICK: "candlestick", "candlestick", ["candle holder", "candle stick", "candleholder"], DECOR,
    "a turned brass candlestick", ["decoration", "holder"], Tabletop @ OnSurface, true, [0.10, 0.10, 0.15], 400.0,
    Look::Turned { profile: URN, body: BRASS, top: 1.0, cap_r: 1.0, cap: GOLD });
// Bouquet of cut flowers, 25 × 25 × 45 cm.
thing!(BOUQUET: "bouquet", "bouquet", ["bunch of flowers", "flowers", "flower arrangement", "cut flowers"], DECOR,
    "a bunch of cut flowers", ["decoration", "plant"], Plant @ OnSurface, true, [0.25, 0.25, 0.45], 100.0,
    Look::Turned { profile: BOUQUET_SHAPE, body: BRIGHTS, top: 1.0, cap_r: 1.0, cap: WHITE_C });
// Statue / figurine, 15 × 15 × 35 cm.
thing!(STATUE: "statue", "statue", ["sculpture", "statuette", "bust"], DECOR, "a small stone statue on a plinth",
    ["decoration", "ornament"], Tabletop @ OnSurface, true, [0.15, 0.15, 0.35], 1500.0,
    Look::Turned { profile: URN, body: STONE, top: 1.0, cap_r: 1.0, cap: WHITE_C });
// Hand bell, 10 cm across, 13 cm tall.
thing!(BELL: "bell", "bell", ["hand bell", "handbell", "school bell", "brass bell"], DECOR, "a brass hand bell with a handle",
    ["decoration", "instrument"], Tabletop @ OnSurface, true, [0.10, 0.10, 0.13], 800.0,
    Look::Turned { profile: BELL_CURVE, body: BRASS, top: 1.0, cap_r: 1.0, cap: GOLD });
// Desk flag on a stand, 20 × 10 × 45 cm.
thing!(FLAG: "flag", "flag", ["desk flag", "table flag", "flag on a stand"], DECOR, "a small cloth flag on a pole in a round base",
    ["decoration"], Tabletop @ OnSurface, true, [0.20, 0.10, 0.45], 100.0,
    Look::Stand { foot: BLACK_C, pole: STEEL_C, head: BRIGHTS, head_h: 0.35 });
// Fridge magnet, 5 cm.
thing!(FRIDGE_MAGNET: "fridge_magnet", "fridge magnet", ["refrigerator magnet"], HOME, "a small flat fridge magnet",
    ["decoration", "magnet"], Tabletop @ OnSurface, true, [0.05, 0.05, 0.01], 2000.0, flat(BRIGHTS, WHITE_C));
// Medal, 7 cm.
thing!(MEDAL: "medal", "medal", ["medallion", "gold medal"], DECOR, "a round metal medal on a ribbon",
    ["award"], Tabletop @ OnSurface, true, [0.07, 0.07, 0.005], 3000.0, flat(BRASS, [0.2, 0.3, 0.7, 1.0]));
// Nesting box for birds, 20 × 20 × 30 cm.
thing!(BIRDHOUSE: "birdhouse", "birdhouse", ["bird house", "nest box", "bird box"], &["garden", "outdoor", "decor"],
    "a small wooden house for birds with a round hole", ["garden decoration"], Tabletop @ OnSurface, true, [0.20, 0.20, 0.30], 250.0,
    Look::Appliance { body: WOODS, front: [0.15, 0.1, 0.05, 1.0], door: [-0.12, 0.12, 0.55, 0.72], knobs: 0, top: true });
// Letterbox on a post, 30 × 30 × 120 cm.
thing!(MAILBOX: "mailbox", "mailbox", ["letterbox", "letter box", "mail box"], &["garden", "outdoor", "fixture"],
    "a mailbox on a post", ["box", "fixture"], Fixture @ Floor, false, [0.30, 0.45, 1.20], 100.0,
    Look::Stand { foot: [0.3, 0.3, 0.3, 1.0], pole: [0.3, 0.3, 0.3, 1.0], head: &[[0.15, 0.2, 0.35, 1.0], [0.7, 0.1, 0.1, 1.0]], head_h: 0.25 });

// --- bags, cases and accessories ----------------------------------------------------
// Briefcase, 44 × 12 × 33 cm.
thing!(BRIEFCASE: "briefcase", "briefcase", ["attache case", "document case"], BAGS, "a flat leather briefcase with a handle",
    ["bag", "case", "luggage"], Container @ OnSurface, true, [0.44, 0.12, 0.33], 200.0,
    Look::Case { body: LEATHER, handle: BLACK_C, handle_h: 0.12 });
// Duffel bag, 60 × 30 × 30 cm.
thing!(DUFFEL_BAG: "duffel_bag", "duffel bag", ["duffle bag", "holdall", "gym bag", "sports bag", "kit bag"], BAGS,
    "a soft cylindrical duffel bag with straps", ["bag", "luggage"], Container @ OnSurface, true, [0.60, 0.30, 0.32], 60.0,
    Look::Bag { body: FABRIC, strap: BLACK_C, body_h: 0.8 });
// Plastic carrier bag, 30 × 15 × 40 cm.
thing!(PLASTIC_BAG: "plastic_bag", "plastic bag", ["grocery bag", "polythene bag", "plastic shopping bag"], BAGS,
    "a white plastic carrier bag", ["bag"], Container @ OnSurface, true, [0.30, 0.15, 0.40], 30.0,
    Look::Bag { body: WHITE, strap: WHITE_C, body_h: 0.75 });
// Pencil case, 21 × 7 × 5 cm.
thing!(PENCIL_CASE: "pencil_case", "pencil case", ["pencil pouch", "pencil box", "pen case"], &["office", "school", "tabletop", "small", "graspable"],
    "a zipped pencil case", ["case", "stationery"], Tabletop @ OnSurface, true, [0.21, 0.07, 0.05], 200.0,
    Look::Pack { body: BRIGHTS, band: BLACK_C });
// Lipstick, 2 × 2 × 7.5 cm.
thing!(LIPSTICK: "lipstick", "lipstick", ["lipstick tube"], HOME, "a lipstick in its tube",
    ["cosmetics"], HandHeld @ OnSurface, true, [0.02, 0.02, 0.075], 1000.0,
    Look::Turned { profile: CAN, body: &[[0.1, 0.1, 0.1, 1.0], [0.85, 0.7, 0.3, 1.0]], top: 0.75, cap_r: 0.7, cap: [0.75, 0.1, 0.2, 1.0] });
// Disposable lighter, 2.5 × 1.2 × 8 cm.
thing!(LIGHTER: "lighter", "lighter", ["cigarette lighter", "gas lighter", "disposable lighter"], HOME, "a small plastic gas lighter",
    ["tool"], HandHeld @ OnSurface, true, [0.025, 0.012, 0.08], 900.0, Look::Pack { body: BRIGHTS, band: STEEL_C });
// Hair comb, 18 cm.
thing!(COMB: "comb", "comb", ["hair comb", "pocket comb"], &["bathroom", "tabletop", "small", "graspable"], "a flat plastic hair comb",
    ["grooming tool"], HandHeld @ OnSurface, true, [0.18, 0.03, 0.004], 1000.0, flat(BLACKS, [0.25, 0.25, 0.27, 1.0]));
// Wristwatch, 4.5 × 4 × 1.2 cm (strap folded).
thing!(WRISTWATCH: "wristwatch", "wristwatch", ["watch", "wrist watch"], HOME, "a wristwatch with its strap",
    ["accessory", "clock"], Tabletop @ OnSurface, true, [0.045, 0.04, 0.012], 1500.0, flat(LEATHER, [0.9, 0.9, 0.88, 1.0]));
// Hat (fedora), 32 × 28 × 14 cm.
thing!(HAT: "hat", "hat", ["fedora", "trilby", "sun hat", "felt hat"], &["home", "clothing", "tabletop"], "a brimmed hat",
    ["clothing", "headwear"], Textile @ OnSurface, true, [0.32, 0.32, 0.14], 60.0,
    Look::Turned { profile: HAT_CROWN, body: FABRIC, top: 1.0, cap_r: 1.0, cap: WHITE_C });
// Baseball cap, 27 × 20 × 12 cm.
thing!(BASEBALL_CAP: "baseball_cap", "baseball cap", ["ball cap", "peaked cap", "snapback"], &["home", "clothing", "tabletop"],
    "a cotton baseball cap with a peak", ["clothing", "headwear"], Textile @ OnSurface, true, [0.20, 0.20, 0.12], 80.0,
    Look::Turned { profile: DOME, body: BRIGHTS, top: 1.0, cap_r: 1.0, cap: WHITE_C });
// Bicycle helmet, 28 × 22 × 18 cm.
thing!(HELMET: "helmet", "helmet", ["bike helmet", "cycling helmet", "bicycle helmet"], &["home", "sport", "tabletop"],
    "a rounded protective helmet", ["protective gear", "headwear"], Tabletop @ OnSurface, true, [0.26, 0.26, 0.18], 100.0,
    Look::Turned { profile: DOME, body: BRIGHTS, top: 1.0, cap_r: 1.0, cap: WHITE_C });
// Pair of gloves, 25 × 12 × 3 cm.
thing!(GLOVES: "gloves", "gloves", ["glove", "pair of gloves", "work gloves", "gardening gloves", "winter gloves"], &["home", "clothing", "tabletop", "soft"],
    "a pair of gloves lying flat", ["clothing", "protective gear"], Textile @ OnSurface, true, [0.25, 0.12, 0.03], 150.0,
    flat(FABRIC, [0.3, 0.3, 0.3, 1.0]));
// Goggles, 18 × 8 × 7 cm.
thing!(GOGGLES: "goggles", "goggles", ["safety goggles", "swimming goggles", "ski goggles", "protective goggles"], &["lab", "workshop", "tabletop", "small", "graspable"],
    "a pair of goggles with a strap", ["protective gear", "eyewear"], Tabletop @ OnSurface, true, [0.18, 0.08, 0.07], 100.0,
    Look::Pack { body: &[[0.8, 0.85, 0.9, 1.0]], band: BLACK_C });
