//! Everyday objects the procedural catalog does not have, each a parametric composition of
//! parts with real-world proportions and sizes (mm): tools, vessels, furniture and vehicles
//! a free-form prompt may name. Objects lie or stand as they would on a floor or a table.

use super::shapes::{
    Parts, bx, cone_x, cone_z, cup, cyl_x, cyl_y, cyl_z, open_top, prism_xy, revolve, rod_arc, round_vertical, sphere,
};
use super::{Build, Spec};
use crate::synth::model::Model;
use crate::synth::profile::Profile;
use crate::synth::solid::{Axis, Shape};

/// The objects: names, the features their words may name, and the builder.
pub const OBJECTS: &[Build] = &[
    Build { names: &["bucket", "pail"], features: &["handle"], build: bucket },
    Build { names: &["hammer", "claw hammer"], features: &["handle"], build: hammer },
    Build { names: &["dumbbell", "barbell"], features: &["weights", "plates"], build: dumbbell },
    Build { names: &["mushroom", "toadstool"], features: &["cap", "stem"], build: mushroom },
    Build { names: &["saucepan", "pan", "pot", "cooking pot"], features: &["handle", "long handle"], build: saucepan },
    Build { names: &["trophy", "trophy cup", "cup trophy"], features: &["pedestal", "handles", "base"], build: trophy },
    Build { names: &["flashlight", "torch"], features: &[], build: flashlight },
    Build { names: &["goblet", "wine glass", "wineglass", "chalice"], features: &["stem"], build: goblet },
    Build { names: &["plunger", "toilet plunger"], features: &["handle"], build: plunger },
    Build { names: &["desk fan", "fan", "electric fan", "table fan"], features: &["stand", "base"], build: desk_fan },
    Build { names: &["microphone", "mic"], features: &["handle"], build: microphone },
    Build { names: &["wrench", "spanner"], features: &[], build: wrench },
    Build { names: &["mallet"], features: &["handle"], build: mallet },
    Build {
        names: &["staircase", "stairs", "flight of stairs", "steps"],
        features: &["steps", "step"],
        build: staircase,
    },
    Build {
        names: &["coat rack", "coat stand", "hat stand", "coat tree"],
        features: &["hooks", "hook"],
        build: coat_rack,
    },
    Build { names: &["guitar", "acoustic guitar"], features: &[], build: guitar },
    Build { names: &["wheelbarrow", "wheel barrow"], features: &["wheel", "handles"], build: wheelbarrow },
    Build { names: &["bathtub", "bath tub", "bath"], features: &["legs", "feet", "leg"], build: bathtub },
    Build { names: &["pickup truck", "pickup", "pick-up truck", "truck"], features: &["bed", "wheels"], build: pickup },
];

/// A tapered pail with a wire handle arching over it.
fn bucket(s: &Spec) -> Model {
    let k = s.size;
    let (rb, rt, h) = (110.0 * k * s.wide, 140.0 * k * s.wide, 280.0 * k * s.tall);
    let mut p = Parts::default();
    p.add("pail", cup(rb, rt, h, 4.0 * k, 6.0 * k, 0.0));
    // Two ears on the rim and a handle whose ends sit inside them.
    let (ex, ez) = (rt + 6.0 * k, h - 25.0 * k);
    for side in [-1.0, 1.0] {
        p.add("ear", bx([side * ex - 8.0 * k, -10.0 * k, h - 40.0 * k], [side * ex + 8.0 * k, 10.0 * k, h - 10.0 * k]));
    }
    p.add("handle", rod_arc(8.0 * k, [0.0, 0.0, ez], ex, Axis::X, Axis::Z, 0.0, 180.0));
    p.finish()
}

/// Lying on its side: a handle along X and a head across it at the far end.
fn hammer(s: &Spec) -> Model {
    let k = s.size;
    let l = 300.0 * k * s.long;
    let (hw, hd) = (35.0 * k, 120.0 * k);
    let mut p = Parts::default();
    p.add("handle", cyl_x(28.0 * k, 0.0, l, 0.0, hw / 2.0));
    p.add("head", bx([l - 5.0 * k, -hd / 2.0, 0.0], [l + hw - 5.0 * k, hd / 2.0, hw]));
    p.add("face", cyl_y(hw * 1.05, -hd / 2.0 - 15.0 * k, -hd / 2.0 + 1.0, l + hw / 2.0 - 5.0 * k, hw / 2.0));
    p.finish()
}

/// A bar along X with a weight plate and a collar at each end.
fn dumbbell(s: &Spec) -> Model {
    let k = s.size;
    let (half, pd, pt) = (175.0 * k * s.long, 120.0 * k * s.thick, 40.0 * k * s.thick);
    let z = pd / 2.0;
    let mut p = Parts::default();
    p.add("bar", cyl_x(30.0 * k, -half, half, 0.0, z));
    for side in [-1.0, 1.0] {
        let inner = 100.0 * k;
        p.add("collar", cyl_x(45.0 * k, side * inner - 5.0 * k, side * inner + 5.0 * k, 0.0, z));
        let (a, b) = if side > 0.0 {
            (inner + 5.0 * k, inner + 5.0 * k + pt)
        } else {
            (-inner - 5.0 * k - pt, -inner - 5.0 * k)
        };
        p.add("plate", cyl_x(pd, a, b, 0.0, z));
    }
    p.finish()
}

/// A tapered stem under a rounded cap.
fn mushroom(s: &Spec) -> Model {
    let k = s.size;
    let (t, w) = (s.tall, s.wide);
    let mut p = Parts::default();
    p.add("stem", cone_z(42.0 * k * w, 34.0 * k * w, 0.0, 66.0 * k * t, 0.0, 0.0));
    let cap: Vec<[f64; 2]> =
        [[0.0, 60.0], [70.0, 60.0], [68.0, 70.0], [60.0, 86.0], [45.0, 100.0], [25.0, 108.0], [0.0, 111.0]]
            .iter()
            .map(|q| [q[0] * k * w, q[1] * k * t])
            .collect();
    p.add("cap", revolve(&cap, 0.0, 0.0));
    p.finish()
}

/// A straight-sided pot with a long handle along +X near the rim.
fn saucepan(s: &Spec) -> Model {
    let k = s.size;
    let (r, h) = (100.0 * k * s.wide, 110.0 * k * s.tall);
    let mut p = Parts::default();
    p.add("pot", cup(r, r, h, 4.0 * k, 5.0 * k, 0.0));
    p.add("handle", bx([r - 5.0 * k, -14.0 * k, h - 16.0 * k], [r + 190.0 * k * s.long, 14.0 * k, h - 4.0 * k]));
    p.finish()
}

/// A cup with two handles on a stem, on a square pedestal.
fn trophy(s: &Spec) -> Model {
    let k = s.size * s.tall;
    let mut p = Parts::default();
    p.add("pedestal", bx([-60.0 * k, -60.0 * k, 0.0], [60.0 * k, 60.0 * k, 40.0 * k]));
    p.add("step", cyl_z(70.0 * k, 40.0 * k, 55.0 * k, 0.0, 0.0));
    p.add("stem", cone_z(20.0 * k, 30.0 * k, 55.0 * k, 142.0 * k, 0.0, 0.0));
    let bowl: Vec<[f64; 2]> = [
        [0.0, 140.0],
        [15.0, 140.0],
        [70.0, 175.0],
        [75.0, 260.0],
        [71.0, 260.0],
        [66.0, 178.0],
        [13.0, 146.0],
        [0.0, 146.0],
    ]
    .iter()
    .map(|q| [q[0] * k, q[1] * k])
    .collect();
    p.add("cup", revolve(&bowl, 0.0, 0.0));
    p.add("handle", rod_arc(9.0 * k, [72.0 * k, 0.0, 215.0 * k], 25.0 * k, Axis::X, Axis::Z, -90.0, 90.0));
    p.add("handle", rod_arc(9.0 * k, [-72.0 * k, 0.0, 215.0 * k], 25.0 * k, Axis::X, Axis::Z, 90.0, 270.0));
    p.finish()
}

/// Lying along X: tail cap, body, flared head, lens bezel, a switch on top.
fn flashlight(s: &Spec) -> Model {
    let k = s.size;
    let l = 150.0 * k * s.long;
    let z = 28.0 * k;
    let mut p = Parts::default();
    p.add("tail", cyl_x(38.0 * k, -10.0 * k, 0.0, 0.0, z));
    p.add("body", cyl_x(36.0 * k, 0.0, l, 0.0, z));
    p.add("head", cone_x(36.0 * k, 56.0 * k, l, l + 40.0 * k, 0.0, z));
    p.add("bezel", cyl_x(56.0 * k, l + 40.0 * k, l + 50.0 * k, 0.0, z));
    p.add("switch", bx([l * 0.6, -6.0 * k, z + 15.0 * k], [l * 0.6 + 18.0 * k, 6.0 * k, z + 22.0 * k]));
    p.finish()
}

/// A wine glass: a foot, a thin stem and an open bowl, in one revolved profile.
fn goblet(s: &Spec) -> Model {
    let k = s.size;
    let (t, w) = (s.tall, s.wide);
    let pts: Vec<[f64; 2]> = [
        [0.0, 0.0],
        [38.0, 0.0],
        [38.0, 4.0],
        [7.0, 10.0],
        [4.5, 20.0],
        [4.5, 95.0],
        [9.0, 103.0],
        [31.0, 116.0],
        [40.0, 140.0],
        [41.0, 190.0],
        [38.5, 190.0],
        [37.5, 141.0],
        [29.0, 119.0],
        [8.0, 107.0],
        [0.0, 107.0],
    ]
    .iter()
    .map(|q| [q[0] * k * w, q[1] * k * t])
    .collect();
    let mut p = Parts::default();
    p.add("glass", revolve(&pts, 0.0, 0.0));
    p.finish()
}

/// A rubber cup opening downward with a long wooden handle.
fn plunger(s: &Spec) -> Model {
    let k = s.size;
    let cup_pts: Vec<[f64; 2]> = [
        [66.0, 0.0],
        [72.0, 0.0],
        [70.0, 20.0],
        [60.0, 42.0],
        [40.0, 58.0],
        [15.0, 66.0],
        [0.0, 68.0],
        [0.0, 62.0],
        [14.0, 60.0],
        [36.0, 52.0],
        [55.0, 38.0],
        [64.0, 20.0],
    ]
    .iter()
    .map(|q| [q[0] * k, q[1] * k])
    .collect();
    let mut p = Parts::default();
    p.add("cup", revolve(&cup_pts, 0.0, 0.0));
    p.add("handle", cyl_z(25.0 * k, 60.0 * k, 520.0 * k * s.tall * s.long, 0.0, 0.0));
    p.finish()
}

/// A round base, a post, a motor, three blades facing −Y inside a round guard.
fn desk_fan(s: &Spec) -> Model {
    let k = s.size;
    let zc = 280.0 * k * s.tall;
    let mut p = Parts::default();
    p.add("base", cyl_z(170.0 * k, 0.0, 30.0 * k, 0.0, 0.0));
    p.add("post", cyl_z(26.0 * k, 30.0 * k, zc, 0.0, 0.0));
    p.add("motor", cyl_y(80.0 * k, -60.0 * k, 50.0 * k, 0.0, zc));
    p.add("hub", cyl_y(44.0 * k, -95.0 * k, -58.0 * k, 0.0, zc));
    // Blades and struts: thin plates in the XZ plane (the Y axis's plane is (Z, X)).
    for a in &[0.0f64, 120.0, 240.0] {
        let r = 78.0 * k;
        let at = [zc + r * a.to_radians().cos(), r * a.to_radians().sin()];
        p.add(
            "blade",
            Shape::Prism {
                profile: Profile::Rect { w: 120.0 * k, h: 46.0 * k },
                axis: Axis::Y,
                at,
                rot: *a,
                from: -90.0 * k,
                to: -86.0 * k,
            },
        );
        let b = a + 60.0;
        let r2 = 80.0 * k;
        let at2 = [zc + r2 * b.to_radians().cos(), r2 * b.to_radians().sin()];
        p.add(
            "strut",
            Shape::Prism {
                profile: Profile::Rect { w: 150.0 * k, h: 6.0 * k },
                axis: Axis::Y,
                at: at2,
                rot: b,
                from: -80.0 * k,
                to: -74.0 * k,
            },
        );
    }
    p.add("guard", Shape::Torus { c: [0.0, -77.0 * k, zc], axis: Axis::Y, major: 306.0 * k, minor: 12.0 * k });
    p.finish()
}

/// A tapered handle under a round grille.
fn microphone(s: &Spec) -> Model {
    let k = s.size;
    let h = 170.0 * k * s.long * s.tall;
    let mut p = Parts::default();
    p.add("handle", cone_z(28.0 * k, 40.0 * k, 0.0, h, 0.0, 0.0));
    p.add("ring", cyl_z(46.0 * k, h - 12.0 * k, h + 2.0 * k, 0.0, 0.0));
    p.add("grille", sphere(64.0 * k, [0.0, 0.0, h + 24.0 * k]));
    p.finish()
}

/// Lying flat: a handle with an open jaw at one end and a ring at the other.
fn wrench(s: &Spec) -> Model {
    let k = s.size;
    let l = 180.0 * k * s.long;
    let t = 8.0 * k * s.thick;
    let mut p = Parts::default();
    p.add("handle", bx([0.0, -11.0 * k, 0.0], [l, 11.0 * k, t]));
    p.add(
        "jaw",
        Shape::Prism {
            profile: Profile::Annulus { od: 50.0 * k, id: 22.0 * k },
            axis: Axis::Z,
            at: [-15.0 * k, 0.0],
            rot: 0.0,
            from: 0.0,
            to: t,
        },
    );
    p.add(
        "ring",
        Shape::Prism {
            profile: Profile::Annulus { od: 40.0 * k, id: 20.0 * k },
            axis: Axis::Z,
            at: [l + 12.0 * k, 0.0],
            rot: 0.0,
            from: 0.0,
            to: t,
        },
    );
    p.cut("jaw opening", bx([-45.0 * k, -11.0 * k, -1.0], [-15.0 * k, 11.0 * k, t + 1.0]));
    p.finish()
}

/// Standing on its handle: a round head across the top.
fn mallet(s: &Spec) -> Model {
    let k = s.size;
    let h = 300.0 * k * s.long;
    let mut p = Parts::default();
    p.add("handle", cyl_z(30.0 * k, 0.0, h, 0.0, 0.0));
    p.add("head", cyl_y(85.0 * k * s.thick, -70.0 * k, 70.0 * k, 0.0, h + 30.0 * k));
    p.finish()
}

/// Solid steps rising along +X.
fn staircase(s: &Spec) -> Model {
    let n = f64::from(s.count.unwrap_or(3));
    let k = s.size;
    let (w, tread, rise) = (900.0 * k * s.wide, 260.0 * k, 170.0 * k * s.tall);
    let mut p = Parts::default();
    for i in 0..s.count.unwrap_or(3) {
        let i = f64::from(i);
        p.add("step", bx([i * tread, -w / 2.0, 0.0], [n * tread, w / 2.0, (i + 1.0) * rise]));
    }
    p.finish()
}

/// A disc base, a pole, a knob on top and J-hooks around the top of the pole.
fn coat_rack(s: &Spec) -> Model {
    let k = s.size;
    let h = 1750.0 * k * s.tall;
    let mut p = Parts::default();
    p.add("base", cyl_z(450.0 * k, 0.0, 35.0 * k, 0.0, 0.0));
    p.add("pole", cyl_z(40.0 * k, 35.0 * k, h, 0.0, 0.0));
    p.add("knob", sphere(64.0 * k, [0.0, 0.0, h + 10.0 * k]));
    let hook = |p: &mut Parts, axis: Axis, sign: f64, z: f64| {
        // The hook starts inside the pole (radius 20), its end disc wholly in it.
        let mut c = [0.0, 0.0, z];
        c[axis.index()] = sign * 8.0 * k;
        let (a0, a1) = if sign > 0.0 { (-90.0, 30.0) } else { (270.0, 150.0) };
        p.add("hook", rod_arc(16.0 * k, c, 90.0 * k, axis, Axis::Z, a0, a1));
        // A ball at the hook's end.
        let t = a1.to_radians();
        let mut e = c;
        e[axis.index()] += 90.0 * k * t.cos();
        e[2] += 90.0 * k * t.sin();
        p.add("hook end", sphere(24.0 * k, e));
    };
    let hooks = s.count.unwrap_or(4);
    let dirs: &[(Axis, f64)] = if hooks == 2 {
        &[(Axis::X, 1.0), (Axis::X, -1.0)]
    } else {
        &[(Axis::X, 1.0), (Axis::Y, 1.0), (Axis::X, -1.0), (Axis::Y, -1.0)]
    };
    for (axis, sign) in dirs {
        hook(&mut p, *axis, *sign, h - 200.0 * k);
    }
    p.finish()
}

/// Lying flat: a body with two bouts and a waist between them (the outline of two circles
/// blended), a sound hole, a bridge, a fretboard standing above the top, a nut, a
/// headstock with three tuning pegs on each side, along +X.
fn guitar(s: &Spec) -> Model {
    let k = s.size;
    let t = 100.0 * k * s.thick;
    let (xl, rl, xu, ru) = (-40.0 * k, 180.0 * k, 160.0 * k, 130.0 * k);
    // Half-width: the two bouts' circles blended by an 8-norm, which fills the notch
    // between them into a waist about two thirds of the lower bout.
    let half = |x: f64| {
        let c = |x0: f64, r: f64| (r * r - (x - x0) * (x - x0)).max(0.0).sqrt();
        (c(xl, rl).powi(8) + c(xu, ru).powi(8)).powf(0.125)
    };
    let (x0, x1) = (xl - rl, xu + ru);
    let n = 48;
    let xs: Vec<f64> =
        (0..=n).map(|i| x0 + (x1 - x0) * 0.5 * (1.0 - (std::f64::consts::PI * i as f64 / n as f64).cos())).collect();
    let mut outline: Vec<[f64; 2]> = xs.iter().map(|&x| [x, -half(x)]).collect();
    outline.extend(xs.iter().rev().skip(1).take(n - 1).map(|&x| [x, half(x)]));
    let mut p = Parts::default();
    p.add("body", prism_xy(&outline, 0.0, t));
    let neck_end = 700.0 * k * s.long;
    p.add("neck", bx([x1 - 40.0 * k, -26.0 * k, t - 25.0 * k], [neck_end, 26.0 * k, t + 6.0 * k]));
    p.add("nut", bx([neck_end - 8.0 * k, -26.0 * k, t], [neck_end, 26.0 * k, t + 10.0 * k]));
    let head_end = neck_end + 180.0 * k;
    p.add("headstock", bx([neck_end - 1.0, -42.0 * k, t - 22.0 * k], [head_end, 42.0 * k, t - 2.0 * k]));
    for i in 0..3 {
        let x = neck_end + (45.0 + 50.0 * i as f64) * k;
        p.add("tuning peg", cyl_y(12.0 * k, -62.0 * k, 62.0 * k, x, t - 12.0 * k));
    }
    p.add("bridge", bx([-70.0 * k, -50.0 * k, t - 1.0], [-45.0 * k, 50.0 * k, t + 9.0 * k]));
    p.cut("sound hole", cyl_z(88.0 * k, t - 10.0 * k, t + 1.0, xu - 10.0 * k, 0.0));
    p.finish()
}

/// An open tray on two legs, a wheel at the front and two handles at the back.
fn wheelbarrow(s: &Spec) -> Model {
    let k = s.size;
    let mut p = Parts::default();
    let tray = p.add(
        "tray",
        Shape::Loft {
            at: [0.0, 0.0],
            from: 350.0 * k,
            to: 650.0 * k,
            bottom: Profile::Rect { w: 500.0 * k, h: 400.0 * k },
            top: Profile::Rect { w: 820.0 * k, h: 650.0 * k },
        },
    );
    open_top(tray, 8.0 * k);
    p.add("wheel", cyl_y(380.0 * k, -45.0 * k, 45.0 * k, 620.0 * k, 190.0 * k));
    for y in [-1.0, 1.0] {
        p.add(
            "fork",
            bx([150.0 * k, y * 60.0 * k - 10.0 * k, 180.0 * k], [640.0 * k, y * 60.0 * k + 10.0 * k, 370.0 * k]),
        );
        p.add(
            "handle",
            bx([-950.0 * k, y * 260.0 * k - 15.0 * k, 520.0 * k], [0.0, y * 260.0 * k + 15.0 * k, 555.0 * k]),
        );
        p.add(
            "leg",
            bx([-360.0 * k, y * 260.0 * k - 15.0 * k, 0.0], [-330.0 * k, y * 260.0 * k + 15.0 * k, 530.0 * k]),
        );
    }
    p.finish()
}

/// A rounded tub, open at the top, on four short feet.
fn bathtub(s: &Spec) -> Model {
    let k = s.size;
    let (l, w, h, lift) = (1600.0 * k * s.long, 750.0 * k * s.wide, 550.0 * k * s.tall, 120.0 * k);
    let mut p = Parts::default();
    let tub = p.add("tub", bx([-l / 2.0, -w / 2.0, lift], [l / 2.0, w / 2.0, lift + h]));
    round_vertical(tub, 200.0 * k);
    open_top(tub, 25.0 * k);
    for x in [-1.0, 1.0] {
        for y in [-1.0, 1.0] {
            p.add(
                "foot",
                cone_z(90.0 * k, 55.0 * k, 0.0, lift + 5.0 * k, x * (l / 2.0 - 180.0 * k), y * (w / 2.0 - 120.0 * k)),
            );
        }
    }
    p.finish()
}

/// A pickup truck: a body with an open bed, a cab and four wheels (front is +X).
fn pickup(s: &Spec) -> Model {
    let k = s.size;
    let (half_l, half_w) = (2650.0 * k * s.long, 950.0 * k);
    let mut p = Parts::default();
    p.add("body", bx([-half_l, -half_w, 400.0 * k], [half_l, half_w, 1100.0 * k]));
    p.add("cab", bx([200.0 * k, -900.0 * k, 1099.0 * k], [1400.0 * k, 900.0 * k, 1850.0 * k]));
    p.add("hood", bx([1399.0 * k, -930.0 * k, 1099.0 * k], [half_l, 930.0 * k, 1180.0 * k]));
    for x in [-1700.0 * k * s.long, 1700.0 * k * s.long] {
        for side in [-1.0, 1.0] {
            let (y0, y1) = if side > 0.0 {
                (half_w - 130.0 * k, half_w + 110.0 * k)
            } else {
                (-half_w - 110.0 * k, -half_w + 130.0 * k)
            };
            p.add("wheel", cyl_y(800.0 * k, y0, y1, x, 400.0 * k));
        }
    }
    p.cut(
        "bed",
        bx([-half_l + 100.0 * k, -half_w + 100.0 * k, 750.0 * k], [150.0 * k, half_w - 100.0 * k, 1101.0 * k]),
    );
    p.finish()
}
