//! Food, drink and their packs from the public lists (RoboCasa's kitchen objects, COCO,
//! Objects365, LVIS): produce, baked and cooked food, bottles, jars and packets. Sizes are
//! of one typical item (supermarket produce classes, standard pack sizes), noted per line.

use super::{BLACK_C, BOTTLE, BROWN_C, CAN, DISC, DOME, GREEN_C, JAR, Look, STEEL_C, TUMBLER, WHITE_C, thing};

type Rgba = [f32; 4];

const PRODUCE: &[&str] = &["kitchen", "food", "produce", "tabletop", "small", "graspable"];
const COOKED: &[&str] = &["kitchen", "food", "tabletop", "small", "graspable"];
const DRINK: &[&str] = &["kitchen", "food", "drink", "tabletop", "small", "graspable"];
const PACKED: &[&str] = &["kitchen", "food", "packaging", "tabletop", "small", "graspable"];
const ROUND_FRUIT: &[&str] = &["kitchen", "food", "produce", "tabletop", "small", "graspable", "round"];

const GREEN: &[Rgba] = &[[0.3, 0.5, 0.15, 1.0], [0.38, 0.58, 0.2, 1.0]];
const DARK_GREEN: &[Rgba] = &[[0.15, 0.28, 0.1, 1.0], [0.2, 0.32, 0.12, 1.0]];
const RED: &[Rgba] = &[[0.7, 0.08, 0.1, 1.0], [0.6, 0.05, 0.08, 1.0]];
const ORANGE: &[Rgba] = &[[0.95, 0.55, 0.15, 1.0], [0.92, 0.6, 0.25, 1.0]];
const YELLOW: &[Rgba] = &[[0.95, 0.8, 0.3, 1.0], [0.92, 0.75, 0.35, 1.0]];
const GOLDEN: &[Rgba] = &[[0.85, 0.6, 0.3, 1.0], [0.78, 0.52, 0.25, 1.0]];
const BROWN: &[Rgba] = &[[0.45, 0.3, 0.15, 1.0], [0.38, 0.25, 0.12, 1.0]];
const CREAM: &[Rgba] = &[[0.95, 0.9, 0.8, 1.0], [0.98, 0.94, 0.85, 1.0]];
const PINK: &[Rgba] = &[[0.9, 0.55, 0.5, 1.0], [0.85, 0.45, 0.45, 1.0]];
const PURPLE: &[Rgba] = &[[0.45, 0.1, 0.25, 1.0], [0.5, 0.15, 0.3, 1.0]];
const AMBER: &[Rgba] = &[[0.45, 0.25, 0.05, 1.0], [0.35, 0.2, 0.05, 1.0]];
const CLEAR: &[Rgba] = &[[0.75, 0.85, 0.92, 1.0], [0.7, 0.82, 0.9, 1.0]];
const GLASS_GREEN: &[Rgba] = &[[0.2, 0.35, 0.2, 1.0], [0.25, 0.4, 0.25, 1.0]];
const PACKS: &[Rgba] = &[
    [0.85, 0.2, 0.15, 1.0],
    [0.2, 0.4, 0.75, 1.0],
    [0.95, 0.8, 0.2, 1.0],
    [0.25, 0.6, 0.3, 1.0],
    [0.9, 0.9, 0.88, 1.0],
];
const LABEL: Rgba = [0.95, 0.95, 0.9, 1.0];
const MUSHROOM_CAP: &[[f64; 2]] =
    &[[0.0, 0.0], [0.35, 0.0], [0.35, 0.45], [1.0, 0.5], [0.9, 0.8], [0.5, 0.97], [0.0, 1.0]];

const fn blob(body: &'static [Rgba]) -> Look {
    Look::Blob { body, accent: BROWN_C, stem: false }
}
const fn fruit(body: &'static [Rgba], accent: Rgba) -> Look {
    Look::Blob { body, accent, stem: true }
}
const fn pack(body: &'static [Rgba]) -> Look {
    Look::Pack { body, band: LABEL }
}
const fn bottle(body: &'static [Rgba], cap: Rgba) -> Look {
    Look::Turned { profile: BOTTLE, body, top: 0.92, cap_r: 0.36, cap }
}
const fn jar(body: &'static [Rgba], lid: Rgba) -> Look {
    Look::Turned { profile: JAR, body, top: 0.88, cap_r: 0.86, cap: lid }
}
const fn round(profile: &'static [[f64; 2]], body: &'static [Rgba]) -> Look {
    Look::Turned { profile, body, top: 1.0, cap_r: 1.0, cap: WHITE_C }
}

// --- produce ------------------------------------------------------------------------
// Hass avocado: about 10 cm long, 7 cm across.
thing!(AVOCADO: "avocado", "avocado", ["hass avocado", "avocado pear"], PRODUCE, "a dark green pear-shaped avocado fruit",
    ["fruit", "produce", "food"], Food @ OnSurface, true, [0.10, 0.07, 0.07], 900.0, fruit(DARK_GREEN, BROWN_C));
// Sweet cherry: 2–2.5 cm.
thing!(CHERRY: "cherry", "cherry", ["sweet cherry", "morello cherry"], ROUND_FRUIT, "a small round red cherry with a stalk",
    ["fruit", "produce", "food"], Food @ OnSurface, true, [0.025, 0.025, 0.025], 1000.0, fruit(RED, GREEN_C));
// Apricot: 4–5 cm.
thing!(APRICOT: "apricot", "apricot", ["fresh apricot"], ROUND_FRUIT, "a small round orange apricot",
    ["fruit", "produce", "food"], Food @ OnSurface, true, [0.045, 0.045, 0.045], 950.0, fruit(ORANGE, BROWN_C));
// Pomegranate: 8–10 cm.
thing!(POMEGRANATE: "pomegranate", "pomegranate", ["pomegranate fruit"], ROUND_FRUIT, "a round red pomegranate with a crown",
    ["fruit", "produce", "food"], Food @ OnSurface, true, [0.09, 0.09, 0.085], 900.0, fruit(RED, BROWN_C));
// Coconut (husked): 11–13 cm.
thing!(COCONUT: "coconut", "coconut", ["husked coconut", "whole coconut"], ROUND_FRUIT, "a round hairy brown coconut",
    ["fruit", "nut", "food"], Food @ OnSurface, true, [0.12, 0.12, 0.12], 700.0, blob(BROWN));
// Papaya: 15–25 cm long, lying.
thing!(PAPAYA: "papaya", "papaya", ["pawpaw", "paw paw"], PRODUCE, "an oblong orange-green papaya fruit",
    ["fruit", "produce", "food"], Food @ OnSurface, true, [0.20, 0.11, 0.11], 900.0, fruit(ORANGE, GREEN_C));
// Durian: 20 cm long, 15 cm across.
thing!(DURIAN: "durian", "durian", ["durian fruit"], PRODUCE, "a large spiky green-brown durian fruit",
    ["fruit", "produce", "food"], Food @ OnSurface, true, [0.22, 0.16, 0.16], 800.0, fruit(&[[0.55, 0.55, 0.25, 1.0]], BROWN_C));
// Grapefruit: 10–12 cm.
thing!(GRAPEFRUIT: "grapefruit", "grapefruit", ["pink grapefruit", "ruby grapefruit"], ROUND_FRUIT, "a large round yellow-pink grapefruit",
    ["citrus fruit", "fruit", "food"], Food @ OnSurface, true, [0.11, 0.11, 0.10], 900.0, fruit(YELLOW, GREEN_C));
// Walnut in its shell: 3–4 cm.
thing!(WALNUT: "walnut", "walnut", ["walnut in its shell", "whole walnut"], ROUND_FRUIT, "a wrinkled brown walnut in its shell",
    ["nut", "food"], Food @ OnSurface, true, [0.035, 0.035, 0.033], 600.0, blob(BROWN));
// Button and chestnut mushrooms: 4–6 cm caps.
thing!(MUSHROOM: "mushroom", "mushroom", ["button mushroom", "chestnut mushroom", "field mushroom"], ROUND_FRUIT,
    "a white button mushroom with a round cap on a short stem", ["vegetable", "fungus", "food"], Food @ OnSurface, true,
    [0.05, 0.05, 0.045], 500.0, round(MUSHROOM_CAP, CREAM));
// Cabbage head: 15–18 cm.
thing!(CABBAGE: "cabbage", "cabbage", ["red cabbage", "white cabbage", "savoy cabbage", "cabbage head"], ROUND_FRUIT,
    "a round head of green cabbage", ["vegetable", "produce", "food"], Food @ OnSurface, true, [0.16, 0.16, 0.15], 600.0,
    blob(GREEN));
// Celery bunch: 30–40 cm long.
thing!(CELERY: "celery", "celery", ["celery stalk", "bunch of celery", "celery stick"], PRODUCE, "a long green bunch of celery stalks",
    ["vegetable", "produce", "food"], Food @ OnSurface, true, [0.35, 0.08, 0.06], 600.0,
    Look::Long { grip: 0.7, grip_w: 0.6, grip_h: 0.7, handle: GREEN, head: [0.3, 0.55, 0.15, 1.0] });
// Asparagus bunch: 22 cm long.
thing!(ASPARAGUS: "asparagus", "asparagus", ["asparagus spear", "bunch of asparagus", "asparagus bunch"], PRODUCE,
    "a bunch of green asparagus spears tied together", ["vegetable", "produce", "food"], Food @ OnSurface, true,
    [0.22, 0.05, 0.045], 600.0, Look::Long { grip: 0.8, grip_w: 0.8, grip_h: 0.8, handle: GREEN, head: [0.3, 0.4, 0.2, 1.0] });
// Green bean pod: 10–12 cm.
thing!(GREEN_BEAN: "green_bean", "green bean", ["runner bean", "french bean", "string bean"], PRODUCE, "a long thin green bean pod",
    ["vegetable", "produce", "food"], Food @ OnSurface, true, [0.12, 0.012, 0.01], 900.0, blob(GREEN));
// Radish: 3–4 cm.
thing!(RADISH: "radish", "radish", ["red radish", "garden radish"], ROUND_FRUIT, "a small round red radish with a leafy top",
    ["vegetable", "root vegetable", "food"], Food @ OnSurface, true, [0.035, 0.035, 0.04], 900.0, fruit(RED, GREEN_C));
// Beetroot: 6–8 cm.
thing!(BEETROOT: "beetroot", "beetroot", ["beet", "red beet"], ROUND_FRUIT, "a round dark purple beetroot with a stalk",
    ["vegetable", "root vegetable", "food"], Food @ OnSurface, true, [0.07, 0.07, 0.07], 950.0, fruit(PURPLE, GREEN_C));
// Ginger root: a 10 cm hand.
thing!(GINGER_ROOT: "ginger_root", "ginger root", ["ginger", "root ginger", "fresh ginger"], PRODUCE, "a knobbly pale brown piece of ginger root",
    ["spice", "root vegetable", "food"], Food @ OnSurface, true, [0.10, 0.05, 0.035], 900.0, blob(&[[0.8, 0.65, 0.45, 1.0]]));
// Globe artichoke: 10 cm.
thing!(ARTICHOKE: "artichoke", "artichoke", ["globe artichoke"], ROUND_FRUIT, "a round green globe artichoke with a stem",
    ["vegetable", "produce", "food"], Food @ OnSurface, true, [0.10, 0.10, 0.11], 600.0, fruit(GREEN, GREEN_C));

// --- baked, cooked and sweet --------------------------------------------------------
// Bagel: 10 cm across, 3.5 cm tall.
thing!(BAGEL: "bagel", "bagel", ["plain bagel", "sesame bagel"], COOKED, "a round golden bread bagel",
    ["bread", "baked goods", "food"], Food @ OnSurface, true, [0.10, 0.10, 0.035], 300.0, round(DISC, GOLDEN));
// Croissant: 14 cm tip to tip.
thing!(CROISSANT: "croissant", "croissant", ["crescent roll", "butter croissant"], COOKED, "a curved golden flaky croissant",
    ["pastry", "baked goods", "food"], Food @ OnSurface, true, [0.14, 0.07, 0.05], 250.0, blob(GOLDEN));
// Round cake: 20–23 cm tin, 10 cm tall.
thing!(CAKE: "cake", "cake", ["birthday cake", "sponge cake", "gateau", "layer cake", "chocolate cake"], COOKED,
    "a round iced layer cake", ["dessert", "baked goods", "food"], Food @ OnSurface, true, [0.22, 0.22, 0.10], 500.0,
    Look::Turned { profile: CAN, body: CREAM, top: 0.8, cap_r: 0.98, cap: [0.95, 0.75, 0.8, 1.0] });
// Pizza: 12-inch (30 cm).
thing!(PIZZA: "pizza", "pizza", ["margherita", "pepperoni pizza", "whole pizza"], COOKED, "a round flat pizza with its toppings",
    ["dish", "food"], Food @ OnSurface, true, [0.30, 0.30, 0.025], 400.0,
    Look::Turned { profile: DISC, body: GOLDEN, top: 0.55, cap_r: 0.9, cap: [0.8, 0.25, 0.1, 1.0] });
// Fruit pie: 23 cm dish.
thing!(PIE: "pie", "pie", ["apple pie", "fruit pie", "meat pie"], COOKED, "a round golden baked pie in its dish",
    ["dessert", "baked goods", "food"], Food @ OnSurface, true, [0.23, 0.23, 0.05], 500.0, round(DOME, GOLDEN));
// Cookie: 7 cm across.
thing!(COOKIE: "cookie", "cookie", ["biscuit", "chocolate chip cookie"], COOKED, "a round flat brown cookie",
    ["snack", "baked goods", "food"], Food @ OnSurface, true, [0.07, 0.07, 0.012], 500.0, round(DISC, BROWN));
// Burger in a bun: 11 cm across, 8 cm tall.
thing!(HAMBURGER: "hamburger", "hamburger", ["burger", "cheeseburger", "beefburger"], COOKED, "a hamburger in a round sesame bun",
    ["sandwich", "fast food", "food"], Food @ OnSurface, true, [0.11, 0.11, 0.08], 400.0, round(DOME, GOLDEN));
// Bread roll: 9–10 cm.
thing!(BREAD_ROLL: "bread_roll", "bread roll", ["bun", "burger bun", "hot dog bun", "hotdog bun", "dinner roll", "bap"], COOKED,
    "a small round golden bread roll", ["bread", "baked goods", "food"], Food @ OnSurface, true, [0.10, 0.10, 0.06], 250.0,
    round(DOME, GOLDEN));
// Steamed bun: 8 cm.
thing!(STEAMED_BUN: "steamed_bun", "steamed bun", ["baozi", "bao", "bao bun"], COOKED, "a round white steamed filled bun",
    ["bread", "dumpling", "food"], Food @ OnSurface, true, [0.08, 0.08, 0.05], 400.0, round(DOME, CREAM));
// Sausage: 15 cm.
thing!(SAUSAGE: "sausage", "sausage", ["banger", "bratwurst", "pork sausage"], COOKED, "a long browned sausage",
    ["meat", "food"], Food @ OnSurface, true, [0.15, 0.03, 0.028], 1000.0, blob(&[[0.6, 0.35, 0.25, 1.0]]));
// Salami: a 25 cm stick.
thing!(SALAMI: "salami", "salami", ["salami stick", "cured sausage"], COOKED, "a long dark red stick of salami",
    ["meat", "food"], Food @ OnSurface, true, [0.25, 0.055, 0.055], 1000.0, blob(&[[0.55, 0.15, 0.15, 1.0]]));
// Ham joint: 18 cm.
thing!(HAM: "ham", "ham", ["gammon", "ham joint", "joint of ham"], COOKED, "a pink joint of cooked ham",
    ["meat", "food"], Food @ OnSurface, true, [0.18, 0.13, 0.11], 1000.0, blob(PINK));
// Shrimp / prawn: 7 cm.
thing!(SHRIMP: "shrimp", "shrimp", ["prawn", "king prawn"], COOKED, "a curled pink cooked shrimp",
    ["seafood", "food"], Food @ OnSurface, true, [0.07, 0.03, 0.02], 1000.0, blob(PINK));
// Sushi piece: 5 × 3 × 2.5 cm.
thing!(SUSHI: "sushi", "sushi", ["sushi roll", "nigiri", "maki"], COOKED, "a piece of sushi, rice with fish on top",
    ["dish", "food"], Food @ OnSurface, true, [0.05, 0.03, 0.025], 900.0, Look::Pack { body: CREAM, band: [0.95, 0.45, 0.3, 1.0] });
// Dumpling: 6 cm.
thing!(DUMPLING: "dumpling", "dumpling", ["potsticker", "gyoza", "jiaozi"], COOKED, "a pleated white filled dumpling",
    ["dish", "food"], Food @ OnSurface, true, [0.06, 0.04, 0.03], 900.0, blob(CREAM));
// Spring roll: 10 cm.
thing!(SPRING_ROLL: "spring_roll", "spring roll", ["egg roll"], COOKED, "a golden fried spring roll",
    ["dish", "food"], Food @ OnSurface, true, [0.10, 0.03, 0.03], 700.0, blob(GOLDEN));
// Burrito: 20 cm.
thing!(BURRITO: "burrito", "burrito", ["breakfast burrito"], COOKED, "a rolled flour tortilla burrito",
    ["dish", "food"], Food @ OnSurface, true, [0.20, 0.07, 0.06], 900.0, blob(&[[0.92, 0.85, 0.65, 1.0]]));
// Taco: 15 cm.
thing!(TACO: "taco", "taco", ["hard shell taco", "soft taco"], COOKED, "a folded corn tortilla taco with filling",
    ["dish", "food"], Food @ OnSurface, true, [0.15, 0.05, 0.07], 500.0, blob(YELLOW));
// Portuguese / Hong Kong egg tart: 7 cm.
thing!(EGG_TART: "egg_tart", "egg tart", ["custard tart", "pastel de nata"], COOKED, "a small round egg custard tart",
    ["pastry", "dessert", "food"], Food @ OnSurface, true, [0.07, 0.07, 0.025], 700.0, round(DISC, YELLOW));
// Scone: 7 cm.
thing!(SCONE: "scone", "scone", ["fruit scone", "cream scone"], COOKED, "a round golden scone",
    ["baked goods", "food"], Food @ OnSurface, true, [0.07, 0.07, 0.05], 500.0, round(DOME, GOLDEN));
// Waffle: 12 cm square.
thing!(WAFFLE: "waffle", "waffle", ["belgian waffle"], COOKED, "a square golden waffle with a grid of pockets",
    ["baked goods", "food"], Food @ OnSurface, true, [0.12, 0.12, 0.02], 400.0, Look::Flat { body: GOLDEN, panel: [0.8, 0.55, 0.25, 1.0] });
// Pancake: 15 cm.
thing!(PANCAKE: "pancake", "pancake", ["crepe", "hotcake"], COOKED, "a round flat golden pancake",
    ["baked goods", "food"], Food @ OnSurface, true, [0.15, 0.15, 0.01], 600.0, round(DISC, GOLDEN));
// Flatbread (pita, naan): 20–25 cm.
thing!(FLATBREAD: "flatbread", "flatbread", ["pita", "pitta", "pita bread", "naan", "naan bread", "tortilla", "flat bread"], COOKED,
    "a flat oval bread such as a pita or naan", ["bread", "baked goods", "food"], Food @ OnSurface, true, [0.24, 0.17, 0.012],
    400.0, Look::Flat { body: CREAM, panel: [0.9, 0.75, 0.5, 1.0] });
// French fries in a carton: 10 × 6 × 13 cm.
thing!(FRENCH_FRIES: "french_fries", "french fries", ["fries", "carton of fries", "chips carton"], COOKED,
    "a red carton of golden french fries", ["fast food", "food"], Food @ OnSurface, true, [0.10, 0.06, 0.13], 300.0,
    Look::Appliance { body: RED, front: [0.95, 0.8, 0.3, 1.0], door: [-0.4, 0.4, 0.75, 1.0], knobs: 0, top: false });
// Tub of ice cream: 0.5 l, 12 cm across.
thing!(ICE_CREAM: "ice_cream", "ice cream", ["icecream", "ice cream tub", "tub of ice cream", "gelato"], PACKED, "a round tub of ice cream with a lid",
    ["dessert", "frozen food", "food"], Food @ OnSurface, true, [0.12, 0.12, 0.11], 500.0, jar(PACKS, WHITE_C));
// Bag of sweets: 12 × 4 × 16 cm.
thing!(BAG_OF_SWEETS: "bag_of_sweets", "bag of sweets", ["bag of candy", "candy", "sweets bag", "candy bag"], PACKED,
    "a colourful bag of sweets", ["snack", "confectionery", "food"], Food @ OnSurface, true, [0.12, 0.04, 0.16], 300.0, pack(PACKS));
// Lollipop: 12 cm on its stick.
thing!(LOLLIPOP: "lollipop", "lollipop", ["lolly", "sucker"], COOKED, "a round hard sweet on a stick",
    ["confectionery", "food"], Food @ OnSurface, true, [0.12, 0.03, 0.03], 600.0,
    Look::Long { grip: 0.7, grip_w: 0.15, grip_h: 0.15, handle: &[[0.95, 0.95, 0.93, 1.0]], head: [0.85, 0.15, 0.3, 1.0] });
// Chocolate bar: 100 g, 16 × 7 × 1.2 cm.
thing!(CHOCOLATE_BAR: "chocolate_bar", "chocolate bar", ["chocolate", "bar of chocolate", "candy bar"], PACKED,
    "a wrapped flat bar of chocolate", ["confectionery", "snack", "food"], Food @ OnSurface, true, [0.16, 0.07, 0.012], 700.0,
    Look::Pack { body: &[[0.35, 0.18, 0.1, 1.0], [0.5, 0.1, 0.35, 1.0]], band: LABEL });
// Cereal bar: 10 × 3.5 × 1.5 cm.
thing!(GRANOLA_BAR: "granola_bar", "granola bar", ["cereal bar", "energy bar", "protein bar", "snack bar", "flapjack"], PACKED,
    "a wrapped cereal bar", ["snack", "food"], Food @ OnSurface, true, [0.10, 0.035, 0.015], 700.0, pack(PACKS));
// Bag of crisps: 150 g sharing bag, 20 × 8 × 28 cm.
thing!(BAG_OF_CRISPS: "bag_of_crisps", "bag of crisps", ["crisps", "potato chips", "bag of chips", "crisp packet", "chips bag"],
    PACKED, "a puffed foil bag of crisps", ["snack", "food"], Food @ OnSurface, true, [0.20, 0.08, 0.28], 80.0,
    Look::Pack { body: PACKS, band: [0.95, 0.85, 0.2, 1.0] });
// A bag of food (frozen vegetables, a bag of pasta shapes): 18 × 8 × 25 cm.
thing!(FOOD_BAG: "food_bag", "food bag", ["bagged food", "bag of food", "food pouch", "bag of frozen vegetables"], PACKED,
    "a sealed plastic bag of food", ["packaging", "food"], Food @ OnSurface, true, [0.18, 0.08, 0.25], 250.0, pack(PACKS));
// Dried pasta, 500 g bag: 10 × 4 × 26 cm.
thing!(PASTA: "pasta", "pasta", ["packet of pasta", "bag of pasta", "dried pasta", "spaghetti", "packet of spaghetti"], PACKED,
    "a packet of dried pasta", ["dry goods", "food"], Food @ OnSurface, true, [0.10, 0.04, 0.26], 500.0, pack(PACKS));
// Instant noodle cup: 9 cm across, 10 cm tall.
thing!(NOODLE_CUP: "noodle_cup", "noodle cup", ["instant noodles", "cup noodles", "pot noodle", "ramen cup"], PACKED,
    "a paper cup of instant noodles with a foil lid", ["snack", "food"], Food @ OnSurface, true, [0.095, 0.095, 0.10], 200.0,
    Look::Turned { profile: TUMBLER, body: PACKS, top: 0.97, cap_r: 1.0, cap: STEEL_C });
// Tofu block pack: 11 × 8 × 5 cm.
thing!(TOFU: "tofu", "tofu", ["bean curd", "block of tofu", "tofu pack"], PACKED, "a white block of tofu in its tray",
    ["food"], Food @ OnSurface, true, [0.11, 0.08, 0.05], 900.0, pack(&[[0.95, 0.95, 0.9, 1.0]]));

// --- bottles and jars ---------------------------------------------------------------
// 500 ml PET water bottle: 6.5 cm across, 21 cm tall.
thing!(BOTTLED_WATER: "bottled_water", "bottled water", ["bottle of water", "mineral water", "plastic water bottle"], DRINK,
    "a clear plastic bottle of water with a blue cap", ["bottle", "drink"], Tabletop @ OnSurface, true, [0.065, 0.065, 0.21], 700.0,
    bottle(CLEAR, [0.1, 0.3, 0.8, 1.0]));
// 330 ml long-neck beer bottle: 6 cm across, 23 cm tall.
thing!(BEER_BOTTLE: "beer_bottle", "beer bottle", ["cider", "bottle of cider", "beer", "bottle of beer"], DRINK, "a brown glass bottle of beer with a crown cap",
    ["bottle", "drink"], Tabletop @ OnSurface, true, [0.06, 0.06, 0.23], 750.0, bottle(AMBER, [0.8, 0.75, 0.2, 1.0]));
// 70 cl spirits bottle: 8 cm across, 28 cm tall.
thing!(SPIRITS_BOTTLE: "spirits_bottle", "spirits bottle", ["vodka", "tequila", "bottle of vodka", "alcohol", "bottle of alcohol", "liquor", "liquor bottle", "bottle of spirits", "whisky bottle", "vodka bottle", "gin bottle", "rum bottle"],
    DRINK, "a square-shouldered glass bottle of spirits", ["bottle", "drink"], Tabletop @ OnSurface, true, [0.08, 0.08, 0.28], 700.0,
    bottle(&[[0.7, 0.45, 0.15, 1.0], [0.8, 0.85, 0.88, 1.0]], BLACK_C));
// 1 l juice bottle: 8 cm across, 24 cm tall.
thing!(JUICE_BOTTLE: "juice_bottle", "juice bottle", ["juice", "bottle of juice", "apple juice"], DRINK,
    "a plastic bottle of fruit juice", ["bottle", "drink"], Tabletop @ OnSurface, true, [0.08, 0.08, 0.24], 800.0,
    bottle(ORANGE, [0.2, 0.55, 0.2, 1.0]));
// 500 ml olive oil bottle: 7 cm across, 28 cm tall.
thing!(COOKING_OIL: "cooking_oil", "cooking oil", ["olive oil", "olive oil bottle", "oil bottle", "canola oil", "vegetable oil", "sunflower oil", "bottle of oil"],
    DRINK, "a tall glass bottle of cooking oil", ["bottle", "condiment"], Tabletop @ OnSurface, true, [0.07, 0.07, 0.28], 800.0,
    bottle(GLASS_GREEN, BLACK_C));
// 350 ml vinegar bottle: 6.5 cm across, 24 cm tall.
thing!(VINEGAR: "vinegar_bottle", "vinegar bottle", ["vinegar", "bottle of vinegar", "balsamic vinegar"], DRINK, "a glass bottle of vinegar",
    ["bottle", "condiment"], Tabletop @ OnSurface, true, [0.065, 0.065, 0.24], 800.0, bottle(AMBER, [0.6, 0.1, 0.1, 1.0]));
// Squeezy syrup or honey bottle: 7 × 5 × 17 cm.
thing!(SYRUP_BOTTLE: "syrup_bottle", "syrup bottle", ["syrup", "maple syrup", "honey bottle", "golden syrup", "squeezy honey"], DRINK,
    "a squeezy bottle of syrup or honey", ["bottle", "condiment"], Tabletop @ OnSurface, true, [0.07, 0.05, 0.17], 900.0,
    bottle(AMBER, [0.95, 0.9, 0.8, 1.0]));
// 340 g peanut butter jar: 9 cm across, 12 cm tall.
thing!(PEANUT_BUTTER: "peanut_butter", "peanut butter", ["jar of peanut butter", "nut butter"], PACKED, "a jar of peanut butter with a lid",
    ["spread", "food"], Tabletop @ OnSurface, true, [0.09, 0.09, 0.12], 900.0, jar(BROWN, [0.8, 0.15, 0.1, 1.0]));
// Salsa / dip jar: 8 cm across, 11 cm tall.
thing!(SALSA: "salsa", "salsa", ["jar of salsa", "salsa jar"], PACKED, "a jar of tomato salsa",
    ["condiment", "food"], Tabletop @ OnSurface, true, [0.08, 0.08, 0.11], 900.0, jar(RED, BLACK_C));
// Ice cube tray: 28 × 11 × 4 cm.
thing!(ICE_CUBE_TRAY: "ice_cube_tray", "ice cube tray", ["ice tray", "ice mould"], &["kitchen", "utensil", "tabletop", "small", "graspable"],
    "a plastic tray of square ice cube moulds", ["tray", "kitchenware"], Tabletop @ OnSurface, true, [0.28, 0.11, 0.04], 150.0,
    Look::Flat { body: &[[0.85, 0.9, 0.95, 1.0], [0.3, 0.6, 0.9, 1.0]], panel: [0.7, 0.8, 0.9, 1.0] });
// Cone of a citrus reamer: 10 cm.
thing!(CITRUS_REAMER: "citrus_reamer", "citrus reamer", ["reamer", "lemon squeezer", "citrus squeezer", "lemon reamer"],
    &["kitchen", "utensil", "tabletop", "small", "graspable"], "a ribbed cone on a dish for squeezing lemons",
    ["kitchen utensil", "utensil"], HandHeld @ OnSurface, true, [0.10, 0.10, 0.08], 300.0,
    Look::Turned { profile: &[[0.0, 0.0], [1.0, 0.0], [1.0, 0.3], [0.45, 0.35], [0.1, 1.0], [0.0, 1.0]], body: &[[0.9, 0.9, 0.88, 1.0], [0.95, 0.85, 0.3, 1.0]], top: 1.0, cap_r: 1.0, cap: WHITE_C });
