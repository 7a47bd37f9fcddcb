//! LVIS v1's *rare* categories (issue 21, fourth round): the in-scope nouns of LVIS's 337
//! rare classes that the catalog lacked, most-imaged first
//! (`bench/vocab/public_lists/lvis_rare.txt`, `coverage.py`). Same parametric looks as the
//! other public families; sizes from published product ranges, noted per line.

use super::common::{CREAM, FOOD, GLASS, GOLDEN, HOME, OFFICE, PACKED, TABLEWARE};
use super::{
    BLACK_C, BLACKS, BRIGHTS, CAN, DISC, DOME, JAR, Look, METAL, STEEL_C, TUMBLER, URN, WHITE, WHITE_C, WOOD_C, WOODS,
    like, thing,
};
use super::{blob, capped, flat, long, pack, turned};

type Rgba = [f32; 4];

const TOOL: &[&str] = &["workshop", "tool", "tabletop", "graspable"];
const PLAY: &[&str] = &["home", "toy", "sport", "graspable"];
const MUSIC: &[&str] = &["home", "music", "instrument"];

const PINKS: &[Rgba] = &[[0.95, 0.6, 0.7, 1.0], [0.85, 0.4, 0.55, 1.0], [0.95, 0.85, 0.6, 1.0]];
const PURPLE: &[Rgba] = &[[0.4, 0.15, 0.35, 1.0], [0.35, 0.12, 0.3, 1.0]];
const ORANGE: &[Rgba] = &[[0.95, 0.5, 0.12, 1.0], [0.9, 0.45, 0.1, 1.0]];
const TURNIP_SKIN: &[Rgba] = &[[0.93, 0.9, 0.85, 1.0], [0.8, 0.6, 0.75, 1.0]];
const DARK: &[Rgba] = &[[0.25, 0.15, 0.08, 1.0], [0.3, 0.18, 0.1, 1.0]];

/// A cocktail glass: a foot, a stem and a wide cone on top.
const COCKTAIL: &[[f64; 2]] = &[[0.0, 0.0], [0.6, 0.0], [0.6, 0.03], [0.08, 0.06], [0.08, 0.5], [1.0, 1.0], [0.0, 1.0]];
/// A goblet: a foot, a stem and a round cup.
const GOBLET: &[[f64; 2]] =
    &[[0.0, 0.0], [0.7, 0.0], [0.7, 0.05], [0.12, 0.1], [0.12, 0.45], [0.8, 0.55], [1.0, 0.8], [0.95, 1.0], [0.0, 1.0]];
/// An hourglass: two bulbs meeting at a waist between end plates.
const HOURGLASS: &[[f64; 2]] = &[
    [0.0, 0.0],
    [1.0, 0.0],
    [1.0, 0.06],
    [0.75, 0.1],
    [0.8, 0.3],
    [0.12, 0.5],
    [0.8, 0.7],
    [0.75, 0.9],
    [1.0, 0.94],
    [1.0, 1.0],
    [0.0, 1.0],
];

const fn fruit(body: &'static [Rgba]) -> Look {
    Look::Blob { body, accent: [0.3, 0.45, 0.15, 1.0], stem: true }
}

// --- food and drink ------------------------------------------------------------------
// A 22 cm quiche, 4 cm deep.
thing!(QUICHE: "quiche", "quiche", ["quiche lorraine", "savoury tart", "savory tart", "flan"], FOOD, "a round golden quiche",
    ["pie", "food"], Food @ OnSurface, true, [0.22, 0.22, 0.04], 600.0, turned(DISC, GOLDEN));
// A smoothie or milkshake in a 450 ml cup, 8 cm across, 15 cm tall.
thing!(SMOOTHIE: "smoothie", "smoothie", ["milkshake", "milk shake", "frappe", "frappuccino", "smoothie cup"], FOOD,
    "a tall cup of smoothie", ["drink"], Food @ OnSurface, true, [0.08, 0.08, 0.15], 800.0, capped(TUMBLER, PINKS, 0.92, 0.98, WHITE_C));
// A 200 g tub of hummus, 10 cm across, 6 cm tall.
thing!(HUMMUS: "hummus", "hummus", ["houmous", "tub of hummus", "guacamole", "tzatziki", "salsa dip"], PACKED,
    "a round tub of hummus with a lid", ["dip", "food"], Food @ OnSurface, true, [0.10, 0.10, 0.06], 700.0, capped(CAN, CREAM, 0.88, 0.98, [0.3, 0.55, 0.3, 1.0]));
// A turnip, 8 cm.
thing!(TURNIP: "turnip", "turnip", ["turnips", "swede", "rutabaga"], FOOD, "a round white and purple turnip with leaves",
    ["vegetable", "produce", "food"], Food @ OnSurface, true, [0.08, 0.08, 0.08], 900.0, fruit(TURNIP_SKIN));
// A persimmon, 7 × 7 × 5 cm.
thing!(PERSIMMON: "persimmon", "persimmon", ["persimmons", "sharon fruit", "kaki"], FOOD, "a squat orange persimmon",
    ["fruit", "produce", "food"], Food @ OnSurface, true, [0.07, 0.07, 0.05], 900.0, fruit(ORANGE));
// A lasagne in its dish, 30 × 20 × 7 cm.
thing!(LASAGNE: "lasagne", "lasagne", ["lasagna", "lasagne dish", "dish of lasagne", "pasta bake", "moussaka"], FOOD,
    "a baked lasagne in a rectangular dish", ["food", "dish"], Food @ OnSurface, true, [0.30, 0.20, 0.07], 800.0, pack(WHITE, [0.8, 0.45, 0.2, 1.0]));
// A burger patty, 11 cm across, 1.5 cm thick.
thing!(PATTY: "burger_patty", "burger patty", ["patty", "patties", "beef patty", "hamburger patty", "veggie patty"], FOOD,
    "a round flat burger patty", ["meat", "food"], Food @ OnSurface, true, [0.11, 0.11, 0.015], 1000.0, turned(DISC, DARK));
// An eclair, 13 × 4 × 3.5 cm.
thing!(ECLAIR: "eclair", "eclair", ["éclair", "chocolate eclair", "cream eclair"], FOOD, "a long choux eclair with chocolate icing",
    ["pastry", "dessert", "food"], Food @ OnSurface, true, [0.13, 0.04, 0.035], 500.0, blob(GOLDEN));
// A fig, 5 cm.
thing!(FIG: "fig", "fig", ["figs", "fresh fig"], FOOD, "a purple fig", ["fruit", "produce", "food"], Food @ OnSurface, true,
    [0.05, 0.05, 0.055], 900.0, fruit(PURPLE));
// A jelly bean, 2 × 1.2 cm.
thing!(JELLY_BEAN: "jelly_bean", "jelly bean", ["jellybean", "jelly beans", "jellybeans"], FOOD, "a small glossy jelly bean",
    ["sweet", "food"], Food @ OnSurface, true, [0.02, 0.012, 0.012], 1200.0, blob(BRIGHTS));
// A steamed pudding, 10 cm across, 8 cm tall.
thing!(PUDDING: "pudding", "pudding", ["christmas pudding", "sponge pudding", "steamed pudding", "plum pudding", "pudding cup"], FOOD,
    "a domed steamed pudding", ["dessert", "food"], Food @ OnSurface, true, [0.10, 0.10, 0.08], 900.0, turned(DOME, DARK));
// A chocolate truffle, 2.5 cm.
thing!(TRUFFLE: "chocolate_truffle", "chocolate truffle", ["truffle", "truffles", "praline", "bonbon", "chocolate bonbon"], FOOD,
    "a round cocoa-dusted chocolate truffle", ["sweet", "chocolate", "food"], Food @ OnSurface, true, [0.025, 0.025, 0.022], 1200.0, blob(DARK));
// An ice lolly, 15 × 5 × 2 cm with its stick.
thing!(ICE_LOLLY: "ice_lolly", "ice lolly", ["popsicle", "ice pop", "ice lollipop", "popsicles", "ice lollies"], FOOD,
    "a frozen ice lolly on a wooden stick", ["frozen food", "dessert", "food"], Food @ OnSurface, true, [0.15, 0.05, 0.02], 700.0,
    long(0.3, WOODS, [0.95, 0.4, 0.45, 1.0]));
// A 1.5 L bottle of lemonade, 9 cm across, 31 cm tall.
thing!(LEMONADE: "lemonade", "lemonade", ["bottle of lemonade", "lemonade bottle", "pop bottle", "fizzy drink", "bottle of pop"], FOOD,
    "a plastic bottle of lemonade", ["drink", "bottle"], Food @ OnSurface, true, [0.09, 0.09, 0.31], 500.0,
    Look::Turned { profile: super::BOTTLE, body: &[[0.9, 0.95, 0.7, 1.0]], top: 0.94, cap_r: 0.35, cap: [0.2, 0.6, 0.3, 1.0] });
// Chewing gum, a pack of 10: 7 × 2 × 1.5 cm.
thing!(CHEWING_GUM: "chewing_gum", "chewing gum", ["bubble gum", "gum", "pack of gum", "packet of gum", "bubblegum"], PACKED,
    "a small pack of chewing gum", ["sweet", "food"], Food @ OnSurface, true, [0.07, 0.02, 0.015], 700.0, pack(BRIGHTS, WHITE_C));

// --- kitchen and table ---------------------------------------------------------------
// A gravy boat, 20 × 10 × 10 cm.
thing!(GRAVY_BOAT: "gravy_boat", "gravy boat", ["sauce boat", "gravy jug", "sauceboat"], TABLEWARE, "a white china gravy boat",
    ["jug", "tableware"], Container @ OnSurface, true, [0.20, 0.10, 0.10], 400.0, turned(TUMBLER, WHITE));
// A shot glass, 5 cm across, 6 cm tall.
thing!(SHOT_GLASS: "shot_glass", "shot glass", ["shooter glass", "tot glass"], TABLEWARE, "a small thick-bottomed shot glass",
    ["glass", "glassware"], Container @ OnSurface, true, [0.05, 0.05, 0.06], 1200.0, turned(TUMBLER, GLASS));
// A martini glass, 11 cm across, 17 cm tall.
thing!(MARTINI_GLASS: "martini_glass", "martini glass", ["martini", "cocktail glass", "margarita glass", "coupe glass"], TABLEWARE,
    "a stemmed cone-shaped cocktail glass", ["glass", "glassware"], Container @ OnSurface, true, [0.11, 0.11, 0.17], 200.0, turned(COCKTAIL, GLASS));
// A chalice, 10 cm across, 20 cm tall.
thing!(CHALICE: "chalice", "chalice", ["communion cup", "metal goblet", "wine chalice", "silver goblet"], TABLEWARE, "a stemmed metal goblet",
    ["cup", "drinkware"], Container @ OnSurface, true, [0.10, 0.10, 0.20], 300.0, turned(GOBLET, &[[0.85, 0.68, 0.28, 1.0], [0.75, 0.77, 0.8, 1.0]]));
// A cast-iron griddle, 50 × 25 × 2 cm.
thing!(GRIDDLE: "griddle", "griddle", ["griddle pan", "plancha", "griddle plate", "flat griddle", "reversible griddle"], &["kitchen", "cookware", "tabletop"],
    "a flat black cast-iron griddle", ["cookware", "pan"], Tabletop @ OnSurface, true, [0.50, 0.25, 0.02], 1500.0, flat(BLACKS, [0.2, 0.2, 0.22, 1.0]));
// A coffee stirrer, 14 cm.
thing!(STIRRER: "stirrer", "stirrer", ["coffee stirrer", "swizzle stick", "drink stirrer", "stir stick", "cocktail stirrer"], TABLEWARE,
    "a thin wooden drink stirrer", ["utensil"], HandHeld @ OnSurface, true, [0.14, 0.006, 0.004], 600.0, long(0.5, WOODS, WOOD_C));
// A nutcracker, 18 cm.
thing!(NUTCRACKER: "nutcracker", "nutcracker", ["nut cracker", "nutcrackers", "walnut cracker"], TABLEWARE, "a hinged metal nutcracker",
    ["kitchen utensil", "utensil"], HandHeld @ OnSurface, true, [0.18, 0.05, 0.02], 800.0, long(0.6, METAL, STEEL_C));
// A glass fish bowl, 25 cm across, 22 cm tall.
thing!(FISHBOWL: "fishbowl", "fish bowl", ["betta bowl"], &["home", "pet", "tabletop"],
    "a round glass fish bowl", ["container", "pet supplies"], Container @ OnSurface, true, [0.25, 0.25, 0.22], 300.0, turned(JAR, GLASS));
// A hookah, 25 cm across, 70 cm tall.
thing!(HOOKAH: "hookah", "hookah", ["shisha", "shisha pipe", "water pipe", "hookah pipe", "narghile"], &["home", "decor"],
    "a tall hookah: a glass base, a stem and a bowl", ["pipe"], Tabletop @ Floor, false, [0.25, 0.25, 0.70], 150.0,
    turned(URN, &[[0.3, 0.5, 0.6, 1.0], [0.55, 0.25, 0.5, 1.0]]));

// --- home, office and care ---------------------------------------------------------------
// A matchbox, 5 × 3.5 × 1.5 cm.
thing!(MATCHBOX: "matchbox", "matchbox", ["box of matches", "match box", "safety matches"], HOME, "a small box of safety matches",
    ["box"], HandHeld @ OnSurface, true, [0.05, 0.035, 0.015], 500.0, pack(&[[0.85, 0.2, 0.15, 1.0], [0.2, 0.35, 0.7, 1.0]], [0.35, 0.2, 0.12, 1.0]));
// A bookmark, 5 × 16 cm.
thing!(BOOKMARK: "bookmark", "bookmark", ["book mark", "page marker"], OFFICE, "a printed card bookmark", ["stationery"],
    HandHeld @ OnSurface, true, [0.05, 0.16, 0.004], 700.0, flat(BRIGHTS, WHITE_C));
// A compact audio cassette, 10.2 × 6.4 × 1.2 cm.
thing!(CASSETTE: "cassette_tape", "cassette tape", ["cassette", "audio cassette", "tape cassette", "mixtape", "compact cassette", "music cassette"], OFFICE,
    "a plastic audio cassette with two reels", ["media"], HandHeld @ OnSurface, true, [0.102, 0.064, 0.012], 800.0, pack(BLACKS, WHITE_C));
// A hand mirror, 25 × 13 × 2 cm.
thing!(HAND_MIRROR: "hand_mirror", "hand mirror", ["hand glass", "handheld mirror", "vanity mirror", "looking glass"], &["bathroom", "personal_care", "tabletop", "small", "graspable"],
    "a round mirror on a handle", ["mirror"], HandHeld @ OnSurface, true, [0.25, 0.13, 0.02], 600.0, long(0.45, PINKS, [0.85, 0.9, 0.95, 1.0]));
// A knitting needle, 35 cm.
thing!(KNITTING_NEEDLE: "knitting_needle", "knitting needle", ["knitting needles", "knitting pins", "crochet hook"], HOME,
    "a long knitting needle with a knob end", ["sewing supplies"], HandHeld @ OnSurface, true, [0.35, 0.01, 0.01], 900.0, long(0.05, BRIGHTS, STEEL_C));
// A nail file, 18 cm.
thing!(NAIL_FILE: "nail_file", "nail file", ["nailfile", "emery board", "nail buffer"], &["bathroom", "personal_care", "tabletop", "small", "graspable"],
    "a thin nail file", ["manicure tool"], HandHeld @ OnSurface, true, [0.18, 0.02, 0.004], 900.0, long(0.4, PINKS, STEEL_C));
// A safety pin, 5 cm.
thing!(SAFETY_PIN: "safety_pin", "safety pin", ["safety pins", "nappy pin", "diaper pin"], HOME, "a steel safety pin", ["fastener"],
    HandHeld @ OnSurface, true, [0.05, 0.01, 0.004], 2000.0, long(0.2, METAL, STEEL_C));
// An asthma inhaler, 10 × 4 × 6 cm.
thing!(INHALER: "inhaler", "inhaler", ["asthma inhaler", "metered dose inhaler", "nebuliser inhaler"], &["clinic", "medical", "tabletop", "small", "graspable"],
    "an L-shaped asthma inhaler", ["medical device"], HandHeld @ OnSurface, true, [0.10, 0.04, 0.06], 400.0,
    pack(&[[0.3, 0.5, 0.8, 1.0], [0.8, 0.45, 0.2, 1.0]], [0.9, 0.9, 0.9, 1.0]));
// A pager, 6 × 2 × 4.5 cm.
thing!(PAGER: "pager", "pager", ["beeper", "bleeper", "radio pager"], &["clinic", "electronics", "tabletop", "small", "graspable"],
    "a small black pager with a screen", ["electronics"], HandHeld @ OnSurface, true, [0.06, 0.02, 0.045], 800.0, pack(BLACKS, [0.55, 0.65, 0.55, 1.0]));
// A hatbox, 35 cm across, 25 cm tall.
thing!(HATBOX: "hatbox", "hatbox", ["hat box", "round gift box", "round storage box"], &["home", "storage", "tabletop"],
    "a round lidded hatbox", ["box", "container"], Container @ OnSurface, true, [0.35, 0.35, 0.25], 150.0,
    capped(CAN, PINKS, 0.85, 0.98, [0.95, 0.95, 0.93, 1.0]));
// An ink pad, 10 × 6.5 × 1.5 cm.
thing!(INK_PAD: "ink_pad", "ink pad", ["inkpad", "stamp pad", "stamping pad"], OFFICE, "a flat tin ink pad", ["office supplies"],
    HandHeld @ OnSurface, true, [0.10, 0.065, 0.015], 900.0, pack(BLACKS, [0.2, 0.3, 0.7, 1.0]));
// A cheque book, 16 × 7.5 × 0.8 cm.
thing!(CHEQUE_BOOK: "cheque_book", "cheque book", ["checkbook", "check book", "chequebook", "cheque booklet"], OFFICE,
    "a long thin cheque book", ["document"], HandHeld @ OnSurface, true, [0.16, 0.075, 0.008], 700.0, flat(&[[0.2, 0.3, 0.45, 1.0]], [0.85, 0.88, 0.92, 1.0]));
// A key card, 8.6 × 5.4 cm (ID-1).
thing!(KEY_CARD: "key_card", "key card", ["keycard", "access card", "card key", "hotel key card", "credit card", "bank card", "debit card", "id card", "smart card"], OFFICE,
    "a plastic card the size of a credit card", ["card"], HandHeld @ OnSurface, true, [0.086, 0.054, 0.003], 1300.0, flat(BRIGHTS, WHITE_C));
// A hair curler, 3 cm across, 6.5 cm long.
thing!(HAIR_CURLER: "hair_curler", "hair curler", ["curler", "hair roller", "curlers", "hair rollers"], &["bathroom", "personal_care", "tabletop", "small", "graspable"],
    "a round hair roller", ["hair accessory"], HandHeld @ OnSurface, true, [0.03, 0.03, 0.065], 200.0, turned(CAN, PINKS));
// An hourglass, 8 cm across, 15 cm tall.
thing!(HOURGLASS_TIMER: "hourglass", "hourglass", ["sand timer", "egg timer", "sandglass", "hour glass", "sand clock"], HOME,
    "a glass sand timer between wooden ends", ["timer", "decoration"], Tabletop @ OnSurface, true, [0.08, 0.08, 0.15], 600.0, turned(HOURGLASS, GLASS));
// A glass paperweight, 8 cm across, 5 cm tall.
thing!(PAPERWEIGHT: "paperweight", "paperweight", ["paper weight", "glass paperweight"], OFFICE, "a domed glass paperweight",
    ["office supplies", "decoration"], Tabletop @ OnSurface, true, [0.08, 0.08, 0.05], 2500.0, turned(DOME, GLASS));
// A poker chip, 3.9 cm across, 3.3 mm thick.
thing!(POKER_CHIP: "poker_chip", "poker chip", ["casino chip", "gaming chip", "poker chips", "gambling chip"], PLAY,
    "a round clay poker chip", ["game piece", "toy"], Toy @ OnSurface, true, [0.039, 0.039, 0.0033], 2000.0, turned(DISC, BRIGHTS));
// A magnetic compass, 6 cm across, 1.5 cm thick.
thing!(COMPASS: "compass", "compass", ["magnetic compass", "hiking compass", "pocket compass", "navigation compass"], HOME,
    "a round magnetic compass", ["instrument"], HandHeld @ OnSurface, true, [0.06, 0.06, 0.015], 1000.0,
    Look::Turned { profile: DISC, body: &[[0.85, 0.68, 0.28, 1.0]], top: 0.8, cap_r: 0.85, cap: WHITE_C });
// A gel ice pack, 25 × 15 × 2 cm.
thing!(ICE_PACK: "ice_pack", "ice pack", ["cold pack", "gel pack", "freezer pack", "ice block", "cool pack", "icepack"], &["clinic", "kitchen", "tabletop", "small", "graspable"],
    "a flat blue gel ice pack", ["first aid"], HandHeld @ OnSurface, true, [0.25, 0.15, 0.02], 1000.0, flat(&[[0.3, 0.55, 0.85, 1.0]], [0.6, 0.8, 0.95, 1.0]));

// --- tools -----------------------------------------------------------------------------
// A pitchfork, 140 cm.
thing!(PITCHFORK: "pitchfork", "pitchfork", ["hay fork", "garden fork", "digging fork", "hayfork"], &["garden", "tool", "outdoor"],
    "a long-handled garden fork", ["garden tool", "tool"], HandHeld @ Floor, true, [1.40, 0.20, 0.05], 300.0, long(0.7, WOODS, STEEL_C));
// Secateurs, 20 cm.
thing!(SECATEURS: "secateurs", "secateurs", ["pruning shears", "pruners", "hand pruner", "plant clippers", "garden clippers", "clippers"], TOOL,
    "a pair of red-handled secateurs", ["garden tool", "tool"], HandHeld @ OnSurface, true, [0.20, 0.06, 0.02], 900.0,
    long(0.55, &[[0.8, 0.12, 0.12, 1.0]], STEEL_C));
// A crowbar, 60 cm.
thing!(CROWBAR: "crowbar", "crowbar", ["pry bar", "wrecking bar", "jemmy", "jimmy bar", "prybar"], TOOL, "a steel crowbar with a hooked end",
    ["hand tool", "tool"], HandHeld @ OnSurface, true, [0.60, 0.05, 0.03], 2000.0, long(0.8, &[[0.15, 0.15, 0.16, 1.0], [0.75, 0.1, 0.1, 1.0]], STEEL_C));
// A paint scraper, 20 cm.
thing!(SCRAPER: "scraper", "scraper", ["paint scraper", "putty knife", "filling knife", "wallpaper scraper", "ice scraper", "spackle knife"], TOOL,
    "a flat-bladed scraper on a handle", ["hand tool", "tool"], HandHeld @ OnSurface, true, [0.20, 0.07, 0.02], 700.0, long(0.55, BRIGHTS, STEEL_C));

// --- music, play and electronics -----------------------------------------------------------
// A pair of drumsticks, 40 cm.
thing!(DRUMSTICK: "drumstick", "drumstick", ["drumsticks", "drum stick", "drum sticks", "pair of drumsticks"], MUSIC,
    "a pair of wooden drumsticks", ["musical instrument accessory"], HandHeld @ OnSurface, true, [0.40, 0.03, 0.015], 700.0, long(0.9, WOODS, WOOD_C));
// A banjo, 95 × 35 × 10 cm.
thing!(BANJO: "banjo", "banjo", ["five-string banjo", "banjolele", "tenor banjo"], MUSIC, "a banjo: a round drum body and a long neck",
    ["string instrument", "musical instrument"], Toy @ OnSurface, true, [0.95, 0.35, 0.10], 250.0,
    Look::Instrument { body: &[[0.9, 0.88, 0.8, 1.0]], neck: WOOD_C, body_len: 0.38 });
// A clarinet, 66 cm.
thing!(CLARINET: "clarinet", "clarinet", ["bass clarinet"], MUSIC, "a black clarinet with silver keys",
    ["woodwind instrument", "musical instrument"], Toy @ OnSurface, true, [0.66, 0.07, 0.07], 400.0, long(0.85, BLACKS, [0.75, 0.77, 0.8, 1.0]));
// A tambourine, 25 cm across, 6 cm deep.
thing!(TAMBOURINE: "tambourine", "tambourine", ["timbrel", "hand drum", "frame drum"], MUSIC, "a round tambourine with jingles",
    ["percussion instrument", "musical instrument"], Toy @ OnSurface, true, [0.25, 0.25, 0.06], 200.0,
    Look::Turned { profile: CAN, body: WOODS, top: 0.9, cap_r: 0.98, cap: [0.95, 0.92, 0.85, 1.0] });
// A mini fitness trampoline, 100 cm across, 25 cm tall.
thing!(TRAMPOLINE: "trampoline", "trampoline", ["mini trampoline", "rebounder", "fitness trampoline", "kids trampoline"], &["home", "sport", "large"],
    "a round mini trampoline: a black mat on short legs", ["sports equipment"], Toy @ Floor, false, [1.00, 1.00, 0.25], 60.0,
    Look::Table { top: 0.2, wood: BLACKS, legs: STEEL_C, shelf: false });
// A toy pinwheel, 20 × 5 × 40 cm.
thing!(PINWHEEL: "pinwheel", "pinwheel", ["toy windmill", "paper windmill", "whirligig", "pin wheel"], PLAY,
    "a colourful toy pinwheel on a stick", ["toy"], Toy @ OnSurface, true, [0.20, 0.20, 0.40], 40.0,
    Look::Stand { foot: WOOD_C, pole: WOOD_C, head: BRIGHTS, head_h: 0.4 });
// A stylus, 12 cm.
thing!(STYLUS: "stylus", "stylus", ["stylus pen", "touch pen", "digital pen", "tablet pen", "apple pencil"], &["office", "electronics", "tabletop", "small", "graspable"],
    "a slim stylus pen", ["electronics accessory", "pen"], HandHeld @ OnSurface, true, [0.12, 0.008, 0.008], 1200.0, long(0.8, WHITE, STEEL_C));
// A subwoofer, 35 × 38 × 38 cm.
thing!(SUBWOOFER: "subwoofer", "subwoofer", ["sub woofer", "bass speaker", "woofer"], &["home", "electronics", "audio"],
    "a black cube subwoofer with a driver in front", ["speaker", "audio device"], SmallAppliance @ Floor, false, [0.35, 0.38, 0.38], 350.0,
    Look::Appliance { body: BLACKS, front: [0.2, 0.2, 0.22, 1.0], door: [-0.35, 0.35, 0.15, 0.85], knobs: 0, top: true });
// A camera drone, 35 × 35 × 10 cm.
thing!(DRONE: "drone", "drone", ["quadcopter", "camera drone", "quadrocopter", "toy drone", "multicopter"], &["home", "electronics", "toy"],
    "a quadcopter drone with four rotor arms", ["electronics", "toy"], Toy @ OnSurface, true, [0.35, 0.35, 0.10], 150.0,
    Look::Table { top: 0.35, wood: &[[0.2, 0.2, 0.22, 1.0], [0.9, 0.9, 0.9, 1.0]], legs: BLACK_C, shelf: false });

// --- things drawn by an existing family's builder ------------------------------------------
// A roller skate, 30 × 11 × 20 cm: a shoe on wheels.
like!(ROLLER_SKATE: "roller_skate", "roller skate", ["roller skates", "rollerblade", "rollerblades", "inline skate", "inline skates", "quad skate"], PLAY,
    "a boot roller skate", ["skate", "sports equipment"], Toy @ OnSurface, true, [0.30, 0.11, 0.20], super::super::toys::build_shoe);
// An ice skate, 30 × 11 × 25 cm: a laced boot on a blade.
like!(ICE_SKATE: "ice_skate", "ice skate", ["ice skates", "figure skate", "hockey skate", "skates"], PLAY,
    "a laced boot ice skate", ["skate", "sports equipment"], Toy @ OnSurface, true, [0.30, 0.11, 0.25], super::super::toys::build_shoe);
// A water pistol, 25 × 7 × 15 cm, lying on its side.
thing!(WATER_PISTOL: "water_pistol", "water pistol", ["water gun", "squirt gun", "super soaker", "water blaster"], PLAY,
    "a brightly coloured toy water pistol", ["toy"], Toy @ OnSurface, true, [0.25, 0.15, 0.07], 200.0,
    long(0.3, BRIGHTS, [0.95, 0.8, 0.2, 1.0]));
