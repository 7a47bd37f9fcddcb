//! Machine tools and fabrication: lathes, drill presses and desktop 3D printers.

use sw_geom::{AssetBuilder, PlacementKind, Pose, Rng, Shape};

use super::kit::{
    Axis, DARK, GLASS, INK, MACHINE_PAINT, SIGNAL_RED, STEEL, along, collider_between, decal_between, pick, rod, shade,
    slab,
};
use super::parts::round_collider;
use super::shapes::{ROUND, revolve};
use crate::{Category, Kind, ParamDef, Params};

pub(crate) const LATHE: Category = Category {
    name: "lathe",
    display: "lathe",
    synonyms: &["metal lathe", "engine lathe", "turning machine", "cnc lathe", "wood lathe", "turning center"],
    tags: &["machine", "industrial", "workshop", "heavy"],
    description: "a metal lathe",
    is_a: &["machine", "machine tool"],
    kind: Kind::Machine,
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 2.0, 1.2, 3.5, 0.12, "along X, the bed's length"),
        ParamDef::new("depth", 0.9, 0.7, 1.2, 0.06, "along Y"),
        ParamDef::new("height", 1.5, 1.2, 1.8, 0.05, "floor to the top of the headstock"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_lathe,
};

/// Two cabinet pedestals under a bed, a headstock with the chuck at -X, a tailstock at
/// +X, a carriage with a tool post, a chip tray and a splash guard at the back.
fn build_lathe(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let paint = pick(rng, MACHINE_PAINT);
    let body = b.material("body", paint, true);
    let steel = b.material("steel", pick(rng, STEEL), false);
    let tray = b.material("chip_tray", shade(pick(rng, DARK), 1.2), false);
    let red = b.material("estop", SIGNAL_RED, false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let bed_z = h * 0.68;
    let pw = (w * 0.2).min(0.5);
    for (x0, x1) in [(-hw, -hw + pw), (hw - pw, hw)] {
        slab(b, [x0, -hd * 0.7, 0.0], [x1, hd, bed_z - 0.25], body);
    }
    slab(b, [-hw + 0.05, -hd * 0.7, bed_z - 0.25], [hw - 0.05, hd * 0.5, bed_z - 0.2], tray);
    slab(b, [-hw + 0.02, -hd * 0.25, bed_z - 0.2], [hw - 0.02, hd * 0.25, bed_z], steel);
    // Headstock and chuck.
    let hs = (w * 0.25).min(0.6);
    slab(b, [-hw, -hd * 0.5, bed_z - 0.001], [-hw + hs, hd * 0.35, h], body);
    let spindle_z = bed_z + (h - bed_z) * 0.45;
    let cr = ((h - bed_z) * 0.35).min(0.15);
    b.visual_mesh_on(
        0,
        &revolve(&[[0.0, 0.0], [cr, 0.0], [cr, 0.08], [cr * 0.3, 0.1], [0.0, 0.1]], ROUND),
        along([-hw + hs, 0.0, spindle_z], Axis::X),
        steel,
    );
    collider_between(b, [-hw + hs, -cr, spindle_z - cr], [-hw + hs + 0.1, cr, spindle_z + cr]);
    // Tailstock and carriage on the bed.
    slab(b, [hw - 0.35, -hd * 0.2, bed_z], [hw - 0.08, hd * 0.2, spindle_z + 0.06], body);
    rod(b, [hw - 0.45, 0.0, spindle_z], 0.03, 0.2, Axis::X, steel);
    let cx = -hw + hs + (w - hs) * 0.4;
    slab(b, [cx - 0.15, -hd * 0.3, bed_z], [cx + 0.15, hd * 0.45, bed_z + 0.12], body);
    slab(b, [cx - 0.05, -0.05, bed_z + 0.12], [cx + 0.05, 0.05, bed_z + 0.2], steel);
    // Splash guard along the back, full depth to the front apron's edge.
    slab(b, [-hw + hs, -hd, bed_z - 0.2], [hw, -hd * 0.7, h * 0.95], tray);
    rod(b, [-hw + hs * 0.5, hd * 0.35 + 0.004, h - 0.12], 0.025, 0.008, Axis::Y, red);
    decal_between(b, [-hw + 0.05, hd * 0.35, bed_z + 0.05], [-hw + hs - 0.05, hd * 0.35 + 0.002, h - 0.2], tray);
    0.0
}

pub(crate) const DRILL_PRESS: Category = Category {
    name: "drill_press",
    display: "drill press",
    synonyms: &["pillar drill", "column drill", "bench drill", "drilling machine", "floor drill press"],
    tags: &["machine", "workshop", "industrial", "tall"],
    description: "a floor-standing drill press",
    is_a: &["machine", "machine tool", "drill"],
    kind: Kind::Machine,
    placement: PlacementKind::Floor,
    params: &[
        ParamDef::new("width", 0.45, 0.3, 0.6, 0.08, "along X"),
        ParamDef::new("depth", 0.7, 0.45, 0.9, 0.08, "along Y, base to the front of the head"),
        ParamDef::new("height", 1.65, 0.8, 1.9, 0.06, "floor to the top of the motor"),
    ],
    movable: false,
    vary_per_instance: false,
    build: build_drill_press,
};

/// A base plate, a round column at the back, a round work table on the column, the head
/// with belt cover and motor, the spindle and the feed handles.
fn build_drill_press(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let paint =
        pick(rng, &[[0.25, 0.45, 0.35, 1.0], [0.85, 0.45, 0.1, 1.0], [0.2, 0.3, 0.55, 1.0], [0.55, 0.57, 0.6, 1.0]]);
    let body = b.material("body", paint, true);
    let steel = b.material("steel", pick(rng, STEEL), false);
    let dark = b.material("motor", pick(rng, DARK), false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let cy = -hd + 0.1;
    let col_r = 0.045f64.min(w * 0.1);
    slab(b, [-hw, -hd, 0.0], [hw, hd, 0.05], body);
    b.visual_mesh_on(
        0,
        &sw_geom::cylinder_mesh(col_r, (h - 0.1) / 2.0, ROUND),
        Pose::from_pos([0.0, cy, 0.05 + (h - 0.1) / 2.0]),
        steel,
    );
    b.collision_on(
        0,
        Shape::Cylinder { radius: col_r, half_height: (h - 0.1) / 2.0 - 0.001 },
        Pose::from_pos([0.0, cy, 0.05 + (h - 0.1) / 2.0]),
    );
    // The work table: a round plate on an arm, in front of the column.
    let tr = (hw * 0.75).min(0.18).min((hd - cy - col_r - 0.035) / 2.0);
    let ty = cy + col_r + tr + 0.03;
    let tz = (h * 0.5).max(0.3);
    slab(b, [-0.04, cy, tz - 0.08], [0.04, ty, tz - 0.02], body);
    b.visual_mesh_on(0, &sw_geom::cylinder_mesh(tr, 0.015, ROUND), Pose::from_pos([0.0, ty, tz - 0.015]), steel);
    let table = round_collider(b, 0, [0.0, ty], tr, tz - 0.03, tz);
    // The head over the table: belt cover, motor behind, spindle and chuck.
    let (hz0, hz1) = (h - 0.35f64.min(h * 0.3), h - 0.06);
    slab(b, [-hw * 0.7, cy - 0.06, hz0], [hw * 0.7, (ty + 0.08).min(hd), hz1], body);
    slab(b, [-hw * 0.6, ty - 0.05, hz1 - 0.001], [hw * 0.6, ty + 0.1f64.min(hd - ty), h], body);
    slab(b, [-0.08, -hd, hz0 + 0.02], [0.08, cy - 0.06, hz1 - 0.02], dark);
    let chuck_z = (tz + (hz0 - tz) * 0.45).max(tz + 0.08);
    rod(b, [0.0, ty, (chuck_z + hz0) / 2.0], 0.025, hz0 - chuck_z, Axis::Z, steel);
    b.collision_on(
        0,
        Shape::Cylinder { radius: 0.025, half_height: (hz0 - chuck_z) / 2.0 },
        Pose::from_pos([0.0, ty, (chuck_z + hz0) / 2.0]),
    );
    // Feed handles on the +X side.
    for a in [0.0f64, 2.1, 4.2] {
        let (s, c) = a.sin_cos();
        rod(b, [hw * 0.7 + 0.004, ty + s * 0.08, hz0 + 0.1 + c * 0.08], 0.008, 0.008, Axis::X, steel);
    }
    let a = tr / std::f64::consts::SQRT_2 - 1e-6;
    b.surface("table", table, [-a, ty - a], [a, ty + a], Some(chuck_z - table - 0.01));
    0.0
}

pub(crate) const FDM_PRINTER: Category = Category {
    name: "fdm_printer",
    display: "fdm printer",
    synonyms: &[
        "3d printer",
        "3-d printer",
        "filament printer",
        "resin printer",
        "additive manufacturing printer",
        "desktop printer enclosure",
        "fused deposition printer",
        "prototyping printer",
    ],
    tags: &["lab", "workshop", "office", "tabletop", "machine", "electronics"],
    description: "a desktop 3d printer",
    is_a: &["printer", "machine"],
    kind: Kind::Machine,
    placement: PlacementKind::OnSurface,
    params: &[
        ParamDef::new("width", 0.45, 0.3, 0.7, 0.1, "along X"),
        ParamDef::new("depth", 0.45, 0.3, 0.7, 0.1, "along Y"),
        ParamDef::new("height", 0.5, 0.35, 0.8, 0.1, "floor to top"),
    ],
    movable: true,
    vary_per_instance: false,
    build: build_fdm_printer,
};

/// An enclosed desktop 3D printer: a frame with a glass door, the build plate, a gantry
/// with the print head, a part on the plate and a filament spool on the side.
fn build_fdm_printer(p: &Params, rng: &mut Rng, b: &mut AssetBuilder) -> f64 {
    let (w, d, h) = (p.get("width"), p.get("depth"), p.get("height"));
    let frame =
        b.material("frame", pick(rng, &[[0.12, 0.12, 0.13, 1.0], [0.9, 0.9, 0.88, 1.0], [0.85, 0.45, 0.1, 1.0]]), true);
    let glass = b.material("door", GLASS, false);
    let plate = b.material("bed", [0.2, 0.2, 0.22, 1.0], false);
    let part = b.material(
        "print",
        pick(rng, &[[0.9, 0.3, 0.1, 1.0], [0.2, 0.6, 0.3, 1.0], [0.2, 0.4, 0.85, 1.0], [0.95, 0.95, 0.93, 1.0]]),
        false,
    );
    let ink = b.material("screen", INK, false);
    let (hw, hd) = (w / 2.0, d / 2.0);
    let top = collider_between(b, [-hw, -hd, 0.0], [hw, hd, h]);
    let t = 0.025;
    // The frame: bottom box, top box, four corner posts.
    decal_between(b, [-hw, -hd, 0.0], [hw, hd, h * 0.15], frame);
    decal_between(b, [-hw, -hd, h - 0.06], [hw, hd, h], frame);
    for (sx, sy) in [(-1.0, -1.0), (1.0, -1.0), (-1.0, 1.0), (1.0, 1.0)] {
        let (x, y) = (sx * (hw - t / 2.0), sy * (hd - t / 2.0));
        decal_between(b, [x - t / 2.0, y - t / 2.0, h * 0.15 - 0.001], [x + t / 2.0, y + t / 2.0, h - 0.059], frame);
    }
    // Glass on the front and sides; the inside shows through the front.
    decal_between(b, [-hw + t, hd - 0.006, h * 0.15], [hw - t, hd - 0.002, h - 0.06], glass);
    for x in [-hw + 0.002, hw - 0.006] {
        decal_between(b, [x, -hd + t, h * 0.15], [x + 0.004, hd - t, h - 0.06], glass);
    }
    decal_between(b, [-hw * 0.7, -hd * 0.7, h * 0.3], [hw * 0.7, hd * 0.7, h * 0.3 + 0.008], plate);
    let pr = w.min(d) * 0.12;
    rod(b, [0.0, 0.0, h * 0.3 + 0.008 + pr * 0.6], pr, pr * 1.2, Axis::Z, part);
    rod(b, [0.0, 0.0, h * 0.75], 0.01, w - 2.0 * t, Axis::X, frame);
    decal_between(b, [-0.03, -0.03, h * 0.75 - 0.04], [0.03, 0.03, h * 0.75 + 0.02], frame);
    decal_between(b, [hw * 0.3, hd - 0.001, h * 0.03], [hw * 0.8, hd + 0.002, h * 0.12], ink);
    b.surface("top", top, [-hw, -hd], [hw, hd], None);
    (w * d * h * 110.0).clamp(5.0, 40.0)
}
