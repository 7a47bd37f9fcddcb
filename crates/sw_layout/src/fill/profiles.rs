//! What lived-in rooms hold, as data: for each kind of room, the furniture it is used
//! with (and where it stands), and for each kind of surface the small things that belong
//! on it. The room is chosen from the plan's room kind, refined by the prompt's own room
//! words where one plan kind covers several (a bedroom and a dining room are living
//! rooms to the planner). Weights are relative frequencies within a surface's list.

use sw_geom::Rng;
use sw_plan::RoomKind;

use super::FillLevel;

/// Where a piece of furniture stands.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Place {
    /// Back to a wall, facing into the room.
    Wall,
    /// In the open floor, near the middle (tables, chairs round them).
    Open,
}

#[derive(Debug, Clone, Copy)]
pub struct Furniture {
    pub category: &'static str,
    pub count: u32,
    pub place: Place,
}

/// A small thing and how often it turns up on its surface.
#[derive(Debug, Clone, Copy)]
pub struct Item {
    pub category: &'static str,
    pub weight: u32,
}

/// The small things on the surfaces of these host categories.
#[derive(Debug, Clone, Copy)]
pub struct Clutter {
    pub hosts: &'static [&'static str],
    pub items: &'static [Item],
}

#[derive(Debug, Clone, Copy)]
pub struct Profile {
    pub name: &'static str,
    pub furniture: &'static [Furniture],
    pub clutter: &'static [Clutter],
}

/// The prompt's words that ask for a fill, and how much.
pub const PROMPT_WORDS: &[(&str, FillLevel)] = &[
    ("furnished", FillLevel::Furnished),
    ("fully furnished", FillLevel::Furnished),
    ("cluttered", FillLevel::Cluttered),
    ("lived in", FillLevel::Cluttered),
    ("realistic", FillLevel::Cluttered),
    ("messy", FillLevel::Cluttered),
    ("untidy", FillLevel::Cluttered),
];

/// Words before a fill word that take it back ("not cluttered").
pub const NEGATIONS: &[&str] = &["not", "no", "never", "without", "un"];

const fn f(category: &'static str, count: u32, place: Place) -> Furniture {
    Furniture { category, count, place }
}

const fn i(category: &'static str, weight: u32) -> Item {
    Item { category, weight }
}

use Place::{Open, Wall};

// Shared lists of small things.
const BOOKSHELF_ITEMS: &[Item] = &[
    i("book", 10),
    i("picture_frame", 2),
    i("vase", 2),
    i("candle", 1),
    i("board_game", 2),
    i("storage_box", 1),
    i("table_clock", 1),
    i("globe", 1),
    i("notebook", 1),
];
const PANTRY_ITEMS: &[Item] = &[
    i("jar", 4),
    i("cereal_box", 3),
    i("sugar_bag", 2),
    i("drink_can", 2),
    i("bottle", 2),
    i("bowl", 2),
    i("plate", 2),
    i("mug", 2),
    i("milk_carton", 1),
    i("storage_box", 1),
];
const COUNTER_ITEMS: &[Item] = &[
    i("kettle", 3),
    i("toaster", 2),
    i("coffee_maker", 2),
    i("microwave", 1),
    i("knife_block", 2),
    i("cutting_board", 2),
    i("jar", 4),
    i("bowl", 2),
    i("apple", 2),
    i("orange", 2),
    i("banana", 2),
    i("lemon", 1),
    i("tomato", 1),
    i("onion", 1),
    i("mug", 4),
    i("bottle", 3),
    i("drink_can", 1),
    i("plate", 2),
    i("dish_rack", 1),
    i("cereal_box", 2),
    i("milk_carton", 1),
    i("bread_loaf", 2),
    i("pitcher", 1),
    i("frying_pan", 1),
    i("saucepan", 1),
    i("stand_mixer", 1),
    i("blender", 1),
    i("spray_bottle", 1),
    i("detergent_bottle", 1),
    i("rice_cooker", 1),
];
const TABLE_SETTING: &[Item] = &[
    i("plate", 4),
    i("bowl", 2),
    i("mug", 2),
    i("cup", 1),
    i("wine_glass", 2),
    i("drinking_glass", 2),
    i("fork", 2),
    i("spoon", 2),
    i("table_knife", 2),
    i("pitcher", 1),
    i("vase", 1),
    i("apple", 1),
    i("orange", 1),
    i("bottle", 1),
    i("candle", 1),
];
const DESK_ITEMS: &[Item] = &[
    i("monitor", 2),
    i("keyboard", 2),
    i("computer_mouse", 2),
    i("laptop", 1),
    i("desk_lamp", 2),
    i("mug", 2),
    i("notebook", 2),
    i("pen", 2),
    i("pencil", 1),
    i("pen_holder", 2),
    i("stapler", 1),
    i("paper_ream", 2),
    i("phone", 1),
    i("book", 2),
    i("calculator", 1),
    i("tape_dispenser", 1),
    i("scissors", 1),
    i("bottle", 1),
    i("table_clock", 1),
    i("picture_frame", 1),
    i("hole_punch", 1),
];
const OFFICE_SHELF: &[Item] = &[
    i("book", 6),
    i("paper_ream", 2),
    i("storage_box", 2),
    i("picture_frame", 1),
    i("vase", 1),
    i("globe", 1),
    i("table_clock", 1),
    i("pen_holder", 1),
    i("notebook", 2),
];
const WORKBENCH_ITEMS: &[Item] = &[
    i("hammer", 3),
    i("screwdriver", 3),
    i("wrench", 3),
    i("pliers", 2),
    i("tape_measure", 2),
    i("power_drill", 2),
    i("circular_saw", 1),
    i("angle_grinder", 1),
    i("jigsaw", 1),
    i("orbital_sander", 1),
    i("toolbox", 2),
    i("clamp", 2),
    i("spirit_level", 1),
    i("chisel", 1),
    i("hand_saw", 1),
    i("paintbrush", 1),
    i("paint_can", 2),
    i("flashlight", 1),
    i("bench_vise", 1),
    i("bench_grinder", 1),
    i("car_battery", 1),
    i("bucket", 1),
    i("spray_bottle", 1),
];
const GARAGE_SHELF: &[Item] = &[
    i("paint_can", 4),
    i("toolbox", 2),
    i("storage_box", 3),
    i("bucket", 1),
    i("jerry_can", 1),
    i("cardboard_box", 2),
    i("spray_bottle", 2),
    i("detergent_bottle", 1),
    i("flashlight", 1),
    i("car_battery", 1),
    i("bin", 2),
];
const SHOP_SHELF: &[Item] = &[
    i("cereal_box", 4),
    i("drink_can", 3),
    i("bottle", 3),
    i("jar", 3),
    i("milk_carton", 2),
    i("sugar_bag", 2),
    i("detergent_bottle", 1),
    i("spray_bottle", 1),
    i("toilet_paper", 1),
    i("tissue_box", 1),
    i("bread_loaf", 1),
    i("shampoo_bottle", 1),
];
const LAB_BENCH: &[Item] = &[
    i("microscope", 1),
    i("centrifuge", 1),
    i("beaker", 3),
    i("erlenmeyer_flask", 3),
    i("graduated_cylinder", 2),
    i("test_tube_rack", 2),
    i("petri_dish", 3),
    i("pipette", 2),
    i("hot_plate", 1),
    i("lab_balance", 1),
    i("vortex_mixer", 1),
    i("water_bath", 1),
    i("bunsen_burner", 1),
    i("bottle", 2),
    i("jar", 1),
    i("laptop", 1),
    i("notebook", 1),
    i("sharps_container", 1),
];
const LAB_SHELF: &[Item] = &[
    i("beaker", 3),
    i("erlenmeyer_flask", 3),
    i("bottle", 3),
    i("jar", 2),
    i("storage_box", 2),
    i("graduated_cylinder", 1),
    i("petri_dish", 2),
    i("first_aid_kit", 1),
];
const CLINIC_ITEMS: &[Item] = &[
    i("pill_bottle", 4),
    i("first_aid_kit", 1),
    i("sharps_container", 1),
    i("tissue_box", 2),
    i("soap_dispenser", 1),
    i("storage_box", 1),
    i("bottle", 1),
    i("drinking_glass", 1),
];
const STORE_ROOM: &[Item] =
    &[i("cardboard_box", 4), i("bin", 2), i("storage_box", 2), i("crate", 1), i("paint_can", 1), i("toolbox", 1)];
/// On any other table-like surface.
const GENERIC_TABLE: &[Item] = &[
    i("mug", 3),
    i("book", 3),
    i("bottle", 2),
    i("bowl", 1),
    i("plate", 1),
    i("phone", 1),
    i("notebook", 1),
    i("pen", 1),
    i("vase", 1),
    i("apple", 1),
    i("drinking_glass", 1),
];

const KITCHEN: Profile = Profile {
    name: "kitchen",
    furniture: &[
        f("counter", 2, Wall),
        f("fridge", 1, Wall),
        f("stove", 1, Wall),
        f("sink", 1, Wall),
        f("dishwasher", 1, Wall),
        f("shelf", 1, Wall),
        f("dining_table", 1, Open),
        f("chair", 4, Open),
        f("trash_can", 1, Wall),
    ],
    clutter: &[
        Clutter { hosts: &["counter", "kitchen_island"], items: COUNTER_ITEMS },
        Clutter {
            hosts: &["sink"],
            items: &[
                i("plate", 2),
                i("bowl", 2),
                i("mug", 2),
                i("drinking_glass", 2),
                i("dish_rack", 1),
                i("spray_bottle", 1),
            ],
        },
        Clutter {
            hosts: &["stove"],
            items: &[i("frying_pan", 2), i("saucepan", 2), i("stock_pot", 1), i("kettle", 1), i("teapot", 1)],
        },
        Clutter { hosts: &["dining_table", "table", "cafe_table"], items: TABLE_SETTING },
        Clutter { hosts: &["shelf", "bookshelf", "cabinet", "fridge"], items: PANTRY_ITEMS },
    ],
};

const OFFICE: Profile = Profile {
    name: "office",
    furniture: &[
        f("desk", 2, Wall),
        f("chair", 2, Open),
        f("filing_cabinet", 2, Wall),
        f("bookshelf", 2, Wall),
        f("water_cooler", 1, Wall),
        f("potted_plant", 1, Wall),
        f("trash_can", 1, Wall),
        f("coat_rack", 1, Wall),
    ],
    clutter: &[
        Clutter { hosts: &["desk", "table", "workbench"], items: DESK_ITEMS },
        Clutter { hosts: &["bookshelf", "shelf", "filing_cabinet", "cabinet"], items: OFFICE_SHELF },
    ],
};

const LIVING: Profile = Profile {
    name: "living room",
    furniture: &[
        f("sofa", 1, Wall),
        f("tv_stand", 1, Wall),
        f("coffee_table", 1, Open),
        f("armchair", 2, Open),
        f("side_table", 2, Wall),
        f("bookshelf", 2, Wall),
        f("floor_lamp", 1, Wall),
        f("potted_plant", 1, Wall),
        f("ottoman", 1, Open),
    ],
    clutter: &[
        Clutter {
            hosts: &["coffee_table", "table"],
            items: &[
                i("remote_control", 2),
                i("book", 3),
                i("mug", 2),
                i("candle", 2),
                i("vase", 1),
                i("tissue_box", 1),
                i("board_game", 1),
                i("bowl", 1),
                i("apple", 1),
                i("drinking_glass", 1),
            ],
        },
        Clutter {
            hosts: &["tv_stand"],
            items: &[
                i("television", 6),
                i("speaker", 2),
                i("remote_control", 1),
                i("picture_frame", 2),
                i("candle", 1),
                i("book", 2),
                i("vase", 1),
                i("board_game", 1),
            ],
        },
        Clutter {
            hosts: &["side_table", "nightstand"],
            items: &[
                i("desk_lamp", 3),
                i("table_clock", 1),
                i("book", 2),
                i("mug", 1),
                i("picture_frame", 2),
                i("vase", 1),
                i("candle", 1),
                i("remote_control", 1),
            ],
        },
        Clutter { hosts: &["bookshelf", "shelf", "cabinet"], items: BOOKSHELF_ITEMS },
        Clutter { hosts: &["sofa", "armchair"], items: &[i("cushion", 4), i("blanket", 1), i("remote_control", 1)] },
    ],
};

const BEDROOM: Profile = Profile {
    name: "bedroom",
    furniture: &[
        f("bed", 1, Wall),
        f("nightstand", 2, Wall),
        f("wardrobe", 1, Wall),
        f("dresser", 1, Wall),
        f("standing_mirror", 1, Wall),
        f("shoe_rack", 1, Wall),
        f("desk", 1, Wall),
        f("chair", 1, Open),
    ],
    clutter: &[
        Clutter {
            hosts: &["bed"],
            items: &[i("pillow", 3), i("cushion", 2), i("blanket", 2), i("teddy_bear", 1), i("book", 1)],
        },
        Clutter {
            hosts: &["nightstand", "side_table"],
            items: &[
                i("desk_lamp", 3),
                i("table_clock", 2),
                i("book", 2),
                i("drinking_glass", 1),
                i("phone", 1),
                i("picture_frame", 1),
                i("candle", 1),
            ],
        },
        Clutter {
            hosts: &["dresser"],
            items: &[
                i("picture_frame", 2),
                i("vase", 1),
                i("candle", 1),
                i("table_clock", 1),
                i("book", 1),
                i("storage_box", 1),
                i("hair_dryer", 1),
                i("towel", 1),
                i("shoe_box", 1),
            ],
        },
        Clutter {
            hosts: &["wardrobe"],
            items: &[
                i("shoe_box", 2),
                i("storage_box", 2),
                i("blanket", 2),
                i("towel", 1),
                i("backpack", 1),
                i("handbag", 1),
            ],
        },
        Clutter { hosts: &["shoe_rack"], items: &[i("shoe", 4), i("boot", 2)] },
        Clutter { hosts: &["desk", "table"], items: DESK_ITEMS },
        Clutter { hosts: &["bookshelf", "shelf"], items: BOOKSHELF_ITEMS },
    ],
};

const DINING: Profile = Profile {
    name: "dining room",
    furniture: &[
        f("dining_table", 1, Open),
        f("chair", 6, Open),
        f("tv_stand", 1, Wall),
        f("cabinet", 1, Wall),
        f("potted_plant", 1, Wall),
    ],
    clutter: &[
        Clutter { hosts: &["dining_table", "table"], items: TABLE_SETTING },
        Clutter {
            hosts: &["tv_stand"],
            items: &[i("vase", 2), i("candle", 2), i("plate", 2), i("bowl", 2), i("pitcher", 1), i("bottle", 2)],
        },
        Clutter { hosts: &["cabinet", "shelf", "bookshelf"], items: PANTRY_ITEMS },
    ],
};

const BATHROOM: Profile = Profile {
    name: "bathroom",
    furniture: &[
        f("toilet", 1, Wall),
        f("bathroom_vanity", 1, Wall),
        f("bathtub", 1, Wall),
        f("shelf", 1, Wall),
        f("trash_can", 1, Wall),
    ],
    clutter: &[
        Clutter {
            hosts: &["bathroom_vanity"],
            items: &[
                i("soap_dispenser", 2),
                i("toothbrush", 2),
                i("drinking_glass", 1),
                i("shampoo_bottle", 2),
                i("towel", 2),
                i("hair_dryer", 1),
                i("spray_bottle", 1),
                i("candle", 1),
            ],
        },
        Clutter { hosts: &["bathtub"], items: &[i("shampoo_bottle", 2), i("rubber_duck", 1), i("soap_dispenser", 1)] },
        Clutter {
            hosts: &["shelf", "cabinet"],
            items: &[
                i("towel", 4),
                i("toilet_paper", 4),
                i("shampoo_bottle", 2),
                i("soap_dispenser", 1),
                i("storage_box", 1),
            ],
        },
    ],
};

const WORKSHOP: Profile = Profile {
    name: "workshop",
    furniture: &[
        f("workbench", 2, Wall),
        f("tool_chest", 1, Wall),
        f("shelf", 2, Wall),
        f("air_compressor", 1, Wall),
        f("shop_vac", 1, Wall),
        f("welding_machine", 1, Wall),
        f("sawhorse", 2, Open),
        f("trash_can", 1, Wall),
    ],
    clutter: &[
        Clutter { hosts: &["workbench", "table", "sawhorse"], items: WORKBENCH_ITEMS },
        Clutter { hosts: &["shelf", "pallet_rack", "cabinet"], items: GARAGE_SHELF },
        Clutter {
            hosts: &["tool_chest"],
            items: &[
                i("toolbox", 1),
                i("power_drill", 1),
                i("hammer", 1),
                i("flashlight", 1),
                i("tape_measure", 1),
                i("wrench", 1),
            ],
        },
    ],
};

const SHOP: Profile = Profile {
    name: "shop",
    furniture: &[
        f("gondola_shelf", 4, Wall),
        f("checkout_counter", 1, Wall),
        f("display_fridge", 2, Wall),
        f("display_case", 1, Wall),
        f("trash_can", 1, Wall),
    ],
    clutter: &[
        Clutter { hosts: &["gondola_shelf", "shelf"], items: SHOP_SHELF },
        Clutter {
            hosts: &["checkout_counter", "counter"],
            items: &[
                i("cash_register", 3),
                i("shopping_basket", 1),
                i("kitchen_scale", 1),
                i("bottle", 1),
                i("drink_can", 1),
            ],
        },
        Clutter {
            hosts: &["display_case"],
            items: &[i("bread_loaf", 2), i("cup", 2), i("jar", 2), i("plate", 2), i("cash_register", 1)],
        },
    ],
};

const CAFE: Profile = Profile {
    name: "café",
    furniture: &[
        f("counter", 1, Wall),
        f("display_case", 1, Wall),
        f("display_fridge", 1, Wall),
        f("cafe_table", 4, Open),
        f("chair", 6, Open),
        f("potted_plant", 1, Wall),
    ],
    clutter: &[
        Clutter {
            hosts: &["cafe_table", "table", "dining_table"],
            items: &[i("mug", 2), i("cup", 2), i("plate", 1), i("drinking_glass", 1), i("spoon", 1), i("vase", 1)],
        },
        Clutter {
            hosts: &["counter"],
            items: &[
                i("espresso_machine", 2),
                i("coffee_maker", 1),
                i("cash_register", 1),
                i("mug", 3),
                i("cup", 3),
                i("kettle", 1),
                i("jar", 2),
                i("pitcher", 1),
                i("bread_loaf", 1),
                i("plate", 2),
                i("kitchen_scale", 1),
            ],
        },
        Clutter { hosts: &["display_case"], items: &[i("bread_loaf", 2), i("cup", 2), i("jar", 2), i("plate", 2)] },
    ],
};

const CLASSROOM: Profile = Profile {
    name: "classroom",
    furniture: &[
        f("desk", 4, Open),
        f("chair", 6, Open),
        f("bookshelf", 2, Wall),
        f("lectern", 1, Wall),
        f("trash_can", 1, Wall),
    ],
    clutter: &[
        Clutter {
            hosts: &["desk", "table"],
            items: &[
                i("book", 3),
                i("notebook", 3),
                i("pencil", 2),
                i("pen", 2),
                i("marker", 1),
                i("calculator", 1),
                i("scissors", 1),
                i("backpack", 1),
                i("globe", 1),
                i("pen_holder", 1),
                i("paper_ream", 1),
                i("laptop", 1),
            ],
        },
        Clutter { hosts: &["bookshelf", "shelf"], items: BOOKSHELF_ITEMS },
    ],
};

const LAB: Profile = Profile {
    name: "lab",
    furniture: &[
        f("workbench", 2, Wall),
        f("fume_hood", 1, Wall),
        f("fridge", 1, Wall),
        f("shelf", 1, Wall),
        f("sink", 1, Wall),
        f("stool", 2, Open),
    ],
    clutter: &[
        Clutter { hosts: &["workbench", "counter", "table", "desk"], items: LAB_BENCH },
        Clutter { hosts: &["shelf", "cabinet", "fridge"], items: LAB_SHELF },
        Clutter { hosts: &["sink"], items: &[i("beaker", 2), i("soap_dispenser", 1), i("bottle", 1)] },
    ],
};

const CLINIC: Profile = Profile {
    name: "clinic",
    furniture: &[
        f("hospital_bed", 1, Wall),
        f("exam_table", 1, Open),
        f("iv_pole", 1, Wall),
        f("cabinet", 1, Wall),
        f("desk", 1, Wall),
        f("chair", 2, Open),
        f("wheelchair", 1, Wall),
        f("sink", 1, Wall),
    ],
    clutter: &[
        Clutter { hosts: &["desk", "table"], items: DESK_ITEMS },
        Clutter { hosts: &["cabinet", "shelf", "side_table", "nightstand"], items: CLINIC_ITEMS },
        Clutter { hosts: &["sink"], items: &[i("soap_dispenser", 2), i("tissue_box", 1)] },
    ],
};

const STORAGE: Profile = Profile {
    name: "storage room",
    furniture: &[f("shelf", 4, Wall), f("cabinet", 1, Wall)],
    clutter: &[Clutter {
        hosts: &["shelf", "pallet_rack", "gondola_shelf", "cabinet", "workbench", "table"],
        items: STORE_ROOM,
    }],
};

/// Room words of the prompt that choose a profile over its plan room kind.
const ROOM_WORDS: &[(&str, &Profile)] = &[
    ("bedroom", &BEDROOM),
    ("bed room", &BEDROOM),
    ("nursery", &BEDROOM),
    ("dining room", &DINING),
    ("bathroom", &BATHROOM),
    ("washroom", &BATHROOM),
    ("restroom", &BATHROOM),
    ("laundry", &BATHROOM),
    ("cafe", &CAFE),
    ("café", &CAFE),
    ("coffee shop", &CAFE),
    ("restaurant", &CAFE),
    ("canteen", &CAFE),
    ("study", &OFFICE),
];

/// The profile of a room.
pub fn for_room(kind: RoomKind, prompt: &str) -> &'static Profile {
    let text = format!(" {} ", prompt.to_lowercase().replace(|c: char| !c.is_alphanumeric() && c != 'é', " "));
    if let Some((_, p)) = ROOM_WORDS.iter().find(|(w, _)| text.contains(&format!(" {w} "))) {
        return p;
    }
    match kind {
        RoomKind::Kitchen => &KITCHEN,
        RoomKind::Office => &OFFICE,
        RoomKind::LivingRoom | RoomKind::Room | RoomKind::Tabletop => &LIVING,
        RoomKind::Workshop | RoomKind::Garage | RoomKind::Factory => &WORKSHOP,
        RoomKind::RetailStore | RoomKind::Pharmacy => &SHOP,
        RoomKind::Classroom => &CLASSROOM,
        RoomKind::Lab | RoomKind::CleanRoom => &LAB,
        RoomKind::Hospital => &CLINIC,
        RoomKind::Warehouse
        | RoomKind::StorageRoom
        | RoomKind::Closet
        | RoomKind::LoadingDock
        | RoomKind::DataCentre
        | RoomKind::Greenhouse => &STORAGE,
    }
}

/// The small things for a host of `category` in `profile`; any table-like surface gets
/// the generic list when the profile names none for it.
pub fn clutter_for(category: &str, profile: &Profile) -> Option<&'static [Item]> {
    if let Some(c) = profile.clutter.iter().find(|c| c.hosts.contains(&category)) {
        return Some(c.items);
    }
    let cat = sw_catalog::find(category)?;
    (cat.has_tag("surface") && cat.has_tag("furniture")).then_some(GENERIC_TABLE)
}

/// One item, by weight.
pub fn pick(items: &[Item], rng: &mut Rng) -> Option<Item> {
    let total: u32 = items.iter().map(|i| i.weight).sum();
    if total == 0 {
        return None;
    }
    let mut r = (rng.next_u64() % u64::from(total)) as u32;
    for it in items {
        if r < it.weight {
            return Some(*it);
        }
        r -= it.weight;
    }
    items.last().copied()
}

/// Every profile, for the tests and the benchmark.
pub const ALL: &[&Profile] = &[
    &KITCHEN, &OFFICE, &LIVING, &BEDROOM, &DINING, &BATHROOM, &WORKSHOP, &SHOP, &CAFE, &CLASSROOM, &LAB, &CLINIC,
    &STORAGE,
];
