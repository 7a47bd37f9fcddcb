//! Breadth chosen from public object lists (issue 21, third round): the nouns of COCO,
//! Objects365, YCB, RoboCasa, LVIS's frequent categories and ShapeNet's top-level synsets
//! that people put in homes, kitchens, offices, shops, labs, workshops and on tabletops and
//! that the catalog lacked (`bench/vocab/public_lists/`, `coverage.py`). Living things, road,
//! rail, air and water vehicles, street furniture and scenery, worn garments and parts of
//! things are out of scope there (`out_of_scope.txt`).
//!
//! Each category is declared in one [`thing!`] line: its names, what it is a kind of, its
//! real size (the middle of a published product range, noted per line) and a [`Look`], a
//! parametric drawing shared by many things (a turned body, a pack, a long tool lying on
//! the table, an appliance, a table, a round blob, a flat sheet, a stand, a case,
//! an instrument, a bag). Every one collides as one box over its whole size, resting flat
//! on its base, so that it settles at once and stacks (as the household things do); what
//! it looks like is drawn inside that box. Furniture and appliances with flat tops carry a
//! support surface there.

mod behavior;
mod common;
mod food;
mod home;
mod leisure;
mod rare;
mod work;

pub(crate) use behavior::*;
pub(crate) use common::*;
pub(crate) use food::*;
pub(crate) use home::*;
pub(crate) use leisure::*;
pub(crate) use rare::*;
pub(crate) use work::*;

use sw_geom::{AssetBuilder, Rng};

use super::forms::{ellipsoid, whd};
use super::household::{hull, mass, part, turn};
use super::kit::{Axis, pick, rod};
use crate::Params;

type Rgba = [f32; 4];

/// How a thing is drawn inside its box (all positions are fractions of the size: x and y
/// from the centre, −0.5…0.5; z from the base, 0…1).
#[derive(Debug, Clone, Copy)]
pub(crate) enum Look {
    /// A body turned from `profile` up to `top`, and a cap (a narrower cylinder, `cap_r`
    /// of the radius) above it: bottles, jars, cans, cups, candles.
    Turned { profile: &'static [[f64; 2]], body: &'static [Rgba], top: f64, cap_r: f64, cap: Rgba },
    /// A box with a label band on its front: packs of food, boxes of things.
    Pack { body: &'static [Rgba], band: Rgba },
    /// A long thing lying along X: a grip over the first `grip` of its length, `grip_w`
    /// of the depth wide and `grip_h` of the height tall, then a head over the rest.
    Long { grip: f64, grip_w: f64, grip_h: f64, handle: &'static [Rgba], head: Rgba },
    /// A boxy appliance: its body, a front panel (door or control face) over `door`
    /// (x0, x1, z0, z1), and `knobs` knobs in a row above it; a top surface when `top`.
    Appliance { body: &'static [Rgba], front: Rgba, door: [f64; 4], knobs: usize, top: bool },
    /// A table or bench: a top `top` of the height thick on four legs, a shelf when
    /// `shelf`; a support surface on top.
    Table { top: f64, wood: &'static [Rgba], legs: Rgba, shelf: bool },
    /// A round blob filling its box (fruit, balls, soft things), with a stem or patch of
    /// `accent` on top when `stem`.
    Blob { body: &'static [Rgba], accent: Rgba, stem: bool },
    /// A flat sheet or slab with an inset panel on top (mats, boards, papers).
    Flat { body: &'static [Rgba], panel: Rgba },
    /// A stand: a round foot, a pole and a head over the top `head` of the height.
    Stand { foot: Rgba, pole: Rgba, head: &'static [Rgba], head_h: f64 },
    /// A case with a carrying handle on top over the top `handle_h` of the height.
    Case { body: &'static [Rgba], handle: Rgba, handle_h: f64 },
    /// An instrument lying along X: a round body over the first `body_len` of its length
    /// and a neck or tube to the other end.
    Instrument { body: &'static [Rgba], neck: Rgba, body_len: f64 },
    /// A soft bag: a rounded body over the lower `body_h` and a strap above it.
    Bag { body: &'static [Rgba], strap: Rgba, body_h: f64 },
}

/// Draws `look` at the requested size, collides as its box, and returns its mass at
/// `density` kg/m³ of its box.
pub(crate) fn draw(p: &Params, rng: &mut Rng, b: &mut AssetBuilder, look: &Look, density: f64) -> f64 {
    let s = whd(p);
    let (w, d, h) = s;
    match *look {
        Look::Turned { profile, body, top, cap_r, cap } => {
            let m = b.material("body", pick(rng, body), true);
            turn(b, s, [0.0, top], profile, m);
            if top < 0.999 {
                let c = b.material("cap", cap, false);
                let r = cap_r.clamp(0.05, 1.0);
                turn(b, s, [top - 0.005, 1.0], &[[0.0, 0.0], [r, 0.0], [r, 1.0], [0.0, 1.0]], c);
            }
        }
        Look::Pack { body, band } => {
            let m = b.material("pack", pick(rng, body), true);
            let l = b.material("band", band, false);
            part(b, s, [-0.5, -0.5, 0.0], [0.5, 0.5, 1.0], m);
            part(b, s, [-0.42, -0.505, 0.25], [0.42, 0.505, 0.75], l);
        }
        Look::Long { grip, grip_w, grip_h, handle, head } => {
            let g = b.material("grip", pick(rng, handle), true);
            let m = b.material("head", head, false);
            let split = -0.5 + grip.clamp(0.05, 0.95);
            part(b, s, [-0.5, -grip_w / 2.0, 0.0], [split + 0.01, grip_w / 2.0, grip_h], g);
            part(b, s, [split, -0.5, 0.0], [0.5, 0.5, 1.0], m);
        }
        Look::Appliance { body, front, door, knobs, top } => {
            let m = b.material("body", pick(rng, body), true);
            let f = b.material("front", front, false);
            part(b, s, [-0.5, -0.5, 0.0], [0.5, 0.49, 1.0], m);
            let [x0, x1, z0, z1] = door;
            part(b, s, [x0, 0.48, z0], [x1, 0.505, z1], f);
            if knobs > 0 {
                let k = b.material("knob", [0.1, 0.1, 0.11, 1.0], false);
                let zk = (z1 + (1.0 - z1) / 2.0).min(0.95);
                for x in super::forms::spread(x0, x1, knobs) {
                    part(b, s, [x - 0.03, 0.48, zk - 0.03], [x + 0.03, 0.505, zk + 0.03], k);
                }
            }
            let t = hull(b, w, d, h);
            if top {
                b.surface("top", t, [-w / 2.0, -d / 2.0], [w / 2.0, d / 2.0], None);
            }
            return mass(w, d, h, density);
        }
        Look::Table { top, wood, legs, shelf } => {
            let m = b.material("top", pick(rng, wood), true);
            let l = b.material("legs", legs, false);
            let z = 1.0 - top;
            part(b, s, [-0.5, -0.5, z], [0.5, 0.5, 1.0], m);
            let lw = (0.05 / w.max(0.1)).min(0.12);
            let ld = (0.05 / d.max(0.1)).min(0.12);
            for (sx, sy) in [(-1.0, -1.0), (1.0, -1.0), (-1.0, 1.0), (1.0, 1.0)] {
                let (cx, cy) = (sx * (0.5 - lw), sy * (0.5 - ld));
                part(b, s, [cx - lw / 2.0 - 0.001, cy - ld / 2.0, 0.0], [cx + lw / 2.0, cy + ld / 2.0, z + 0.01], l);
            }
            if shelf {
                part(b, s, [-0.47, -0.47, 0.15], [0.47, 0.47, 0.15 + top], l);
            }
            let t = hull(b, w, d, h);
            b.surface("top", t, [-w / 2.0, -d / 2.0], [w / 2.0, d / 2.0], None);
            return mass(w, d, h, density);
        }
        Look::Blob { body, accent, stem } => {
            let m = b.material("skin", pick(rng, body), true);
            ellipsoid(b, [0.0, 0.0, h / 2.0], [w / 2.0, d / 2.0, h / 2.0], m);
            if stem {
                let a = b.material("stem", accent, false);
                part(b, s, [-0.06, -0.06, 0.9], [0.06, 0.06, 1.0], a);
            }
        }
        Look::Flat { body, panel } => {
            let m = b.material("sheet", pick(rng, body), true);
            let pm = b.material("panel", panel, false);
            part(b, s, [-0.5, -0.5, 0.0], [0.5, 0.5, 0.98], m);
            part(b, s, [-0.4, -0.4, 0.5], [0.4, 0.4, 1.0], pm);
        }
        Look::Stand { foot, pole, head, head_h } => {
            let f = b.material("foot", foot, false);
            let pm = b.material("pole", pole, false);
            let hm = b.material("head", pick(rng, head), true);
            let hh = head_h.clamp(0.05, 0.9);
            turn(b, s, [0.0, 0.04], &[[0.0, 0.0], [1.0, 0.0], [0.8, 1.0], [0.0, 1.0]], f);
            let r = (w.min(d) * 0.04).clamp(0.004, 0.025);
            rod(b, [0.0, 0.0, (1.0 - hh) * h / 2.0 + 0.01], r, (1.0 - hh) * h, Axis::Z, pm);
            part(b, s, [-0.5, -0.5, 1.0 - hh], [0.5, 0.5, 1.0], hm);
        }
        Look::Case { body, handle, handle_h } => {
            let m = b.material("shell", pick(rng, body), true);
            let g = b.material("handle", handle, false);
            let z = 1.0 - handle_h.clamp(0.03, 0.5);
            part(b, s, [-0.5, -0.5, 0.0], [0.5, 0.5, z], m);
            part(b, s, [-0.22, -0.08, z - 0.01], [-0.16, 0.08, 1.0], g);
            part(b, s, [0.16, -0.08, z - 0.01], [0.22, 0.08, 1.0], g);
            part(b, s, [-0.2, -0.08, 1.0 - (1.0 - z) * 0.4], [0.2, 0.08, 1.0], g);
        }
        Look::Instrument { body, neck, body_len } => {
            let m = b.material("body", pick(rng, body), true);
            let n = b.material("neck", neck, false);
            let bl = body_len.clamp(0.2, 0.9);
            let cx = (-0.5 + bl / 2.0) * w;
            ellipsoid(b, [cx, 0.0, h / 2.0], [bl * w / 2.0, d / 2.0, h / 2.0], m);
            part(b, s, [-0.5 + bl - 0.02, -0.12, 0.3], [0.5, 0.12, 0.7], n);
        }
        Look::Bag { body, strap, body_h } => {
            let m = b.material("fabric", pick(rng, body), true);
            let st = b.material("strap", strap, false);
            let bh = body_h.clamp(0.4, 0.95);
            part(b, s, [-0.5, -0.5, 0.0], [0.5, 0.5, bh * 0.5], m);
            ellipsoid(b, [0.0, 0.0, bh * h * 0.5], [w / 2.0, d / 2.0, bh * h * 0.5], m);
            part(b, s, [-0.3, -0.05, bh - 0.05], [-0.24, 0.05, 1.0], st);
            part(b, s, [0.24, -0.05, bh - 0.05], [0.3, 0.05, 1.0], st);
            part(b, s, [-0.28, -0.05, 0.94], [0.28, 0.05, 1.0], st);
        }
    }
    hull(b, w, d, h);
    mass(w, d, h, density)
}

/// Declares one category drawn by a [`Look`]:
/// `thing!(ID: "name", "display", [synonyms], TAGS, "description", [is_a], Kind @ Placement,
/// movable, [w, d, h], density, look);`
macro_rules! thing {
    ($id:ident: $name:literal, $display:literal, [$($syn:literal),* $(,)?], $tags:expr, $desc:literal,
     [$($isa:literal),+ $(,)?], $kind:ident @ $place:ident, $movable:literal, [$w:expr, $d:expr, $h:expr],
     $density:expr, $look:expr $(,)?) => {
        pub(crate) const $id: crate::Category = super::super::forms::def(
            $name,
            $display,
            &[$($syn),*],
            $tags,
            $desc,
            &[$($isa),+],
            crate::Kind::$kind,
            sw_geom::PlacementKind::$place,
            $movable,
            &super::super::household::sized($w, $d, $h),
            {
                fn build(p: &crate::Params, rng: &mut sw_geom::Rng, b: &mut sw_geom::AssetBuilder) -> f64 {
                    super::draw(p, rng, b, &$look, $density)
                }
                build
            },
        );
    };
}
pub(crate) use thing;

/// One category drawn by another family's builder at its own size.
macro_rules! like {
    ($id:ident: $name:literal, $display:literal, [$($syn:literal),* $(,)?], $tags:expr, $desc:literal,
     [$($isa:literal),+ $(,)?], $kind:ident @ $place:ident, $movable:literal, [$w:expr, $d:expr, $h:expr], $build:path $(,)?) => {
        pub(crate) const $id: crate::Category = super::super::forms::def(
            $name, $display, &[$($syn),*], $tags, $desc, &[$($isa),+], crate::Kind::$kind,
            sw_geom::PlacementKind::$place, $movable, &super::super::household::sized($w, $d, $h), $build,
        );
    };
}
pub(crate) use like;

// Palettes and profiles shared by the families.
pub(crate) const WOODS: &[Rgba] = &[[0.62, 0.45, 0.28, 1.0], [0.5, 0.34, 0.2, 1.0], [0.72, 0.56, 0.38, 1.0]];
pub(crate) const METAL: &[Rgba] = &[[0.66, 0.68, 0.7, 1.0], [0.55, 0.57, 0.6, 1.0]];
pub(crate) const WHITE: &[Rgba] = &[[0.93, 0.93, 0.92, 1.0], [0.88, 0.88, 0.86, 1.0]];
pub(crate) const BLACKS: &[Rgba] = &[[0.12, 0.12, 0.13, 1.0], [0.2, 0.2, 0.22, 1.0]];
pub(crate) const BRIGHTS: &[Rgba] = &[
    [0.8, 0.15, 0.12, 1.0],
    [0.15, 0.35, 0.75, 1.0],
    [0.95, 0.75, 0.1, 1.0],
    [0.2, 0.6, 0.3, 1.0],
    [0.55, 0.25, 0.6, 1.0],
];
pub(crate) const FABRIC: &[Rgba] =
    &[[0.3, 0.35, 0.45, 1.0], [0.55, 0.2, 0.2, 1.0], [0.35, 0.4, 0.3, 1.0], [0.2, 0.2, 0.22, 1.0]];
pub(crate) const LEATHER: &[Rgba] = &[[0.35, 0.2, 0.1, 1.0], [0.15, 0.1, 0.08, 1.0], [0.45, 0.3, 0.18, 1.0]];
pub(crate) const STEEL_C: Rgba = [0.6, 0.62, 0.65, 1.0];
pub(crate) const BLACK_C: Rgba = [0.1, 0.1, 0.11, 1.0];
pub(crate) const WHITE_C: Rgba = [0.95, 0.95, 0.93, 1.0];
pub(crate) const WOOD_C: Rgba = [0.55, 0.38, 0.22, 1.0];
pub(crate) const GREEN_C: Rgba = [0.25, 0.45, 0.15, 1.0];
pub(crate) const BROWN_C: Rgba = [0.35, 0.22, 0.1, 1.0];

/// A straight can or tub.
pub(crate) const CAN: &[[f64; 2]] = &[[0.0, 0.0], [0.95, 0.0], [1.0, 0.04], [1.0, 0.96], [0.95, 1.0], [0.0, 1.0]];
/// A bottle: a body, a shoulder and a neck.
pub(crate) const BOTTLE: &[[f64; 2]] =
    &[[0.0, 0.0], [0.96, 0.0], [1.0, 0.04], [1.0, 0.62], [0.8, 0.75], [0.38, 0.86], [0.36, 1.0], [0.0, 1.0]];
/// A jar: straight, a short shoulder to a wide mouth.
pub(crate) const JAR: &[[f64; 2]] =
    &[[0.0, 0.0], [0.95, 0.0], [1.0, 0.05], [1.0, 0.85], [0.85, 0.95], [0.85, 1.0], [0.0, 1.0]];
/// A cup or tumbler, wider at the top.
pub(crate) const TUMBLER: &[[f64; 2]] = &[[0.0, 0.0], [0.75, 0.0], [1.0, 1.0], [0.0, 1.0]];
/// A cone narrowing to the top (a trophy's cup, a cone).
pub(crate) const CONE: &[[f64; 2]] = &[[0.0, 0.0], [1.0, 0.0], [0.15, 1.0], [0.0, 1.0]];
/// A vase or urn: foot, belly, neck, lip.
pub(crate) const URN: &[[f64; 2]] =
    &[[0.0, 0.0], [0.6, 0.0], [0.55, 0.1], [1.0, 0.45], [0.55, 0.8], [0.7, 1.0], [0.0, 1.0]];
/// A dome (a cake, a bun, a cap).
pub(crate) const DOME: &[[f64; 2]] = &[[0.0, 0.0], [1.0, 0.0], [0.95, 0.45], [0.7, 0.85], [0.0, 1.0]];
/// A disc with a rounded rim (a pizza, a frisbee, a pie).
pub(crate) const DISC: &[[f64; 2]] = &[[0.0, 0.0], [0.95, 0.0], [1.0, 0.5], [0.95, 1.0], [0.0, 1.0]];

/// Shorthands for the common looks, shared by the LVIS families.
pub(crate) const fn turned(profile: &'static [[f64; 2]], body: &'static [Rgba]) -> Look {
    Look::Turned { profile, body, top: 1.0, cap_r: 1.0, cap: WHITE_C }
}
pub(crate) const fn capped(
    profile: &'static [[f64; 2]],
    body: &'static [Rgba],
    top: f64,
    cap_r: f64,
    cap: Rgba,
) -> Look {
    Look::Turned { profile, body, top, cap_r, cap }
}
pub(crate) const fn blob(body: &'static [Rgba]) -> Look {
    Look::Blob { body, accent: BROWN_C, stem: false }
}
pub(crate) const fn pack(body: &'static [Rgba], band: Rgba) -> Look {
    Look::Pack { body, band }
}
pub(crate) const fn flat(body: &'static [Rgba], panel: Rgba) -> Look {
    Look::Flat { body, panel }
}
pub(crate) const fn long(grip: f64, handle: &'static [Rgba], head: Rgba) -> Look {
    Look::Long { grip, grip_w: 0.45, grip_h: 0.7, handle, head }
}
pub(crate) const fn appliance(body: &'static [Rgba], front: Rgba, knobs: usize) -> Look {
    Look::Appliance { body, front, door: [-0.4, 0.4, 0.2, 0.7], knobs, top: true }
}
