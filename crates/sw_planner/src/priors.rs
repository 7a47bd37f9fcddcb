//! Size priors for labelled proxies: when a noun has no catalog asset, its stand-in is
//! sized like the things that noun usually names.

/// A prior: its name, a size (width, depth, height, m) and whether items of it move.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Prior {
    pub name: &'static str,
    pub size: [f64; 3],
    pub movable: bool,
}

const TABLETOP: Prior = Prior { name: "tabletop item", size: [0.1, 0.1, 0.14], movable: true };
const HANDHELD: Prior = Prior { name: "hand-held item", size: [0.25, 0.08, 0.06], movable: true };
const CONTAINER: Prior = Prior { name: "floor container", size: [0.5, 0.5, 0.8], movable: false };
const MACHINE: Prior = Prior { name: "machine", size: [1.4, 1.0, 1.7], movable: false };
const FURNITURE: Prior = Prior { name: "furniture", size: [1.2, 0.7, 0.8], movable: false };
const TALL_FIXTURE: Prior = Prior { name: "tall fixture", size: [0.8, 0.6, 1.9], movable: false };
const PLANT: Prior = Prior { name: "plant", size: [0.45, 0.45, 1.0], movable: false };
const VEHICLE: Prior = Prior { name: "vehicle", size: [2.6, 1.2, 2.0], movable: false };
const SMALL_VEHICLE: Prior = Prior { name: "cart", size: [1.0, 0.6, 1.0], movable: false };
const FLOOR_OBJECT: Prior = Prior { name: FALLBACK, size: [0.6, 0.6, 0.9], movable: false };

/// The prior of a proxy whose words say nothing of its size: neither its head noun nor a
/// support it rests on. Any other prior was read from the prompt.
pub const FALLBACK: &str = "floor object";

/// Head nouns (singular) that name each prior.
const BY_NOUN: &[(&[&str], Prior)] = &[
    (
        &[
            "cup",
            "mug",
            "bottle",
            "can",
            "jar",
            "vial",
            "beaker",
            "flask",
            "bowl",
            "plate",
            "glass",
            "phone",
            "toy",
            "fruit",
            "apple",
            "banana",
            "orange",
            "ball",
            "block",
            "cube",
            "sphere",
            "part",
            "widget",
            "gadget",
            "component",
            "sensor",
            "battery",
            "camera",
            "book",
            "box",
            "package",
            "pack",
            "object",
            "item",
            "thing",
            "puck",
            "gear",
            "bolt",
            "nut",
            "screw",
            "pipette",
            "sample",
            "specimen",
            "test tube",
            "pill",
            "medicine",
            "cartridge",
            "spool",
            "lamp",
            "clock",
            "speaker",
            "router",
            "laptop",
            "tablet",
            "keyboard",
            "mouse",
            "monitor",
            "stapler",
            "calculator",
            "tray",
            "container",
            "jug",
            "kettle",
            "pot",
            "pan",
            "dish",
        ],
        TABLETOP,
    ),
    (
        &[
            "tool",
            "wrench",
            "hammer",
            "screwdriver",
            "drill",
            "pliers",
            "knife",
            "pen",
            "pencil",
            "marker",
            "brush",
            "spatula",
            "scissors",
            "file",
        ],
        HANDHELD,
    ),
    (&["barrel", "drum", "bucket", "trash can", "bin", "can", "tank", "cylinder", "keg", "sack", "bag"], CONTAINER),
    (
        &[
            "machine",
            "press",
            "lathe",
            "mill",
            "printer",
            "furnace",
            "oven",
            "generator",
            "compressor",
            "pump",
            "station",
            "unit",
            "welder",
            "robot",
            "engine",
            "motor",
            "cnc",
            "saw",
            "grinder",
            "dispenser",
            "centrifuge",
            "incubator",
            "analyzer",
            "scanner",
            "x-ray",
            "autoclave",
        ],
        MACHINE,
    ),
    (&["desk", "couch", "sofa", "bed", "counter", "bench", "stool", "seat", "ottoman", "island"], FURNITURE),
    (
        &[
            "locker",
            "wardrobe",
            "fridge",
            "refrigerator",
            "freezer",
            "vending machine",
            "rack",
            "tower",
            "column",
            "pillar",
            "cupboard",
            "closet",
            "bookcase",
            "dresser",
            "kiosk",
            "booth",
        ],
        TALL_FIXTURE,
    ),
    (&["plant", "tree", "bush", "shrub", "flower", "fern", "palm", "cactus", "seedling"], PLANT),
    (&["forklift", "car", "truck", "van", "vehicle", "tractor", "lift", "scissor lift"], VEHICLE),
    (&["cart", "trolley", "wagon", "dolly", "pallet jack", "wheelbarrow", "stroller"], SMALL_VEHICLE),
];

/// The prior for a proxy labelled `label`, judged by its last word (or two). Items said
/// to rest on something are tabletop items whatever they are called.
pub(crate) fn prior_for(label: &str, resting_on_something: bool) -> Prior {
    let words: Vec<&str> = label.split_whitespace().collect();
    let last = words.last().copied().unwrap_or("");
    let last_two = if words.len() >= 2 { words[words.len() - 2..].join(" ") } else { String::new() };
    for (nouns, prior) in BY_NOUN {
        if nouns.contains(&last_two.as_str()) {
            return pick(*prior, resting_on_something);
        }
    }
    for (nouns, prior) in BY_NOUN {
        if nouns.contains(&last) {
            return pick(*prior, resting_on_something);
        }
    }
    if resting_on_something { TABLETOP } else { FLOOR_OBJECT }
}

fn pick(prior: Prior, resting_on_something: bool) -> Prior {
    if resting_on_something && !prior.movable { TABLETOP } else { prior }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn priors_follow_the_head_noun_and_the_support() {
        assert_eq!(prior_for("potted plant", false).name, "plant");
        assert_eq!(prior_for("hydraulic press", false).name, "machine");
        assert_eq!(prior_for("vending machine", false).name, "tall fixture");
        assert_eq!(prior_for("widget", true).name, "tabletop item");
        assert_eq!(prior_for("hydraulic press", true).name, "tabletop item");
        assert_eq!(prior_for("flux capacitor", false).name, "floor object");
    }
}
