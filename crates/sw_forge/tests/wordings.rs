#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Families of wordings: the same part said in the manners engineers write it (drawing
//! notes, shop shorthand, catalogue lines, forum questions, British English, inches),
//! generated over several sizes, must read as one part whose size and volume are worked out
//! here by closed formulas; words that only say again what was said add nothing; words that
//! contradict each other are refused with them. Pure Rust (no CadQuery): what the forge
//! promises is checked against the executed code by `bench cad` and `tests/synth.rs`.
//!
//! A failure prints what each stage made of the words — the lengths with their roles
//! (`doc`), the things they belong to (`mention`), the second reading (`takeoff`) — so it
//! says which stage lost the word.

use std::f64::consts::PI;

use sw_forge::synth::doc::Doc;
use sw_forge::synth::mention;
use sw_forge::synth::takeoff::Takeoff;
use sw_forge::synth::{SynthError, Synthesis, synthesize};

/// What each stage read of a prompt.
fn stages(prompt: &str) -> String {
    let d = Doc::new(prompt);
    let mut s = String::from("  doc (lengths, roles, qualifiers):\n");
    for x in &d.dims {
        s.push_str(&format!("    {} mm {:?} {:?} list {:?}\n", x.mm, x.role, x.quals, x.list));
    }
    s.push_str("  mention (things and their lengths):\n");
    let (_, els) = mention::read(&d);
    for e in &els {
        let mm: Vec<f64> = e.dims.iter().map(|k| d.dims[*k].mm).collect();
        s.push_str(&format!("    {} {:?} shape {:?} count {:?} {mm:?}\n", e.noun, e.kind, e.shape, e.count));
    }
    s.push_str("  takeoff (the second reading):\n");
    let t = Takeoff::read(&d);
    for (k, th) in t.things.iter().enumerate() {
        s.push_str(&format!("    {} {:?} {:?}\n", th.noun, th.kind, t.solid(k)));
    }
    s
}

fn sorted(mut v: [f64; 3]) -> [f64; 3] {
    v.sort_by(f64::total_cmp);
    v
}

/// The prompt reads as a part of these extents (any order) and this volume.
fn made(prompt: &str, size: [f64; 3], volume: f64) -> Result<(), String> {
    let s: Synthesis = synthesize(prompt).map_err(|e| format!("{prompt}\n  refused: {e}\n{}", stages(prompt)))?;
    let (a, b) = (sorted(s.size), sorted(size));
    let size_ok = a.iter().zip(&b).all(|(x, y)| (x - y).abs() <= 1e-3 * y.max(1.0));
    let vol_ok = s.volume.is_none_or(|v| (v - volume).abs() <= 1e-3 * volume);
    if size_ok && vol_ok {
        Ok(())
    } else {
        Err(format!(
            "{prompt}\n  made {:?} ({:?} mm³), the words say {size:?} ({volume:.1} mm³)\n{}",
            s.size,
            s.volume,
            stages(prompt)
        ))
    }
}

/// The prompt is refused, quoting one of these words.
fn refused(prompt: &str, words: &[&str]) -> Result<(), String> {
    match synthesize(prompt) {
        Err(SynthError::Unread { phrase, .. }) if words.iter().any(|w| phrase.contains(w)) => Ok(()),
        other => {
            Err(format!("{prompt}\n  expected a refusal quoting one of {words:?}, got {other:?}\n{}", stages(prompt)))
        }
    }
}

fn check(results: Vec<Result<(), String>>) {
    let failed: Vec<String> = results.into_iter().filter_map(Result::err).collect();
    assert!(failed.is_empty(), "{} of the family failed:\n{}", failed.len(), failed.join("\n"));
}

fn tube(od: f64, id: f64, l: f64) -> f64 {
    PI / 4.0 * (od * od - id * id) * l
}

#[test]
fn a_tube_by_its_diameters_and_length() {
    let mut r = Vec::new();
    for (od, id, l) in [(42.0, 36.0, 120.0), (50.0, 40.0, 100.0), (25.0, 19.0, 300.0)] {
        let w = (od - id) / 2.0;
        for p in [
            format!("{od} OD x {id} ID x {l} long tube"),
            format!("{od} OD x {id} ID x {l} LG TUBE"),
            format!("Tube, {od} mm OD, {id} mm ID, {l} mm long"),
            format!("{l} long tube, OD {od}, ID {id}"),
            format!("tube Ø{od} x {l} lg, {w} wall"),
            format!("A length of tube, {od} outside diameter and {w} wall, {l} long."),
            format!("how do I make a hollow cylinder? {od} outside diameter, {id} inside, {l} tall"),
        ] {
            r.push(made(&p, [od, od, l], tube(od, id, l)));
        }
    }
    // In inches: the same tube.
    r.push(made("1.5 in OD x 1.25 in ID x 4 in long tube", [38.1, 38.1, 101.6], tube(38.1, 31.75, 101.6)));
    r.push(made("1-1/2\" OD x 1-1/4\" ID x 4\" long tube", [38.1, 38.1, 101.6], tube(38.1, 31.75, 101.6)));
    check(r);
}

#[test]
fn a_bar_or_pin_by_diameter_and_length_with_chamfered_ends() {
    let mut r = Vec::new();
    for (d, l, c) in [(20.0, 50.0, 1.0), (25.0, 60.0, 0.5), (12.0, 40.0, 1.0)] {
        let rr = d / 2.0;
        let one_end = 2.0 * PI * (rr - c / 3.0) * (c * c / 2.0);
        let v = PI * rr * rr * l - 2.0 * one_end;
        for p in [
            format!("Ø{d} x {l} pin, {c}x45° chamfer both ends"),
            format!("pin Ø{d} x {l} lg, {c}x45 chfr both ends"),
            format!("{d} mm diameter pin, {l} mm long, with a {c} mm x 45° chamfer on each end"),
            format!("Ø{d} x {l} pin with a {c} x 45° chamfer on each end. Both ends chamfered, same size, {c} mm."),
        ] {
            r.push(made(&p, [d, d, l], v));
        }
        // At one end only (either end gives the same part).
        for p in [
            format!("A rod {d} mm in diameter and {l} mm long with a {c} mm chamfer at one end."),
            format!("Ø{d} x {l} pin, {c}x45° chamfer one end"),
        ] {
            r.push(made(&p, [d, d, l], PI * rr * rr * l - one_end));
        }
        for p in [
            format!("rd bar Ø{d} x {l} lg"),
            format!("{d}\u{2300} x {l} long round bar"),
            format!("A {d} mm round bar, {l} long."),
        ] {
            r.push(made(&p, [d, d, l], PI * rr * rr * l));
        }
    }
    check(r);
}

#[test]
fn a_plate_with_a_hole_at_each_corner() {
    let mut r = Vec::new();
    for (a, b, t, h, i) in [(100.0, 60.0, 8.0, 6.6, 10.0), (150.0, 100.0, 10.0, 11.0, 15.0)] {
        let v = a * b * t - 4.0 * PI * h * h / 4.0 * t;
        for p in [
            format!("PLATE {a} x {b} x {t}, 4X Ø{h} THRU, {i} FROM EDGES"),
            format!("plt {a}x{b}x{t}, 4x Ø{h} thru {i} from edges"),
            format!("A {a} x {b} x {t} plate with four {h} mm holes, {i} mm from each edge at the corners"),
            format!("a {a} x {b} x {t} mm plate with a {h} mm hole {i} mm in from each corner (four holes)"),
            format!("PLATE {a} x {b} x {t}, 4X Ø{h} THRU ON {} x {} CENTRES", a - 2.0 * i, b - 2.0 * i),
            format!(
                "A {a} by {b} by {t} plate with four {h} mm holes on a {} by {} rectangle",
                a - 2.0 * i,
                b - 2.0 * i
            ),
        ] {
            r.push(made(&p, [a, b, t], v));
        }
    }
    check(r);
}

#[test]
fn polygonal_bars_across_flats_and_corners() {
    let mut r = Vec::new();
    for (af, l) in [(22.0, 40.0), (17.0, 30.0), (19.0, 60.0)] {
        let ac = af / (PI / 6.0).cos();
        let v = 3.0 * 3f64.sqrt() / 2.0 * (ac / 2.0).powi(2) * l;
        for p in [
            format!("hex {af} A/F x {l} lg"),
            format!("Hex bar {af} across flats, {l} long"),
            format!("A hexagonal bar {af} mm across the flats and {l} mm long"),
            format!("Hex bar {af} across flats, {l} long. Across the corners it is what a hexagon gives."),
        ] {
            r.push(made(&p, [ac, af, l], v));
        }
    }
    // An octagon given across its flats lies on a flat: across flats both ways.
    let (af, l) = (30.0, 60.0);
    let side = af * (PI / 8.0).tan();
    r.push(made(&format!("An octagonal bar {af} across flats and {l} long."), [af, af, l], 2.0 * af * side * l));
    check(r);
}

#[test]
fn words_that_say_again_what_was_said_add_nothing() {
    let mut r = Vec::new();
    for (x, y, z) in [(80.0, 40.0, 20.0), (50.0, 30.0, 20.0)] {
        let base = format!("A block {x} x {y} x {z}.");
        for again in [
            String::new(),
            format!(" It is {x} long, {y} wide and {z} thick."),
            " One block, lying flat.".to_string(),
            format!(" The block is {z} mm thick."),
            format!(" Its length is {x} and its width {y}."),
        ] {
            r.push(made(&format!("{base}{again}"), [x, y, z], x * y * z));
        }
    }
    for (d, l) in [(30.0, 60.0), (20.0, 45.0)] {
        let v = PI * d * d / 4.0 * l;
        for again in ["", " Its diameter is {d} and its length {l}.", " A single cylinder, standing upright."] {
            let again = again.replace("{d}", &d.to_string()).replace("{l}", &l.to_string());
            r.push(made(
                &format!("A cylinder {d} mm in diameter and {l} mm long, with its axis along Z.{again}"),
                [d, d, l],
                v,
            ));
        }
    }
    check(r);
}

#[test]
fn words_that_contradict_each_other_are_refused_with_them() {
    let mut r = Vec::new();
    for (a, b) in [(50.0, 40.0), (30.0, 25.0)] {
        r.push(refused(&format!("A {a} mm cube, {a} x {a} x {b}."), &[&b.to_string()]));
    }
    for (od, id) in [(10.0, 12.0), (20.0, 25.0)] {
        r.push(refused(&format!("Washer {od} OD, {id} ID, 2 thick."), &[&id.to_string()]));
    }
    for (od, w, id) in [(30.0, 3.0, 26.0), (50.0, 5.0, 30.0)] {
        r.push(refused(&format!("Tube {od} OD, {w} wall, {id} ID, 50 long."), &["wall", "ID"]));
    }
    for (d, t) in [(25.0, 20.0), (30.0, 12.0)] {
        r.push(refused(&format!("Blind hole Ø8 x {d} dp in a 60 x 60 x {t} plate."), &["Blind hole", &d.to_string()]));
    }
    for (pin, hole) in [(20.0, 25.0), (10.0, 10.0)] {
        r.push(refused(&format!("Ø{pin} x 60 pin with a Ø{hole} cross hole through the middle."), &["cross hole"]));
    }
    check(r);
}

#[test]
fn screw_sizes_read_as_clearance_holes_or_tap_drills() {
    // ISO 273 medium clearance and ISO coarse tap drills.
    let mut r = Vec::new();
    for (m, clear, tap) in [(4.0, 4.5, 3.3), (5.0, 5.5, 4.2), (6.0, 6.6, 5.0), (8.0, 9.0, 6.8)] {
        let disc = PI * 20.0 * 20.0 * 10.0;
        for (p, h) in [
            (format!("Ø40 x 10 disc, M{m} clearance hole thru ctr"), clear),
            (format!("Ø40 x 10 disc, M{m} clr thru ctr"), clear),
            (format!("Ø40 x 10 disc, M{m} tapped thru ctr"), tap),
        ] {
            r.push(made(&p, [40.0, 40.0, 10.0], disc - PI * h * h / 4.0 * 10.0));
        }
    }
    check(r);
}

#[test]
fn a_part_of_a_catalog_object_is_never_the_whole_object() {
    // ("a lamp shade" is a catalog category of its own since the catalog grew: a shade is
    // the part asked for, and the catalog makes it.)
    for p in ["a sofa leg", "a table leg", "a chair back", "a mug handle"] {
        match sw_forge::freeform::offline(p) {
            Err(SynthError::Unread { reason, .. }) => assert!(reason.contains("part of"), "{p}: {reason}"),
            Err(e) => panic!("{p}: {e}"),
            Ok(_) => panic!("{p}: made an object for a part of one"),
        }
    }
}

/// Words with no number of their own that place or count what the numbers size: blind holes
/// at both ends, a bore through the length, a body below another, and inch drawings written
/// without a unit. Each is made as the words say, or refused quoting them — never made
/// otherwise (the second reading measures the part for each).
#[test]
fn words_that_place_or_count_without_a_number() {
    let mut out = Vec::new();
    let cyl = |d: f64, l: f64| PI * d * d / 4.0 * l;
    // (ISO coarse tap drills: M4 3.3, M5 4.2, M6 5.0.)
    for (d, l, m, tap, depth) in [(8.0, 40.0, 4, 3.3, 10.0), (10.0, 30.0, 5, 4.2, 8.0), (12.0, 50.0, 6, 5.0, 12.0)] {
        let want = cyl(d, l) - 2.0 * cyl(tap, depth);
        for prompt in [
            format!("STANDOFF Ø{d} x {l} LG, M{m} TAPPED x {depth} DP BOTH ENDS"),
            format!("pin {d} mm diameter, {l} mm long, with an M{m} tapped hole {depth} mm deep at each end"),
        ] {
            out.push(made(&prompt, [d, d, l], want));
        }
    }
    for (s, l, h) in [(20.0, 80.0, 6.0), (25.0, 100.0, 10.0), (30.0, 150.0, 12.0)] {
        let prompt = format!(
            "A square bar {s} mm across the flats and {l} mm long, with a {h} mm hole bored right through its length"
        );
        out.push(made(&prompt, [s, s, l], s * s * l - cyl(h, l)));
    }
    for (fd, ft, bd, bl, bore) in [(40.0, 5.0, 25.0, 20.0, 16.0), (30.0, 4.0, 20.0, 12.0, 10.0)] {
        let prompt = format!(
            "Flanged bushing: flange Ø{fd} x {ft} thick, body Ø{bd} x {bl} long below the flange, Ø{bore} bore right through"
        );
        out.push(made(&prompt, [fd, fd, ft + bl], cyl(fd, ft) + cyl(bd, bl) - cyl(bore, ft + bl)));
    }
    // Unitless fractions and leading-point decimals are an inch drawing's.
    let i = 25.4;
    for (od, id, l, text) in [
        (0.375, 0.191, 0.5, "round spacer 3/8 OD x .191 ID x 1/2 long"),
        (0.625, 0.375, 0.75, "bushing 5/8 OD x 3/8 ID x 3/4 long"),
    ] {
        out.push(made(text, [od * i, od * i, l * i], tube(od * i, id * i, l * i)));
    }
    // Two blind holes that would meet, and a second inch size in millimetres that disagrees.
    out.push(refused("PIN Ø6 x 20 LG, Ø4 x 12 DP BOTH ENDS", &["BOTH"]));
    out.push(refused("bushing 5/8 OD x 3/8 ID x 3/4 long, 20 mm long", &["20"]));
    check(out);
}

/// A bore "through its length" runs along the part's own axis: a round part's axis whatever
/// its proportions (a disc wider than it is long, a flanged bushing whose flange is wider
/// than the part is long, a cylinder as long as it is wide), a bar's or block's one longest
/// extent otherwise. The volumes are worked out here: a bore along the axis removes
/// `π/4·d²·L` of the part's length L, one across it would remove a different amount.
#[test]
fn a_bore_through_its_length_runs_along_the_parts_axis() {
    let mut out = Vec::new();
    let cyl = |d: f64, l: f64| PI * d * d / 4.0 * l;
    // Discs and rounds wider than long, and as wide as long (no one longest extent).
    for (d, l, h) in [(80.0, 20.0, 10.0), (60.0, 60.0, 20.0), (120.0, 15.0, 25.0)] {
        for prompt in [
            format!("A cylinder {d} mm in diameter and {l} mm long with a {h} mm hole through its length"),
            format!("round disc Ø{d} x {l} long, {h} mm bore through the full length"),
        ] {
            out.push(made(&prompt, [d, d, l], cyl(d, l) - cyl(h, l)));
        }
    }
    // A flanged bushing wider than it is long: the bore still runs its axis.
    for (fd, ft, bd, bl, bore) in [(60.0, 5.0, 30.0, 20.0, 16.0), (50.0, 6.0, 24.0, 10.0, 12.0)] {
        let prompt = format!(
            "Flanged bushing: flange Ø{fd} x {ft} thick, body Ø{bd} x {bl} long below the flange, Ø{bore} bore through its length"
        );
        out.push(made(&prompt, [fd, fd, ft + bl], cyl(fd, ft) + cyl(bd, bl) - cyl(bore, ft + bl)));
    }
    // A block: along its one longest extent, on its centre line.
    for (l, w, h, d) in [(120.0, 40.0, 30.0, 10.0), (90.0, 25.0, 25.0, 8.0)] {
        let prompt = format!("A block {l} x {w} x {h} mm with a {d} mm hole drilled through its length");
        out.push(made(&prompt, [l, w, h], l * w * h - cyl(d, l)));
    }
    check(out);
}

/// Two lengths of one role joined by "and" ("legs 80 mm and 60 mm", "legs of 60 and 40")
/// are that role's two values, as "legs 80 x 60" is. Gusset volume: ½·a·b·t.
#[test]
fn two_legs_joined_by_and_are_both_legs() {
    let mut out = Vec::new();
    for (a, b, t) in [(80.0, 60.0, 8.0), (100.0, 70.0, 6.0), (50.0, 40.0, 5.0)] {
        for prompt in [
            format!("Gusset: right-angled triangle, legs {a} mm and {b} mm, {t} mm plate"),
            format!("Triangular gusset, {t} mm plate, legs {a} x {b}"),
            format!("gusset plate, right triangle with legs of {a} and {b} mm, {t} mm thick"),
        ] {
            out.push(made(&prompt, [a, b, t], 0.5 * a * b * t));
        }
    }
    check(out);
}

/// A C x 45° chamfer on one circular outside edge of radius r (Pappus).
fn chamfer_ring(r: f64, c: f64) -> f64 {
    2.0 * PI * (r - c / 3.0) * c * c / 2.0
}

#[test]
fn section_letters_written_apart_and_top_hat_bushes() {
    let mut out = Vec::new();
    for (a, b, t, w) in [(50.0, 30.0, 5.0, 40.0), (60.0, 60.0, 6.0, 25.0), (80.0, 40.0, 8.0, 50.0)] {
        let v = (a * t + (b - t) * t) * w;
        for p in [
            format!("L bracket {a} x {b} x {t} thick, {w} wide"),
            format!("L-bracket {a} x {b} x {t} thick, {w} wide"),
            format!("l bracket {a} x {b} x {t} thk, {w} wide"),
        ] {
            out.push(made(&p, [a, b, w], v));
        }
    }
    for (f, tf, s, ls, bore) in [(30.0, 4.0, 20.0, 12.0, 10.0), (40.0, 5.0, 25.0, 20.0, 16.0)] {
        let v = PI / 4.0 * (f * f * tf + s * s * ls - bore * bore * (tf + ls));
        for p in [
            format!(
                "Top-hat bush: flange Ø{f} x {tf} thick, spigot Ø{s} x {ls} long below the flange, Ø{bore} bore right through"
            ),
            format!(
                "Top hat bush: flange Ø{f} x {tf} thick, spigot Ø{s} x {ls} long below the flange, Ø{bore} bore right through"
            ),
            format!(
                "top hat bush, flange {f} dia x {tf} thk, body {s} dia x {ls} long below the flange, bored {bore} right through"
            ),
        ] {
            out.push(made(&p, [f, f, tf + ls], v));
        }
    }
    check(out);
}

#[test]
fn a_centre_bore_in_inches_chamfers_by_letter_and_bored_to_a_size() {
    let inch = 25.4;
    let mut out = Vec::new();
    for (d, t, b) in [(3.0, 0.375, 1.05), (4.0, 0.5, 1.5), (2.5, 0.25, 0.75)] {
        let v = tube(d * inch, b * inch, t * inch);
        for p in [
            format!("Round plate {d:.3} in dia x {t:.3} in thick, {b:.3} in centre bore"),
            format!("round plate {d} in diameter, {t} in thick, with a {b} in center bore"),
        ] {
            out.push(made(&p, [d * inch, d * inch, t * inch], v));
        }
    }
    for (d, h, c) in [(50.0, 20.0, 1.0), (30.0, 60.0, 2.0), (80.0, 12.0, 0.5)] {
        let v = PI * d * d / 4.0 * h - 2.0 * chamfer_ring(d / 2.0, c);
        for p in [
            format!("DISC Ø{d} x {h}, C{c} BOTH ENDS"),
            format!("rd bar {d} dia x {h} lg, C{c} both ends"),
            format!("Ø{d} x {h} pin, {c}x45° chamfer both ends"),
        ] {
            out.push(made(&p, [d, d, h], v));
        }
    }
    for (a, h, b) in [(40.0, 20.0, 16.0), (60.0, 30.0, 25.0)] {
        let v = a * a * h - PI * b * b / 4.0 * h;
        for p in [
            format!("Block {a} x {a} x {h}, bored {b} right through"),
            format!("blk {a} x {a} x {h}, drilled {b} thru"),
            format!("Block {a} x {a} x {h} with a {b} mm hole through it"),
        ] {
            out.push(made(&p, [a, a, h], v));
        }
    }
    // A finish says nothing about the geometry.
    for finish in ["black-oxide", "zinc-plated", "anodised", "galvanized"] {
        let p = format!("Shaft collar 20 mm bore x 36 mm OD x 12 mm wide, {finish} steel");
        out.push(made(&p, [36.0, 36.0, 12.0], tube(36.0, 20.0, 12.0)));
    }
    check(out);
}

#[test]
fn bodies_nothing_places_and_treatments_nothing_sizes_are_refused() {
    check(vec![
        // A flange and a body on one axis that no word stacks: end to end or overlapping
        // are different parts.
        refused("bush, flange 40 dia x 5, body 25 dia x 20 long, bore 16 thru", &["body"]),
        refused("Top hat bush, flange 40 dia x 5, body 25 dia x 20 long, bored 16 right through", &["body"]),
        // Said overall, the long body runs the whole length and the flange is at one end.
        made(
            "Flanged bush, 12 mm bore, 18 mm OD, flange 24 mm dia x 3 mm, overall length 20 mm",
            [24.0, 24.0, 20.0],
            PI / 4.0 * (24.0 * 24.0 * 3.0 + 18.0 * 18.0 * 17.0 - 12.0 * 12.0 * 20.0),
        ),
        // A chamfer with no size is refused, never left off; one said not to be there is not made.
        refused("Disc 50 dia x 20 thick, with a chamfer on both faces", &["chamfer"]),
        refused("A block 40 x 30 x 20 with a fillet on the top edges", &["fillet"]),
        made("Disc 50 dia x 20 thick, no chamfers", [50.0, 50.0, 20.0], PI * 625.0 * 20.0),
    ]);
}

#[test]
fn diameter_pairs_written_with_a_slash_under_a_title_noun() {
    let mut out = Vec::new();
    for (od, id, t) in [(140.0, 60.0, 12.0), (30.0, 17.0, 3.0), (80.0, 42.0, 10.0)] {
        let v = tube(od, id, t);
        for p in [
            format!("FLANGE OD {od} / ID {id} x {t} THK"),
            format!("WASHER OD {od} / ID {id} x {t} THK"),
            format!("RING {od} OD / {id} ID x {t} THK"),
            format!("Flange, OD {od}, ID {id}, {t} thick"),
        ] {
            out.push(made(&p, [od, od, t], v));
        }
        // Holes on a pitch circle between the two.
        let pcd = (od + id) / 2.0;
        let h = (od - id) / 5.0;
        out.push(made(
            &format!("FLANGE OD {od} / ID {id} x {t} THK, 4X Ø{h} THRU EQ SP ON {pcd} PCD"),
            [od, od, t],
            v - 4.0 * PI * h * h / 4.0 * t,
        ));
    }
    out.push(refused("Disc OD 80 / ID 90 x 10 thick", &["90"]));
    out.push(refused("WASHER OD 20 / ID 22 x 2 THK", &["22"]));
    check(out);
}

#[test]
fn a_square_bar_by_its_side_and_length_and_how_a_part_rests() {
    let inch = 25.4;
    let mut out = Vec::new();
    for (a, l) in [(1.5, 6.0), (0.75, 4.0), (2.0, 12.0)] {
        let (a, l) = (a * inch, l * inch);
        for p in
            [format!("Square bar {}\" x {}\" long", a / inch, l / inch), format!("square bar {a} mm x {l} mm long")]
        {
            out.push(made(&p, [l, a, a], a * a * l));
        }
    }
    for (d, l) in [(30.0, 60.0), (20.0, 100.0)] {
        let v = PI * d * d / 4.0 * l;
        for p in [
            format!("A {l} mm long cylinder of {d} mm diameter, standing upright on its end. Just the one cylinder."),
            format!("A cylinder {d} mm diameter, {l} mm long, standing on end"),
            format!("A cylinder {d} mm diameter, {l} mm long, lying on its side"),
        ] {
            out.push(made(&p, [d, d, l], v));
        }
    }
    // A cube has one size, whatever role says another.
    out.push(refused("how would I model a 40 mm cube that is 30 mm tall?", &["30 mm tall"]));
    out.push(refused("A 40 mm cube, 30 mm tall", &["30 mm tall"]));
    out.push(made("A 40 mm cube, 40 mm tall", [40.0, 40.0, 40.0], 64_000.0));
    check(out);
}

#[test]
fn holes_no_word_places_are_in_the_middle_of_a_part_that_runs_from_its_origin() {
    // A channel is made from X=0 along its length: a hole or a row of holes in its web sits
    // about the middle of the length, never half off its end.
    let mut out = Vec::new();
    for (web, fl, t, l, d, n, p) in [(50.0, 25.0, 3.0, 300.0, 6.5, 5, 50.0), (80.0, 40.0, 5.0, 400.0, 9.0, 3, 100.0)] {
        let section = web * t + 2.0 * (fl - t) * t;
        let hole = PI * d * d / 4.0 * t;
        out.push(made(
            &format!("U channel {web} x {fl} x {t}, {l} long, with a row of {n} holes {d} dia in the web at {p} ctrs"),
            [l, web, fl],
            section * l - f64::from(n) * hole,
        ));
        // Its volume is not known to the forge (a hole through a section's web), so where
        // the holes are is checked on the code: centred on the length at the pitch.
        let prompt = format!("U channel {web} x {fl} x {t}, {l} long, with {n} holes {d} dia in the web at {p} ctrs");
        let code = synthesize(&prompt).map(|s| s.code).unwrap_or_default();
        let mut xs: Vec<f64> = code
            .split(".translate((")
            .skip(1)
            .filter_map(|c| c.split(',').next()?.trim().parse::<f64>().ok())
            .collect();
        xs.sort_by(f64::total_cmp);
        let want: Vec<f64> = (0..n).map(|i| l / 2.0 + (f64::from(i) - f64::from(n - 1) / 2.0) * p).collect();
        if xs != want {
            out.push(Err(format!("{prompt}\n  holes at X {xs:?}, the words say {want:?}\n{code}")));
        }
        out.push(made(
            &format!("flat bar {l} x {web} x {t}, with a row of {n} holes {d} dia at {p} ctrs"),
            [l, web, t],
            web * t * l - f64::from(n) * hole,
        ));
    }
    check(out);
}
