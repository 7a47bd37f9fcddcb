//! The things of garages, workshops, clinics and offices that people name and the
//! catalog lacked (issue 21): tyre and wheel machines, jacks, laser cutters,
//! generators, a dental chair, photocopiers, binders and the small hand tools and
//! supplies of benches and desks. Built like `household`: one collision box over the
//! whole size, the look drawn inside it; sizes from published product ranges.

use sw_geom::{AssetBuilder, PlacementKind, Rng};

use super::forms::{def, size3, whd};
use super::household::{bar_x, hull, mass, part, sized, turn};
use super::kit::{DARK, INK, LABEL_WHITE, PLASTIC, RUBBER, STEEL, WOOD, collider_between, pick, shade};
use crate::{Category, Kind, ParamDef, Params};

const GARAGE: &[&str] = &["garage", "workshop", "automotive", "floor", "heavy"];
const BENCH: &[&str] = &["workshop", "tool", "tabletop", "small", "graspable"];
const DESK: &[&str] = &["office", "stationery", "tabletop", "small", "graspable"];

/// A machine cabinet: a body, a darker top part and a control panel on its front (+Y).
fn cabinet_machine(b: &mut AssetBuilder, s: (f64, f64, f64), body: usize, dark: usize, top: f64) {
    part(b, s, [-0.5, -0.5, 0.0], [0.5, 0.5, top], body);
    part(b, s, [-0.3, 0.49, top * 0.55], [0.3, 0.505, top * 0.9], dark);
}

pub(crate) const TYRE_CHANGER: Category = def(
    "tyre_changer",
    "tyre changer",
    &[
        "tire changer",
        "tyre changing machine",
        "tire changing machine",
        "tyre machine",
        "tire machine",
        "tyre fitting machine",
    ],
    GARAGE,
    "a tyre changer: a cabinet with a wheel turntable on top and a mount-demount arm on a post",
    &["garage equipment", "machine"],
    Kind::Machine,
    PlacementKind::Floor,
    false,
    // Corghi / Hunter changers: 95–110 × 75–100 × 170–190 cm with the arm up.
    &size3(1.0, 0.85, 1.8, 0.8, 1.2, 0.03),
    build_tyre_changer,
);

fn build_tyre_changer(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let body =
        b.material("body", pick(rng, &[[0.75, 0.1, 0.1, 1.0], [0.15, 0.3, 0.6, 1.0], [0.2, 0.2, 0.22, 1.0]]), true);
    let dark = b.material("panel", INK, false);
    let table = b.material("turntable", pick(rng, STEEL), false);
    cabinet_machine(b, s, body, dark, 0.5);
    part(b, s, [-0.45, -0.45, 0.5], [0.35, 0.35, 0.53], table);
    part(b, s, [0.38, 0.3, 0.0], [0.5, 0.45, 1.0], body);
    part(b, s, [-0.1, 0.33, 0.9], [0.5, 0.42, 0.96], body);
    part(b, s, [-0.08, 0.0, 0.6], [-0.02, 0.4, 0.94], table);
    hull(b, s.0, s.1, s.2);
    0.0
}

pub(crate) const WHEEL_BALANCER: Category = def(
    "wheel_balancer",
    "wheel balancer",
    &["wheel balancing machine", "tyre balancer", "tire balancer", "balancing machine", "wheel balancing rig"],
    GARAGE,
    "a wheel balancer: a cabinet with a shaft for the wheel, a hinged hood over it and a display",
    &["garage equipment", "machine"],
    Kind::Machine,
    PlacementKind::Floor,
    false,
    // Hunter / Beissbarth balancers: 100–130 × 80–100 × 130–160 cm with the hood up.
    &size3(1.1, 0.9, 1.45, 0.8, 1.2, 0.03),
    build_wheel_balancer,
);

fn build_wheel_balancer(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let body =
        b.material("body", pick(rng, &[[0.2, 0.22, 0.25, 1.0], [0.75, 0.1, 0.1, 1.0], [0.9, 0.9, 0.88, 1.0]]), true);
    let dark = b.material("display", INK, false);
    let steel = b.material("shaft", pick(rng, STEEL), false);
    part(b, s, [-0.5, -0.2, 0.0], [0.2, 0.5, 0.62], body);
    part(b, s, [-0.45, 0.3, 0.62], [0.15, 0.5, 1.0], dark);
    bar_x(b, s, [0.2, 0.45], [0.15, 0.45], 0.02, steel);
    part(b, s, [0.15, -0.5, 0.45], [0.5, 0.5, 0.72], body);
    hull(b, s.0, s.1, s.2);
    0.0
}

pub(crate) const CAR_JACK: Category = def(
    "car_jack",
    "car jack",
    &["trolley jack", "floor jack", "hydraulic jack", "jack", "scissor jack", "garage jack", "bottle jack"],
    &["garage", "workshop", "automotive", "tool", "graspable"],
    "a hydraulic trolley jack: a low steel frame on wheels, a lifting arm with a saddle and a long handle",
    &["garage equipment", "tool"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // 2–3 t trolley jacks: 60–75 × 28–36 × 14–18 cm (handle off).
    &sized(0.65, 0.3, 0.15),
    build_car_jack,
);

fn build_car_jack(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let m =
        b.material("frame", pick(rng, &[[0.75, 0.1, 0.1, 1.0], [0.1, 0.1, 0.12, 1.0], [0.95, 0.7, 0.1, 1.0]]), true);
    let wheel = b.material("wheels", RUBBER[0], false);
    let steel = b.material("saddle", pick(rng, STEEL), false);
    part(b, s, [-0.5, -0.4, 0.1], [0.45, 0.4, 0.7], m);
    for (x, y) in [(-0.48, -0.5), (-0.48, 0.35), (0.35, -0.5), (0.35, 0.35)] {
        part(b, s, [x, y, 0.0], [x + 0.12, y + 0.15, 0.35], wheel);
    }
    part(b, s, [0.35, -0.2, 0.7], [0.5, 0.2, 1.0], steel);
    hull(b, s.0, s.1, s.2);
    mass(s.0, s.1, s.2, 800.0).clamp(8.0, 40.0)
}

pub(crate) const LASER_CUTTER: Category = def(
    "laser_cutter",
    "laser cutter",
    &["laser engraver", "co2 laser", "laser cutting machine", "laser engraving machine", "glowforge"],
    &["workshop", "makerspace", "machine", "floor"],
    "a CO2 laser cutter: a cabinet with a hinged glass lid on a stand",
    &["machine tool", "machine"],
    Kind::Machine,
    PlacementKind::Floor,
    false,
    // 60–100 W CO2 cutters on their stands: 100–140 × 70–95 × 95–110 cm.
    &size3(1.2, 0.8, 1.05, 0.5, 1.5, 0.03),
    build_laser_cutter,
);

fn build_laser_cutter(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let body =
        b.material("body", pick(rng, &[[0.92, 0.92, 0.9, 1.0], [0.15, 0.3, 0.6, 1.0], [0.2, 0.2, 0.22, 1.0]]), true);
    let glass = b.material("lid_glass", [0.55, 0.3, 0.15, 1.0], false);
    let dark = b.material("panel", INK, false);
    let stand = b.material("stand", pick(rng, DARK), false);
    part(b, s, [-0.5, -0.5, 0.55], [0.5, 0.5, 0.9], body);
    part(b, s, [-0.48, -0.48, 0.9], [0.48, 0.48, 1.0], body);
    part(b, s, [-0.4, -0.3, 0.995], [0.3, 0.4, 1.0], glass);
    part(b, s, [0.32, 0.49, 0.6], [0.46, 0.505, 0.85], dark);
    for (x, y) in [(-0.48, -0.48), (0.43, -0.48), (-0.48, 0.43), (0.43, 0.43)] {
        part(b, s, [x, y, 0.0], [x + 0.05, y + 0.05, 0.55], stand);
    }
    hull(b, s.0, s.1, s.2);
    0.0
}

pub(crate) const GENERATOR: Category = def(
    "generator",
    "generator",
    &["petrol generator", "portable generator", "diesel generator", "genset", "inverter generator", "generator set"],
    &["garage", "outdoor", "construction", "machine", "floor"],
    "a portable petrol generator in an open tube frame with a fuel tank on top",
    &["machine", "power source"],
    Kind::Machine,
    PlacementKind::Floor,
    false,
    // 3–5 kW open-frame generators: 55–70 × 42–55 × 42–55 cm.
    &size3(0.6, 0.45, 0.47, 0.6, 1.6, 0.03),
    build_generator,
);

fn build_generator(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let tank =
        b.material("tank", pick(rng, &[[0.85, 0.1, 0.08, 1.0], [0.95, 0.7, 0.1, 1.0], [0.15, 0.45, 0.2, 1.0]]), true);
    let frame = b.material("frame", INK, false);
    let engine = b.material("engine", pick(rng, STEEL), false);
    for y in [-0.5, 0.45] {
        part(b, s, [-0.5, y, 0.0], [0.5, y + 0.05, 0.06], frame);
        for x in [-0.5, 0.45] {
            part(b, s, [x, y, 0.0], [x + 0.05, y + 0.05, 1.0], frame);
        }
    }
    part(b, s, [-0.4, -0.4, 0.06], [0.4, 0.4, 0.6], engine);
    part(b, s, [-0.4, -0.35, 0.6], [0.4, 0.35, 0.95], tank);
    hull(b, s.0, s.1, s.2);
    0.0
}

pub(crate) const DENTAL_CHAIR: Category = def(
    "dental_chair",
    "dental chair",
    &["dentist's chair", "dentist chair", "dental unit", "treatment chair"],
    &["clinic", "hospital", "medical", "furniture", "floor", "heavy"],
    "a reclining dental chair on a pedestal with an instrument tray arm and a lamp",
    &["chair", "medical equipment", "furniture"],
    Kind::Furniture,
    PlacementKind::Floor,
    false,
    // Dental units reclined: 175–200 × 70–90 × 110–150 cm with the lamp.
    &size3(1.9, 0.8, 1.3, 0.8, 1.15, 0.03),
    build_dental_chair,
);

fn build_dental_chair(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let seat = b.material(
        "upholstery",
        pick(rng, &[[0.15, 0.45, 0.65, 1.0], [0.9, 0.9, 0.88, 1.0], [0.2, 0.55, 0.45, 1.0]]),
        true,
    );
    let base = b.material("base", [0.92, 0.92, 0.92, 1.0], false);
    let lamp = b.material("lamp", pick(rng, DARK), false);
    part(b, s, [-0.2, -0.2, 0.0], [0.2, 0.2, 0.35], base);
    part(b, s, [-0.5, -0.3, 0.35], [0.45, 0.3, 0.45], seat);
    part(b, s, [-0.5, -0.3, 0.45], [-0.3, 0.3, 0.55], seat);
    part(b, s, [0.35, -0.3, 0.45], [0.45, 0.3, 0.5], seat);
    part(b, s, [0.15, 0.3, 0.3], [0.22, 0.5, 0.95], lamp);
    part(b, s, [-0.2, 0.3, 0.92], [0.22, 0.5, 1.0], lamp);
    hull(b, s.0, s.1, s.2);
    0.0
}

pub(crate) const PHOTOCOPIER: Category = def(
    "photocopier",
    "photocopier",
    &["copier", "copy machine", "photocopy machine", "multifunction copier", "office copier", "xerox machine"],
    &["office", "appliance", "floor", "electronics"],
    "a floor-standing office photocopier with paper drawers and a document feeder on top",
    &["office machine", "machine"],
    Kind::LargeAppliance,
    PlacementKind::Floor,
    false,
    // Canon imageRUNNER / Ricoh MP floor models: 58–65 × 65–75 × 110–125 cm.
    &size3(0.6, 0.68, 1.15, 0.8, 1.2, 0.03),
    build_photocopier,
);

fn build_photocopier(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let body = b.material("body", pick(rng, &[[0.9, 0.9, 0.88, 1.0], [0.82, 0.83, 0.84, 1.0]]), true);
    let dark = b.material("trim", pick(rng, DARK), false);
    part(b, s, [-0.5, -0.5, 0.0], [0.5, 0.5, 0.85], body);
    for z in [0.1, 0.3, 0.5] {
        part(b, s, [-0.45, 0.49, z], [0.45, 0.505, z + 0.15], dark);
    }
    part(b, s, [-0.45, -0.4, 0.85], [0.45, 0.45, 1.0], body);
    part(b, s, [0.1, -0.5, 0.8], [0.45, -0.4, 0.9], dark);
    hull(b, s.0, s.1, s.2);
    0.0
}

pub(crate) const RING_BINDER: Category = def(
    "ring_binder",
    "ring binder",
    &["binder", "lever arch file", "folder", "file folder", "document folder", "box file", "arch file"],
    DESK,
    "a ring binder lying flat, its spine along one side",
    &["file", "stationery"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // A4 lever arch files: 32 × 28.5 × 5–8 cm.
    &size3(0.32, 0.285, 0.06, 0.6, 1.4, 0.04),
    build_ring_binder,
);

fn build_ring_binder(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let cover = b.material(
        "cover",
        pick(rng, &[[0.1, 0.2, 0.5, 1.0], [0.1, 0.1, 0.1, 1.0], [0.6, 0.1, 0.1, 1.0], [0.2, 0.5, 0.25, 1.0]]),
        true,
    );
    let paper = b.material("paper", LABEL_WHITE, false);
    part(b, s, [-0.5, -0.5, 0.0], [0.5, 0.5, 0.1], cover);
    part(b, s, [-0.47, -0.5, 0.1], [0.5, 0.45, 0.9], paper);
    part(b, s, [-0.5, -0.5, 0.0], [-0.45, 0.5, 1.0], cover);
    part(b, s, [-0.5, -0.5, 0.9], [0.5, 0.5, 1.0], cover);
    hull(b, s.0, s.1, s.2);
    0.9
}

pub(crate) const TOWEL_RAIL: Category = Category {
    name: "towel_rail",
    display: "towel rail",
    synonyms: &["towel rack", "towel bar", "towel holder", "towel rod", "towel hanger"],
    tags: &["bathroom", "kitchen", "wall", "fixture"],
    description: "a chrome towel rail on two brackets on the wall",
    is_a: &["rail", "fixture"],
    kind: Kind::Fixture,
    placement: PlacementKind::WallMounted,
    // Bathroom towel bars: 45–75 cm long, 6–10 cm off the wall, 3–6 cm high.
    params: &[
        ParamDef::new("width", 0.6, 0.3, 1.0, 0.05, "along the wall"),
        ParamDef::new("depth", 0.08, 0.05, 0.12, 0.05, "off the wall"),
        ParamDef::new("height", 0.05, 0.03, 0.08, 0.05, "bracket height"),
        ParamDef::new("mount_height", 1.0, 0.5, 1.3, 0.05, "floor to the rail"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_towel_rail,
};

/// A rail on two brackets, its back on the wall (−Y); its origin on the floor below it.
fn build_towel_rail(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = whd(p);
    let z0 = p.get("mount_height");
    let chrome =
        b.material("chrome", pick(rng, &[[0.8, 0.82, 0.85, 1.0], [0.1, 0.1, 0.1, 1.0], [0.75, 0.62, 0.35, 1.0]]), true);
    for x in [-w / 2.0, w / 2.0 - 0.03] {
        super::kit::decal_between(b, [x, -d / 2.0, z0], [x + 0.03, d / 2.0, z0 + h], chrome);
    }
    super::kit::decal_between(b, [-w / 2.0, d / 2.0 - 0.025, z0 + h * 0.3], [w / 2.0, d / 2.0, z0 + h * 0.8], chrome);
    collider_between(b, [-w / 2.0, -d / 2.0, z0], [w / 2.0, d / 2.0, z0 + h]);
    0.0
}

pub(crate) const WINE_RACK: Category = def(
    "wine_rack",
    "wine rack",
    &["bottle rack", "wine bottle rack", "wine shelf", "wine holder"],
    &["kitchen", "home", "bar", "storage", "furniture"],
    "a wooden wine rack with rows of bottle holes, a few bottles in it",
    &["rack", "storage", "furniture"],
    Kind::Furniture,
    PlacementKind::AgainstWall,
    false,
    // Free-standing 12–24 bottle racks: 45–70 × 23–30 × 45–90 cm.
    &size3(0.6, 0.25, 0.7, 0.6, 1.6, 0.04),
    build_wine_rack,
);

fn build_wine_rack(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let wood = b.material("wood", pick(rng, WOOD), true);
    let bottle = b.material("bottles", [0.12, 0.25, 0.12, 1.0], false);
    for x in [-0.5, -0.17, 0.17, 0.47] {
        part(b, s, [x, -0.5, 0.0], [x + 0.03, 0.5, 1.0], wood);
    }
    for z in [0.0, 0.32, 0.64, 0.96] {
        part(b, s, [-0.5, -0.5, z], [0.5, 0.5, z + 0.04], wood);
    }
    for (x, z) in [(-0.33, 0.15), (0.0, 0.47), (0.33, 0.15), (0.33, 0.79)] {
        part(b, s, [x - 0.08, -0.5, z], [x + 0.08, 0.5, z + 0.15], bottle);
    }
    hull(b, s.0, s.1, s.2);
    0.0
}

/// A bench instrument: a case, a screen or dial panel on its front (+Y), knobs.
fn instrument(p: &Params, rng: &mut Rng, b: &mut AssetBuilder, screen: [f32; 4]) -> f64 {
    let s = whd(p);
    let case =
        b.material("case", pick(rng, &[[0.85, 0.85, 0.83, 1.0], [0.25, 0.3, 0.4, 1.0], [0.15, 0.15, 0.16, 1.0]]), true);
    let face = b.material("screen", screen, false);
    let knob = b.material("knobs", INK, false);
    part(b, s, [-0.5, -0.5, 0.0], [0.5, 0.5, 1.0], case);
    part(b, s, [-0.45, 0.49, 0.2], [0.1, 0.505, 0.85], face);
    part(b, s, [0.2, 0.49, 0.3], [0.42, 0.505, 0.7], knob);
    hull(b, s.0, s.1, s.2);
    mass(s.0, s.1, s.2, 600.0)
}

pub(crate) const OSCILLOSCOPE: Category = def(
    "oscilloscope",
    "oscilloscope",
    &["scope", "digital oscilloscope"],
    &["lab", "electronics", "workshop", "tabletop"],
    "a bench oscilloscope: a case with a screen on the left and knobs on the right",
    &["test equipment", "lab equipment", "instrument"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // Rigol / Siglent bench scopes: 31–36 × 10–14 × 15–18 cm.
    &sized(0.33, 0.13, 0.16),
    build_oscilloscope,
);

fn build_oscilloscope(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    instrument(p, rng, b, [0.1, 0.25, 0.35, 1.0])
}

pub(crate) const SOLDERING_STATION: Category = def(
    "soldering_station",
    "soldering station",
    &["soldering iron", "solder station", "rework station", "soldering iron station", "hot air station"],
    &["electronics", "workshop", "lab", "tabletop", "small"],
    "a soldering station: a control box with a dial and the iron in its holder beside it",
    &["tool", "electronics equipment"],
    Kind::SmallAppliance,
    PlacementKind::OnSurface,
    true,
    // Hakko FX-888 / Weller WE1010 with the holder: 20–25 × 14–18 × 10–12 cm.
    &sized(0.22, 0.16, 0.11),
    build_soldering_station,
);

fn build_soldering_station(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let case =
        b.material("case", pick(rng, &[[0.2, 0.4, 0.75, 1.0], [0.15, 0.15, 0.16, 1.0], [0.85, 0.5, 0.1, 1.0]]), true);
    let steel = b.material("holder", pick(rng, STEEL), false);
    let dial = b.material("dial", INK, false);
    part(b, s, [-0.5, -0.5, 0.0], [0.05, 0.5, 0.85], case);
    part(b, s, [-0.4, 0.49, 0.3], [-0.05, 0.505, 0.7], dial);
    part(b, s, [0.1, -0.3, 0.0], [0.5, 0.3, 0.15], case);
    part(b, s, [0.25, -0.08, 0.15], [0.38, 0.08, 1.0], steel);
    hull(b, s.0, s.1, s.2);
    1.3
}

pub(crate) const EXTENSION_LEAD: Category = def(
    "extension_lead",
    "extension lead",
    &["extension cord", "power strip", "extension cable", "multi-plug", "power bar", "surge protector", "gang socket"],
    &["office", "home", "electrical", "tabletop", "small", "graspable"],
    "a four-way extension lead: a socket strip lying flat",
    &["electrical accessory"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Four-way leads: 30–40 × 5–6 × 3.5–4.5 cm (cable coiled under it).
    &sized(0.35, 0.055, 0.04),
    build_extension_lead,
);

fn build_extension_lead(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let body = b.material("body", pick(rng, &[[0.95, 0.95, 0.94, 1.0], [0.12, 0.12, 0.13, 1.0]]), true);
    let holes = b.material("sockets", INK, false);
    part(b, s, [-0.5, -0.5, 0.0], [0.5, 0.5, 1.0], body);
    for x in [-0.35, -0.12, 0.11, 0.34] {
        part(b, s, [x - 0.06, -0.2, 0.98], [x + 0.06, 0.2, 1.0], holes);
    }
    hull(b, s.0, s.1, s.2);
    0.45
}

/// A hand tool lying along X: a handle (−X) and a working part (+X).
fn hand_tool(
    p: &Params,
    rng: &mut Rng,
    b: &mut AssetBuilder,
    handle_frac: f64,
    head_half_width: f64,
    head: [f32; 4],
    handle: &[[f32; 4]],
) -> f64 {
    let s = whd(p);
    let grip = b.material("handle", pick(rng, handle), true);
    let metal = b.material("metal", head, false);
    let split = -0.5 + handle_frac;
    part(b, s, [-0.5, -0.2, 0.0], [split, 0.2, 0.8], grip);
    part(b, s, [split - 0.01, -head_half_width, 0.0], [0.5, head_half_width, 1.0], metal);
    hull(b, s.0, s.1, s.2);
    mass(s.0, s.1, s.2, 1500.0).clamp(0.01, 3.0)
}

pub(crate) const ALLEN_KEY: Category = def(
    "allen_key",
    "allen key",
    &["hex key", "allen wrench", "hex wrench", "allen keys", "hex keys", "set of allen keys"],
    BENCH,
    "an L-shaped hexagonal steel allen key",
    &["hand tool", "tool", "key"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // 5–8 mm keys: 8–10 × 2.5–3.5 cm arms, 5–8 mm thick.
    &size3(0.09, 0.03, 0.006, 0.5, 1.8, 0.05),
    build_allen_key,
);

fn build_allen_key(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let m = b.material("steel", pick(rng, &[[0.15, 0.15, 0.16, 1.0], [0.7, 0.72, 0.75, 1.0]]), true);
    part(b, s, [-0.5, -0.5, 0.0], [0.5, -0.3, 1.0], m);
    part(b, s, [0.38, -0.5, 0.0], [0.5, 0.5, 1.0], m);
    hull(b, s.0, s.1, s.2);
    0.03
}

pub(crate) const AXE: Category = def(
    "axe",
    "axe",
    &["ax", "hatchet", "wood axe", "splitting axe", "felling axe", "hand axe"],
    &["garden", "outdoor", "workshop", "tool", "graspable"],
    "an axe lying flat: a wooden haft with a steel head at one end",
    &["hand tool", "tool"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Fiskars / Gransfors axes: 45–75 cm long, heads 15–20 cm, 3–5 cm thick.
    &sized(0.6, 0.17, 0.04),
    build_axe,
);

fn build_axe(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    hand_tool(p, rng, b, 0.85, 0.5, [0.45, 0.46, 0.5, 1.0], WOOD)
}

pub(crate) const SPADE: Category = def(
    "spade",
    "spade",
    &["shovel", "garden spade", "digging spade", "snow shovel", "garden shovel"],
    &["garden", "outdoor", "tool", "graspable"],
    "a garden spade lying flat: a long handle with a D-grip and a steel blade",
    &["garden tool", "tool"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Garden spades: 95–105 cm long, blades 18–20 cm wide.
    &sized(1.0, 0.19, 0.05),
    build_spade,
);

fn build_spade(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    hand_tool(p, rng, b, 0.7, 0.5, [0.5, 0.52, 0.55, 1.0], WOOD)
}

pub(crate) const THERMOMETER: Category = def(
    "thermometer",
    "thermometer",
    &["clinical thermometer", "digital thermometer", "meat thermometer", "lab thermometer", "ear thermometer"],
    &["medical", "lab", "kitchen", "tabletop", "small", "graspable"],
    "a slim digital thermometer with a small display",
    &["instrument", "medical device"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Digital stick thermometers: 12–15 cm long, 2 cm wide, 1 cm thick.
    &sized(0.135, 0.02, 0.012),
    build_thermometer,
);

fn build_thermometer(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    hand_tool(p, rng, b, 0.6, 0.2, [0.75, 0.77, 0.8, 1.0], &[[0.95, 0.95, 0.95, 1.0], [0.3, 0.55, 0.85, 1.0]])
}

pub(crate) const SYRINGE: Category = def(
    "syringe",
    "syringe",
    &["hypodermic syringe", "medical syringe", "hypodermic needle", "oral syringe"],
    &["medical", "lab", "tabletop", "small", "graspable"],
    "a plastic syringe with its plunger, lying down",
    &["medical device", "lab equipment"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // 5–10 ml syringes: 10–13 cm long, 1.5–2 cm across.
    &sized(0.12, 0.018, 0.018),
    build_syringe,
);

fn build_syringe(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let barrel = b.material("barrel", pick(rng, &[[0.9, 0.92, 0.95, 1.0], [0.85, 0.9, 0.85, 1.0]]), true);
    let plunger = b.material("plunger", pick(rng, PLASTIC), false);
    bar_x(b, s, [-0.2, 0.4], [0.0, 0.5], 0.45, barrel);
    bar_x(b, s, [-0.5, -0.19], [0.0, 0.5], 0.25, plunger);
    bar_x(b, s, [0.39, 0.5], [0.0, 0.5], 0.1, plunger);
    hull(b, s.0, s.1, s.2);
    0.02
}

pub(crate) const TAPE_ROLL: Category = def(
    "tape_roll",
    "sticky tape",
    &[
        "roll of tape",
        "sellotape",
        "scotch tape",
        "duct tape",
        "masking tape",
        "roll of duct tape",
        "packing tape",
        "gaffer tape",
        "tape",
    ],
    &["office", "stationery", "tabletop", "small", "graspable", "round"],
    "a roll of adhesive tape lying flat",
    &["stationery", "supply"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Sellotape 24 mm × 66 m: 7.5 cm across, 2.4 cm wide; duct tape 10 × 5 cm.
    &size3(0.075, 0.075, 0.024, 0.6, 1.6, 0.05),
    build_tape_roll,
);

fn build_tape_roll(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let tape =
        b.material("tape", pick(rng, &[[0.85, 0.8, 0.6, 1.0], [0.6, 0.62, 0.64, 1.0], [0.9, 0.88, 0.75, 1.0]]), true);
    let core = b.material("core", [0.7, 0.55, 0.38, 1.0], false);
    turn(b, s, [0.0, 1.0], &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], tape);
    turn(b, (s.0 * 0.6, s.1 * 0.6, s.2), [0.0, 1.005], &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], core);
    hull(b, s.0, s.1, s.2);
    0.08
}

pub(crate) const STICKY_NOTES: Category = def(
    "sticky_notes",
    "sticky notes",
    &["post-it notes", "post-it", "post-its", "pad of sticky notes", "sticky note pad", "memo pad"],
    DESK,
    "a square pad of yellow sticky notes",
    &["stationery", "paper"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // Post-it 76 × 76 mm, 100 sheets: 1.2–1.5 cm thick.
    &size3(0.076, 0.076, 0.015, 0.5, 2.0, 0.02),
    build_sticky_notes,
);

fn build_sticky_notes(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let m =
        b.material("paper", pick(rng, &[[0.98, 0.92, 0.4, 1.0], [0.95, 0.6, 0.75, 1.0], [0.6, 0.85, 0.95, 1.0]]), true);
    part(b, s, [-0.5, -0.5, 0.0], [0.5, 0.5, 1.0], m);
    hull(b, s.0, s.1, s.2);
    0.06
}

pub(crate) const PENCIL_SHARPENER: Category = def(
    "pencil_sharpener",
    "pencil sharpener",
    &["sharpener", "pencil-sharpener", "electric pencil sharpener"],
    DESK,
    "a small pencil sharpener with a blade over a hole",
    &["stationery"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Hand sharpeners: 3–6 × 2–3 × 1.5–3 cm.
    &sized(0.04, 0.028, 0.02),
    build_pencil_sharpener,
);

fn build_pencil_sharpener(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let m =
        b.material("body", pick(rng, &[[0.7, 0.72, 0.75, 1.0], [0.85, 0.15, 0.15, 1.0], [0.15, 0.4, 0.8, 1.0]]), true);
    let hole = b.material("hole", INK, false);
    part(b, s, [-0.5, -0.5, 0.0], [0.5, 0.5, 1.0], m);
    part(b, s, [-0.505, -0.25, 0.25], [-0.49, 0.25, 0.75], hole);
    hull(b, s.0, s.1, s.2);
    0.015
}

pub(crate) const CLOTHES_PEG: Category = def(
    "clothes_peg",
    "clothes peg",
    &["clothespin", "clothes pin", "washing peg", "laundry peg"],
    &["laundry", "home", "tabletop", "small", "graspable"],
    "a wooden or plastic spring clothes peg",
    &["laundry accessory", "clip"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Spring pegs: 7–7.5 cm long, about 1 cm wide and 1.5 cm high.
    &sized(0.072, 0.011, 0.015),
    build_clothes_peg,
);

fn build_clothes_peg(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let m = b.material("body", pick(rng, &[[0.85, 0.72, 0.5, 1.0], [0.2, 0.5, 0.85, 1.0], [0.9, 0.3, 0.4, 1.0]]), true);
    let spring = b.material("spring", pick(rng, STEEL), false);
    part(b, s, [-0.5, -0.5, 0.0], [0.5, 0.5, 0.45], m);
    part(b, s, [-0.5, -0.5, 0.55], [0.5, 0.5, 1.0], m);
    part(b, s, [-0.1, -0.45, 0.4], [0.1, 0.45, 0.6], spring);
    hull(b, s.0, s.1, s.2);
    0.01
}

pub(crate) const NEWSPAPER: Category = def(
    "newspaper",
    "newspaper",
    &["broadsheet", "tabloid", "daily paper", "folded newspaper", "news paper"],
    &["home", "office", "cafe", "tabletop", "paper"],
    "a folded newspaper lying flat",
    &["publication", "paper"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // A tabloid folded once: 30 × 20–29 cm, about 1 cm thick.
    &size3(0.3, 0.22, 0.012, 0.6, 1.5, 0.04),
    build_newspaper,
);

fn build_newspaper(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let m = b.material("paper", pick(rng, &[[0.92, 0.91, 0.88, 1.0], [0.95, 0.85, 0.8, 1.0]]), true);
    let ink = b.material("print", [0.3, 0.3, 0.32, 1.0], false);
    part(b, s, [-0.5, -0.5, 0.0], [0.5, 0.5, 1.0], m);
    part(b, s, [-0.42, 0.25, 0.99], [0.42, 0.42, 1.0], ink);
    for y in [-0.4, -0.15, 0.05] {
        part(b, s, [-0.42, y, 0.99], [0.42, y + 0.12, 1.0], ink);
    }
    hull(b, s.0, s.1, s.2);
    0.25
}

/// A flat mat lying on the floor or a desk.
fn mat(p: &Params, rng: &mut Rng, b: &mut AssetBuilder, colours: &[[f32; 4]], density: f64) -> f64 {
    let s = whd(p);
    let m = b.material("mat", pick(rng, colours), true);
    let edge = b.material("edge", shade(pick(rng, DARK), 1.0), false);
    part(b, s, [-0.5, -0.5, 0.0], [0.5, 0.5, 0.9], edge);
    part(b, s, [-0.46, -0.44, 0.9], [0.46, 0.44, 1.0], m);
    hull(b, s.0, s.1, s.2);
    mass(s.0, s.1, s.2, density)
}

pub(crate) const DOORMAT: Category = def(
    "doormat",
    "doormat",
    &["door mat", "welcome mat", "coir mat", "entrance mat", "boot mat"],
    &["home", "textile", "floor", "flat"],
    "a coir doormat lying on the floor",
    &["mat", "textile"],
    Kind::Textile,
    PlacementKind::OnSurface,
    true,
    // Coir mats: 60–90 × 40–60 cm, 1.5–2.5 cm thick.
    &size3(0.75, 0.45, 0.018, 0.6, 1.5, 0.04),
    build_doormat,
);

fn build_doormat(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    mat(p, rng, b, &[[0.7, 0.52, 0.3, 1.0], [0.3, 0.3, 0.32, 1.0]], 300.0)
}

pub(crate) const MOUSE_MAT: Category = def(
    "mouse_mat",
    "mouse mat",
    &["mouse pad", "mousepad", "mousemat", "desk mat", "gaming mat"],
    DESK,
    "a thin rubber-backed mouse mat",
    &["computer accessory", "mat"],
    Kind::Tabletop,
    PlacementKind::OnSurface,
    true,
    // Mouse mats: 22–32 × 18–27 cm, 2–4 mm thick.
    &size3(0.25, 0.21, 0.003, 0.6, 3.0, 0.04),
    build_mouse_mat,
);

fn build_mouse_mat(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    mat(p, rng, b, &[[0.1, 0.1, 0.12, 1.0], [0.2, 0.3, 0.55, 1.0], [0.55, 0.1, 0.1, 1.0]], 600.0)
}

pub(crate) const LEGO_BRICK: Category = def(
    "lego_brick",
    "lego brick",
    &["lego", "toy brick", "building brick", "duplo brick", "lego block", "duplo"],
    &["toy", "tabletop", "small", "graspable"],
    "a plastic building brick with studs on top",
    &["toy", "block"],
    Kind::Toy,
    PlacementKind::OnSurface,
    true,
    // A 2 × 4 brick: 31.8 × 15.8 × 11.4 mm (studs included); Duplo twice as big.
    &size3(0.032, 0.016, 0.0115, 0.8, 2.2, 0.02),
    build_lego_brick,
);

fn build_lego_brick(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let m = b.material(
        "plastic",
        pick(rng, &[[0.8, 0.1, 0.1, 1.0], [0.1, 0.3, 0.75, 1.0], [0.95, 0.8, 0.1, 1.0], [0.15, 0.55, 0.25, 1.0]]),
        true,
    );
    let stud = b.material("studs", [0.9, 0.9, 0.9, 0.0], false);
    let _ = stud;
    part(b, s, [-0.5, -0.5, 0.0], [0.5, 0.5, 0.85], m);
    for x in [-0.375, -0.125, 0.125, 0.375] {
        for y in [-0.25, 0.25] {
            part(b, s, [x - 0.1, y - 0.2, 0.85], [x + 0.1, y + 0.2, 1.0], m);
        }
    }
    hull(b, s.0, s.1, s.2);
    0.0025
}

pub(crate) const GARDEN_HOSE: Category = def(
    "garden_hose",
    "garden hose",
    &["hose", "hose reel", "hosepipe", "hose pipe", "water hose", "coiled hose"],
    &["garden", "outdoor", "graspable", "round"],
    "a coiled green garden hose lying flat",
    &["garden tool", "hose"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // A 15–25 m coil of 12.5 mm hose: 40–50 cm across, 8–12 cm high.
    &sized(0.45, 0.45, 0.1),
    build_garden_hose,
);

fn build_garden_hose(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let m = b.material("hose", pick(rng, &[[0.2, 0.55, 0.2, 1.0], [0.9, 0.5, 0.1, 1.0], [0.2, 0.3, 0.6, 1.0]]), true);
    let mid = b.material("middle", shade(pick(rng, DARK), 0.8), false);
    turn(b, s, [0.0, 1.0], &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], m);
    turn(b, (s.0 * 0.55, s.1 * 0.55, s.2), [0.0, 1.005], &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], mid);
    hull(b, s.0, s.1, s.2);
    2.5
}

pub(crate) const BOILER: Category = def(
    "boiler",
    "boiler",
    &["combi boiler", "water heater", "hot water tank", "hot water cylinder", "gas boiler"],
    &["home", "utility", "fixture", "heating"],
    "a white gas combi boiler with a control panel on its front",
    &["heater", "appliance", "fixture"],
    Kind::Fixture,
    PlacementKind::AgainstWall,
    false,
    // Worcester / Vaillant combi boilers: 40–45 × 28–35 × 70–72 cm.
    &size3(0.42, 0.32, 0.72, 0.8, 2.5, 0.03),
    build_boiler,
);

fn build_boiler(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let body = b.material("case", pick(rng, &[[0.95, 0.95, 0.94, 1.0], [0.85, 0.86, 0.87, 1.0]]), true);
    let panel = b.material("panel", pick(rng, DARK), false);
    let pipe = b.material("pipes", [0.75, 0.5, 0.3, 1.0], false);
    part(b, s, [-0.5, -0.5, 0.2], [0.5, 0.5, 1.0], body);
    part(b, s, [-0.3, 0.49, 0.25], [0.3, 0.505, 0.35], panel);
    for x in [-0.3, -0.1, 0.1, 0.3] {
        part(b, s, [x - 0.03, -0.2, 0.0], [x + 0.03, -0.1, 0.2], pipe);
    }
    collider_between(b, [-s.0 / 2.0, -s.1 / 2.0, 0.0], [s.0 / 2.0, s.1 / 2.0, s.2]);
    0.0
}

pub(crate) const CHESSBOARD: Category = def(
    "chessboard",
    "chessboard",
    &["chess board", "draughts board", "checkerboard", "checkers board", "game of chess"],
    &["home", "toy", "game", "tabletop"],
    "a chessboard with its pieces set up",
    &["board game", "game", "toy"],
    Kind::Toy,
    PlacementKind::OnSurface,
    true,
    // Tournament boards: 40–50 cm square, 1.5–3 cm thick; set up with pieces 8–10 cm.
    &[
        ParamDef::new("width", 0.42, 0.25, 0.55, 0.03, "along X"),
        ParamDef::new("depth", 0.42, 0.25, 0.55, 0.03, "along Y"),
        ParamDef::new("height", 0.025, 0.012, 0.11, 0.03, "the board, or its pieces when taller than 5 cm"),
    ],
    build_chessboard,
);

fn build_chessboard(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let light = b.material("light", pick(rng, &[[0.9, 0.82, 0.65, 1.0], [0.95, 0.95, 0.92, 1.0]]), true);
    let dark = b.material("dark", [0.35, 0.2, 0.12, 1.0], false);
    let board = if s.2 > 0.05 { 0.2 } else { 0.9 };
    part(b, s, [-0.5, -0.5, 0.0], [0.5, 0.5, board], light);
    for i in 0..8 {
        for j in 0..8 {
            if (i + j) % 2 == 1 {
                let (x, y) = (-0.45 + 0.1125 * f64::from(i), -0.45 + 0.1125 * f64::from(j));
                part(b, s, [x, y, board - 0.01], [x + 0.1125, y + 0.1125, board + 0.01], dark);
            }
        }
    }
    if board > 0.5 {
        hull(b, s.0, s.1, s.2);
        return 1.0;
    }
    let white = b.material("white_pieces", LABEL_WHITE, false);
    let black = b.material("black_pieces", INK, false);
    for (y, m) in [(-0.45, white), (0.34, black)] {
        for i in 0..8 {
            let x = -0.44 + 0.1125 * f64::from(i);
            part(b, s, [x, y, 0.2], [x + 0.09, y + 0.1, 0.7], m);
            part(b, s, [x + 0.02, y + 0.01, 0.7], [x + 0.07, y + 0.09, 1.0], m);
        }
    }
    hull(b, s.0, s.1, s.2);
    1.2
}

pub(crate) const TWEEZERS: Category = def(
    "tweezers",
    "tweezers",
    &["pair of tweezers", "forceps", "lab tweezers", "precision tweezers"],
    &["lab", "medical", "bathroom", "tabletop", "small", "graspable"],
    "a pair of steel tweezers lying flat",
    &["hand tool", "tool"],
    Kind::HandHeld,
    PlacementKind::OnSurface,
    true,
    // Tweezers: 9–12 cm long, 1 cm wide, 1 cm high at the hinge.
    &sized(0.11, 0.01, 0.009),
    build_tweezers,
);

fn build_tweezers(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let s = whd(p);
    let m = b.material("steel", pick(rng, &[[0.75, 0.77, 0.8, 1.0], [0.2, 0.2, 0.22, 1.0]]), true);
    part(b, s, [-0.5, -0.5, 0.0], [0.5, -0.2, 1.0], m);
    part(b, s, [-0.5, 0.2, 0.0], [0.5, 0.5, 1.0], m);
    part(b, s, [-0.5, -0.5, 0.0], [-0.35, 0.5, 1.0], m);
    hull(b, s.0, s.1, s.2);
    0.012
}
