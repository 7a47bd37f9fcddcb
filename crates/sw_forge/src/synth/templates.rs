//! The templates: which part a prompt asks for (by its nouns), and that part built from
//! the prompt's lengths as a [`Body`]. Each template says which lengths it needs and fails
//! with a message naming the missing one.

use std::f64::consts::PI;

use super::body::{Body, BoxEdges, Dir, Edge, Prim, regular, star};
use super::measure::{Axis, Reading, Role};

/// A template's result.
#[derive(Debug, Clone, PartialEq)]
pub struct Built {
    pub template: &'static str,
    pub body: Body,
    /// Through-holes of the part, when the template knows them.
    pub genus: Option<u32>,
}

pub type Outcome = Result<Built, String>;

/// A template's failure: its name and what was missing.
pub type Named = Result<Built, (&'static str, String)>;

fn named(name: &'static str, o: Outcome) -> Named {
    o.map_err(|e| (name, e))
}

fn built(template: &'static str, body: Body, genus: Option<u32>) -> Outcome {
    Ok(Built { template, body, genus })
}

fn need(v: Option<f64>, what: &str) -> Result<f64, String> {
    match v {
        Some(x) if x.is_finite() && x > 0.0 => Ok(x),
        Some(x) => Err(format!("the {what} must be a positive length, not {x}")),
        None => Err(format!("no {what} given")),
    }
}

/// The template names, in the order they are tried.
pub const TEMPLATES: &[&str] = &[
    "washer",
    "square_washer",
    "hex_nut",
    "hex_bolt",
    "flange",
    "bushing",
    "stacked_shaft",
    "gear",
    "i_beam",
    "t_beam",
    "l_bracket",
    "channel",
    "rect_tube",
    "plate_with_holes",
    "tube",
    "hemisphere",
    "dome",
    "sphere",
    "capsule",
    "frustum",
    "cone",
    "pyramid",
    "rect_frustum",
    "polygon_prism",
    "right_triangle_prism",
    "wedge",
    "stadium",
    "elliptic_cylinder",
    "half_pipe",
    "cylinder",
    "cube",
    "box",
];

/// Picks the template for a prompt and builds it.
pub fn build(r: &Reading) -> Named {
    let built = choose(r)?;
    // Features a template's part does not have.
    let refuse: &[(&str, &str)] =
        &[("l_bracket", "hole"), ("l_bracket", "holes"), ("flange", "pipe"), ("box", "hole"), ("box", "holes")];
    for (template, word) in refuse {
        if built.template == *template && r.mentions(word) {
            return Err((built.template, format!("the {template} template cannot make the {word} this part asks for")));
        }
    }
    // Features no template makes: refuse rather than hand back a different part.
    let counterbore_ok = built.template == "plate_with_holes";
    for feature in UNSUPPORTED {
        if r.mentions(feature) || r.mentions(&format!("{feature}s")) {
            return Err((built.template, format!("the synthesizer cannot make the {feature} this part asks for")));
        }
    }
    if !counterbore_ok && (r.mentions("counterbore") || r.mentions("counterbored")) {
        return Err((built.template, "the synthesizer makes counterbores only in plates".into()));
    }
    Ok(built)
}

/// Features the templates do not make.
const UNSUPPORTED: &[&str] = &[
    "keyway",
    "slot",
    "set screw",
    "cooling fin",
    "socket",
    "groove",
    "prong",
    "spoke",
    "boss",
    "shell",
    "shelled",
    "loft",
    "lofted",
    "sweep",
    "swept",
    "thread",
    "elbow",
    "tee",
    "lightening hole",
    "standoff",
    "recess",
    "chassis",
    "bend",
    "compound",
    "stack",
    "fitting",
    "assembly",
    "post",
    "pulley",
    "vase",
    "enclosure",
    "container",
    "handwheel",
    "flywheel",
    "coupling",
    "transition",
    "radiusarc",
];

fn choose(r: &Reading) -> Named {
    let t = &r.text;
    let has = |p: &str| r.mentions(p);
    let any = |ps: &[&str]| ps.iter().any(|p| has(p));
    if any(&["square flat washer", "square washer"]) {
        return named("square_washer", square_washer(r));
    }
    if any(&["washer"]) {
        return named("washer", washer(r));
    }
    if any(&["hex nut", "hexagonal nut", "nut"]) {
        return named("hex_nut", hex_nut(r));
    }
    if any(&["hex bolt", "hexagon bolt", "hexagonal bolt"]) {
        return named("hex_bolt", hex_bolt(r));
    }
    if any(&["gear"]) {
        return named("gear", gear(r));
    }
    if any(&["i-beam", "h-beam", "i beam", "h beam"]) {
        return named("i_beam", i_beam(r));
    }
    if any(&["t-beam", "t beam", "tee beam"]) {
        return named("t_beam", t_beam(r));
    }
    if any(&["l-bracket", "l bracket", "angle bracket", "l-shaped bracket", "angle iron"]) {
        return named("l_bracket", l_bracket(r));
    }
    if any(&["u-channel", "c-channel", "channel"]) {
        return named("channel", channel(r));
    }
    if any(&["rectangular tube", "square tube", "box section", "hollow rectangular"]) {
        return named("rect_tube", rect_tube(r));
    }
    if any(&["bushing", "flanged shaft", "shoulder screw", "stepped shaft"]) {
        return named("stacked", stacked(r));
    }
    if any(&["flange"]) && (any(&["plate", "disc", "disk"]) || r.count("hole").is_some()) {
        return named("flange", flange(r));
    }
    if any(&["hole", "holes"]) && any(&["plate", "block", "bracket", "panel"]) {
        return named("plate_with_holes", plate_with_holes(r));
    }
    if any(&["tube", "pipe", "ring", "sleeve", "spacer"]) && !t.contains("half-pipe") && !t.contains("half pipe") {
        return named("tube", tube(r));
    }
    // Primitives: the shape named first is the part ("a dome … topped by a hemisphere").
    let primitives: &[(&str, &'static str)] = &[
        ("half-pipe", "half_pipe"),
        ("half pipe", "half_pipe"),
        ("trough", "half_pipe"),
        ("hemisphere", "hemisphere"),
        ("half sphere", "hemisphere"),
        ("half-sphere", "hemisphere"),
        ("dome", "dome"),
        ("capsule", "capsule"),
        ("pill", "capsule"),
        ("sphere", "sphere"),
        ("ball", "sphere"),
        ("frustum", "frustum"),
        ("truncated cone", "frustum"),
        ("rectangular frustum", "rect_frustum"),
        ("tapered rectangular", "rect_frustum"),
        ("tapered block", "rect_frustum"),
        ("pyramid", "pyramid"),
        ("cone", "frustum"),
        ("right-angle triangular", "right_triangle_prism"),
        ("right triangle", "right_triangle_prism"),
        ("right-angled triangular", "right_triangle_prism"),
        ("right triangular", "right_triangle_prism"),
        ("wedge", "wedge"),
        ("triangular", "polygon_prism"),
        ("pentagonal", "polygon_prism"),
        ("hexagonal", "polygon_prism"),
        ("hex bar", "polygon_prism"),
        ("hex prism", "polygon_prism"),
        ("heptagonal", "polygon_prism"),
        ("octagonal", "polygon_prism"),
        ("decagonal", "polygon_prism"),
        ("dodecagonal", "polygon_prism"),
        ("-sided", "polygon_prism"),
        ("stadium", "stadium"),
        ("oblong", "stadium"),
        ("obround", "stadium"),
        ("elliptical", "elliptic_cylinder"),
        ("elliptic", "elliptic_cylinder"),
        ("oval", "elliptic_cylinder"),
        ("cylinder", "cylinder"),
        ("cylindrical", "cylinder"),
        ("rod", "cylinder"),
        ("disc", "cylinder"),
        ("disk", "cylinder"),
        ("puck", "cylinder"),
        ("pin", "cylinder"),
        ("dowel", "cylinder"),
        ("shaft", "cylinder"),
        ("coin", "cylinder"),
        ("cube", "cube"),
        ("block", "box"),
        ("box", "box"),
        ("plate", "box"),
        ("bar", "box"),
        ("fin", "box"),
        ("slab", "box"),
        ("brick", "box"),
        ("beam", "box"),
        ("prism", "box"),
        ("board", "box"),
        ("cuboid", "box"),
        ("panel", "box"),
    ];
    let mut best: Option<(usize, usize, &'static str)> = None;
    for (phrase, template) in primitives {
        let at = t.match_indices(phrase).map(|(i, _)| i).find(|&i| {
            let before = t[..i].chars().next_back();
            let after = t[i + phrase.len()..].chars().next();
            (phrase.starts_with('-') || !before.is_some_and(|c| c.is_ascii_alphanumeric()))
                && !after.is_some_and(|c| c.is_ascii_alphanumeric())
        });
        if let Some(at) = at {
            // The earliest mention; at the same place the longer phrase.
            let key = (at, usize::MAX - phrase.len());
            if best.is_none_or(|(a, l, _)| key < (a, l)) {
                best = Some((key.0, key.1, template));
            }
        }
    }
    if let Some((_, _, template)) = best {
        let o = match template {
            "half_pipe" => half_pipe(r),
            "hemisphere" => hemisphere(r),
            "dome" => dome(r),
            "capsule" => capsule(r),
            "sphere" => sphere(r),
            "frustum" => frustum(r),
            "rect_frustum" => rect_frustum(r),
            "pyramid" => pyramid(r),
            "right_triangle_prism" => right_triangle_prism(r),
            "wedge" => wedge(r),
            "polygon_prism" => match polygon_sides(r) {
                Some(k) => polygon_prism(r, k),
                None => Err("no number of sides given".into()),
            },
            "stadium" => stadium(r),
            "elliptic_cylinder" => elliptic_cylinder(r),
            "cylinder" => cylinder(r),
            "cube" => cube(r),
            _ => cuboid(r),
        };
        return named(template, o);
    }
    Err(("none", "no template for this part (the synthesizer knows blocks, cylinders, spheres, cones, tubes, washers, plates with holes, brackets, channels, beams, flanges, bushings, gears, prisms)".into()))
}

fn polygon_sides(r: &Reading) -> Option<usize> {
    let names: &[(&str, usize)] = &[
        ("triangular", 3),
        ("square prism", 4),
        ("pentagonal", 5),
        ("hexagonal", 6),
        ("hex bar", 6),
        ("hex prism", 6),
        ("heptagonal", 7),
        ("octagonal", 8),
        ("decagonal", 10),
        ("dodecagonal", 12),
    ];
    for (w, k) in names {
        if r.mentions(w) {
            return Some(*k);
        }
    }
    if let Some(k) = r.counts.iter().find(|(n, _)| n == "sided" || n == "side").map(|(_, k)| *k as usize)
        && (3..=64).contains(&k)
    {
        return Some(k);
    }
    None
}

/// A length along an axis or with one of these roles.
fn along(r: &Reading, axis: Axis, roles: &[Role]) -> Option<f64> {
    r.dims.iter().find(|d| d.axis == Some(axis) && !d.paren).map(|d| d.mm).or_else(|| {
        roles
            .iter()
            .find_map(|role| r.dims.iter().find(|d| d.role == *role && !d.paren && d.axis.is_none()).map(|d| d.mm))
    })
}

/// Length (X), width (Y), height (Z) of a block from roles, an "A by B by C" list, sides.
fn block_dims(r: &Reading) -> Result<[f64; 3], String> {
    let list = r.list();
    let side = r.mm(Role::Side, &[], &["fillet", "chamfer"]);
    let mut x = along(r, Axis::X, &[Role::Length]);
    let mut y = along(r, Axis::Y, &[Role::Width, Role::Depth]);
    let mut z = along(r, Axis::Z, &[Role::Height]);
    if list.len() >= 2 {
        x = x.or(Some(list[0]));
        y = y.or(Some(list[1]));
        if list.len() >= 3 {
            z = z.or(Some(list[2]));
        }
    }
    if let Some(s) = side {
        x = x.or(Some(s));
        y = y.or(Some(s));
    }
    // A thickness fills the one extent still missing ("80mm tall, 60mm long, 2mm thick").
    let thick = r.mm(Role::Thickness, &[], &[]);
    if z.is_none() {
        z = thick.or(side);
    } else if y.is_none() {
        y = thick;
    } else if x.is_none() {
        x = thick;
    }
    Ok([need(x, "length")?, need(y, "width")?, need(z, "height or thickness")?])
}

fn edge_treatment(r: &Reading) -> Option<(BoxEdges, Edge)> {
    let e = if let Some(f) = r.mm(Role::Fillet, &[], &[]) {
        Edge::Fillet(f)
    } else if let Some(c) = r.mm(Role::Chamfer, &[], &[]) {
        Edge::Chamfer(c)
    } else if r.mentions("rounded") || r.mentions("filleted") {
        Edge::Fillet(r.mm(Role::Radius, &[], &[])?)
    } else {
        return None;
    };
    let t = &r.text;
    let which = if t.contains("vertical edge") || t.contains("four vertical") {
        BoxEdges::Parallel(Dir::Z)
    } else if t.contains("long edge") {
        BoxEdges::Parallel(Dir::X)
    } else {
        BoxEdges::All
    };
    Some((which, e))
}

fn cuboid(r: &Reading) -> Outcome {
    let s = block_dims(r)?;
    let edges = edge_treatment(r);
    // "long edges": the edges along the longest side.
    let edges = edges.map(|(w, e)| match w {
        BoxEdges::Parallel(Dir::X) => {
            let d = if s[0] >= s[1] && s[0] >= s[2] {
                Dir::X
            } else if s[1] >= s[2] {
                Dir::Y
            } else {
                Dir::Z
            };
            (BoxEdges::Parallel(d), e)
        }
        o => (o, e),
    });
    check_edges(&s, edges)?;
    built("box", Body::of(Prim::Box { c: [0.0, 0.0, s[2] / 2.0], s, edges }), Some(0))
}

fn check_edges(s: &[f64; 3], edges: Option<(BoxEdges, Edge)>) -> Result<(), String> {
    if let Some((_, e)) = edges {
        let v = match e {
            Edge::Fillet(v) | Edge::Chamfer(v) => v,
        };
        let min = s.iter().copied().fold(f64::INFINITY, f64::min);
        if v <= 0.0 || 2.0 * v >= min {
            return Err(format!("an edge treatment of {v} mm does not fit a part {min} mm thin"));
        }
    }
    Ok(())
}

fn cube(r: &Reading) -> Outcome {
    let a = r.mm(Role::Side, &[], &[]).or_else(|| {
        r.dims.iter().find(|d| matches!(d.role, Role::Bare | Role::Length | Role::Width | Role::Height)).map(|d| d.mm)
    });
    let a = need(a, "side")?;
    let s = [a; 3];
    let edges = edge_treatment(r);
    check_edges(&s, edges)?;
    built("cube", Body::of(Prim::Box { c: [0.0, 0.0, a / 2.0], s, edges }), Some(0))
}

fn round_dims(r: &Reading) -> Result<(f64, f64), String> {
    let d = need(r.diameter(&[], &["bore", "hole", "inner"]), "diameter")?;
    let h = r
        .mm(Role::Height, &[], &[])
        .or_else(|| r.mm(Role::Length, &[], &[]))
        .or_else(|| r.mm(Role::Thickness, &[], &[]))
        .or_else(|| r.mm(Role::Depth, &[], &[]));
    Ok((d, need(h, "height (or length, thickness)")?))
}

fn cylinder(r: &Reading) -> Outcome {
    let (d, h) = round_dims(r)?;
    let edge = if let Some(f) = r.mm(Role::Fillet, &[], &[]) {
        Some(Edge::Fillet(f))
    } else {
        r.mm(Role::Chamfer, &[], &[]).map(Edge::Chamfer)
    };
    if let Some(Edge::Fillet(v) | Edge::Chamfer(v)) = edge
        && (v <= 0.0 || 2.0 * v >= h.min(d))
    {
        return Err(format!("an edge treatment of {v} mm does not fit this cylinder"));
    }
    built("cylinder", Body::of(Prim::Cyl { c: [0.0, 0.0, h / 2.0], r: d / 2.0, len: h, dir: Dir::Z, edge }), Some(0))
}

fn tube_dims(r: &Reading) -> Result<(f64, f64, f64), String> {
    let od = r.diameter(&["outer"], &[]).or_else(|| r.diameter(&[], &["inner", "bore", "hole"]));
    let od = need(od, "outer diameter")?;
    let id = r.diameter(&["inner"], &[]).or_else(|| r.diameter(&["bore"], &[])).or_else(|| r.diameter(&["hole"], &[]));
    let id = match id {
        Some(v) => v,
        None => {
            let wall = need(
                r.mm(Role::Wall, &[], &[]).or_else(|| r.mm(Role::Thickness, &["wall"], &[])),
                "inner diameter or wall",
            )?;
            od - 2.0 * wall
        }
    };
    let h = r
        .mm(Role::Thickness, &[], &["wall"])
        .or_else(|| r.mm(Role::Height, &[], &[]))
        .or_else(|| r.mm(Role::Length, &[], &[]));
    let h = need(h, "thickness (or height, length)")?;
    if id <= 0.0 || id >= od {
        return Err(format!("the inner diameter {id} mm must be smaller than the outer {od} mm"));
    }
    Ok((od, id, h))
}

fn annulus(od: f64, id: f64, z0: f64, h: f64) -> Prim {
    Prim::Revolve {
        profile: vec![[id / 2.0, z0], [od / 2.0, z0], [od / 2.0, z0 + h], [id / 2.0, z0 + h]],
        x: 0.0,
        y: 0.0,
    }
}

fn washer(r: &Reading) -> Outcome {
    let (od, id, h) = tube_dims(r)?;
    built("washer", Body::of(annulus(od, id, 0.0, h)), Some(1))
}

fn tube(r: &Reading) -> Outcome {
    let (od, id, h) = tube_dims(r)?;
    built("tube", Body::of(annulus(od, id, 0.0, h)), Some(1))
}

fn square_washer(r: &Reading) -> Outcome {
    let list = r.list();
    let side = r.mm(Role::Side, &[], &[]).or(list.first().copied());
    let a = need(side, "side")?;
    let b = list.get(1).copied().unwrap_or(a);
    let t = need(r.mm(Role::Thickness, &[], &[]).or(list.get(2).copied()), "thickness")?;
    let d = need(r.diameter(&[], &[]), "hole diameter")?;
    if d >= a.min(b) {
        return Err(format!("the hole ({d} mm) does not fit the washer"));
    }
    let body = Body::of(Prim::Box { c: [0.0, 0.0, t / 2.0], s: [a, b, t], edges: None }).minus(Prim::Cyl {
        c: [0.0, 0.0, t / 2.0],
        r: d / 2.0,
        len: t,
        dir: Dir::Z,
        edge: None,
    });
    built("square_washer", body, Some(1))
}

fn sphere(r: &Reading) -> Outcome {
    let d = need(r.diameter(&[], &[]), "diameter or radius")?;
    built("sphere", Body::of(Prim::Sphere { c: [0.0, 0.0, d / 2.0], r: d / 2.0 }), Some(0))
}

fn hemisphere(r: &Reading) -> Outcome {
    let d = need(r.diameter(&[], &[]), "diameter or radius")?;
    let rr = d / 2.0;
    let profile = quarter_arc(rr, 0.0, 48);
    built("hemisphere", Body::of(Prim::Revolve { profile, x: 0.0, y: 0.0 }), Some(0))
}

/// A quarter circle of radius `r` above z0 as a polygon — replaced by the exact arc in code
/// through [`Prim::Sphere`] would need a boolean; instead the dome is revolved from many
/// segments whose volume the Pappus sum gives exactly.
fn quarter_arc(r: f64, z0: f64, segments: usize) -> Vec<[f64; 2]> {
    let mut pts = vec![[0.0, z0]];
    for k in 0..=segments {
        let t = 0.5 * PI * k as f64 / segments as f64;
        pts.push([r * t.cos(), z0 + r * t.sin()]);
    }
    pts
}

fn dome(r: &Reading) -> Outcome {
    let d = need(r.diameter(&[], &[]), "diameter")?;
    let base = r.mm(Role::Thickness, &[], &[]).unwrap_or(0.0);
    let rr = d / 2.0;
    let mut profile = vec![[0.0, 0.0], [rr, 0.0]];
    profile.extend(quarter_arc(rr, base, 96).into_iter().skip(1));
    built("dome", Body::of(Prim::Revolve { profile, x: 0.0, y: 0.0 }), Some(0))
}

fn capsule(r: &Reading) -> Outcome {
    let (d, h) = round_dims(r)?;
    let rr = d / 2.0;
    let body = Body::of(Prim::Cyl { c: [0.0, 0.0, rr + h / 2.0], r: rr, len: h, dir: Dir::Z, edge: None })
        .plus(Prim::Sphere { c: [0.0, 0.0, rr], r: rr })
        .plus(Prim::Sphere { c: [0.0, 0.0, rr + h], r: rr });
    // The caps overlap the cylinder by half a sphere each: the volume is the cylinder and
    // one sphere, which the disjoint-sum rule cannot see, so it is given.
    let mut body = body;
    body.exact = Some(PI * rr * rr * h + 4.0 / 3.0 * PI * rr.powi(3));
    built("capsule", body, Some(0))
}

fn frustum(r: &Reading) -> Outcome {
    let base =
        r.diameter(&["base"], &[]).or_else(|| r.diameter(&["bottom"], &[])).or_else(|| r.diameter(&[], &["top"]));
    let base = need(base, "base diameter")?;
    let top = r.diameter(&["top"], &[]).unwrap_or(0.0);
    let h = need(r.mm(Role::Height, &[], &[]).or_else(|| r.mm(Role::Length, &[], &[])), "height")?;
    let profile = if top > 0.0 {
        vec![[0.0, 0.0], [base / 2.0, 0.0], [top / 2.0, h], [0.0, h]]
    } else {
        vec![[0.0, 0.0], [base / 2.0, 0.0], [0.0, h]]
    };
    built(if top > 0.0 { "frustum" } else { "cone" }, Body::of(Prim::Revolve { profile, x: 0.0, y: 0.0 }), Some(0))
}

fn pyramid(r: &Reading) -> Outcome {
    let a = need(r.mm(Role::Side, &[], &[]).or_else(|| r.mm(Role::Width, &[], &[])), "base side")?;
    let h = need(r.mm(Role::Height, &[], &[]), "height")?;
    built("pyramid", Body::of(Prim::RectFrustum { a0: a, b0: a, a1: 0.0, b1: 0.0, z0: 0.0, h }), Some(0))
}

fn rect_frustum(r: &Reading) -> Outcome {
    // "the base is 50mm (X) by 30mm (Y) …, the top face is 30mm (X) by 15mm (Y)".
    let xs: Vec<f64> = r.dims.iter().filter(|d| d.axis == Some(Axis::X)).map(|d| d.mm).collect();
    let ys: Vec<f64> = r.dims.iter().filter(|d| d.axis == Some(Axis::Y)).map(|d| d.mm).collect();
    let h = need(along(r, Axis::Z, &[Role::Height]), "height")?;
    if xs.len() < 2 || ys.len() < 2 {
        return Err("a tapered block needs its base and top sizes, each as X by Y".into());
    }
    built(
        "rect_frustum",
        Body::of(Prim::RectFrustum { a0: xs[0], b0: ys[0], a1: xs[1], b1: ys[1], z0: 0.0, h }),
        Some(0),
    )
}

fn polygon_prism(r: &Reading, sides: usize) -> Outcome {
    let d = r.diameter(&["circumscribed"], &[]).or_else(|| r.diameter(&[], &["across"]));
    let d = need(d, "circumscribed diameter")?;
    let h = r
        .mm(Role::Height, &[], &[])
        .or_else(|| r.mm(Role::Length, &[], &[]))
        .or_else(|| r.mm(Role::Thickness, &[], &[]));
    let h = need(h, "height (or length)")?;
    let pts = regular(sides, d / 2.0, if sides == 3 { PI / 2.0 } else { 0.0 });
    built("polygon_prism", Body::of(Prim::Prism { pts, dir: Dir::Z, mid: h / 2.0, len: h }), Some(0))
}

fn right_triangle_prism(r: &Reading) -> Outcome {
    let legs: Vec<&super::measure::Dim> = r.dims.iter().filter(|d| d.has("leg") || d.clause_has("leg")).collect();
    let a = legs.iter().find(|d| d.clause_mods.contains("x") || d.axis == Some(Axis::X)).or(legs.first()).map(|d| d.mm);
    let b = legs.iter().find(|d| d.axis == Some(Axis::Y)).or(legs.get(1)).map(|d| d.mm);
    let a = need(a, "first leg")?;
    let b = need(b, "second leg")?;
    let h = need(
        r.mm(Role::Length, &[], &[])
            .or_else(|| r.mm(Role::Height, &[], &[]))
            .or_else(|| r.mm(Role::Bare, &[], &["leg"])),
        "extrusion",
    )?;
    let pts = vec![[0.0, 0.0], [a, 0.0], [0.0, b]];
    built("right_triangle_prism", Body::of(Prim::Prism { pts, dir: Dir::Z, mid: h / 2.0, len: h }), Some(0))
}

fn wedge(r: &Reading) -> Outcome {
    let list = r.list();
    let x = need(along(r, Axis::X, &[Role::Length]).or(list.first().copied()), "length")?;
    let y = need(along(r, Axis::Y, &[Role::Width]).or(list.get(1).copied()), "width")?;
    let h = r
        .dims
        .iter()
        .rev()
        .find(|d| d.coord == Some(Axis::Z) || d.axis == Some(Axis::Z) || (d.role == Role::Height && d.coord.is_none()))
        .map(|d| d.mm);
    let h = need(h, "height")?;
    // Symmetric ridge: the triangle in YZ, extruded along X.
    let pts = vec![[-y / 2.0, 0.0], [y / 2.0, 0.0], [0.0, h]];
    built("wedge", Body::of(Prim::Prism { pts, dir: Dir::X, mid: 0.0, len: x }), Some(0))
}

fn stadium(r: &Reading) -> Outcome {
    let l = need(along(r, Axis::X, &[Role::Length]), "length")?;
    let w = need(along(r, Axis::Y, &[Role::Width]), "width")?;
    let h = need(along(r, Axis::Z, &[Role::Thickness, Role::Height]), "thickness")?;
    if w >= l {
        return Err("a stadium's width must be less than its length".into());
    }
    built("stadium", Body::of(Prim::Stadium { l, w, z0: 0.0, h }), Some(0))
}

fn elliptic_cylinder(r: &Reading) -> Outcome {
    let a =
        need(r.find(Role::Bare, &["major"], &[]).map(|d| d.mm).or_else(|| r.diameter(&["major"], &[])), "major axis")?;
    let b =
        need(r.find(Role::Bare, &["minor"], &[]).map(|d| d.mm).or_else(|| r.diameter(&["minor"], &[])), "minor axis")?;
    let h = need(r.mm(Role::Height, &[], &[]).or_else(|| r.mm(Role::Length, &[], &[])), "height")?;
    built("elliptic_cylinder", Body::of(Prim::Ellipse { a: a.max(b) / 2.0, b: a.min(b) / 2.0, z0: 0.0, h }), Some(0))
}

fn half_pipe(r: &Reading) -> Outcome {
    let ro = need(
        r.mm(Role::Radius, &["outer"], &[]).or_else(|| r.diameter(&["outer"], &[]).map(|d| d / 2.0)),
        "outer radius",
    )?;
    let ri = need(
        r.mm(Role::Radius, &["inner"], &[]).or_else(|| r.diameter(&["inner"], &[]).map(|d| d / 2.0)),
        "inner radius",
    )?;
    let len = r.dims.iter().find(|d| d.role == Role::Bare && d.has("extruded")).map(|d| d.mm);
    let len = len.or_else(|| r.dims.iter().filter(|d| d.axis == Some(Axis::Y)).map(|d| d.mm).next());
    let len = len.or_else(|| {
        r.dims.iter().filter(|d| !d.paren).map(|d| d.mm).fold(None, |m: Option<f64>, v| Some(m.map_or(v, |m| m.max(v))))
    });
    let len = need(len, "length")?;
    if ri >= ro {
        return Err("the inner radius must be less than the outer".into());
    }
    // Semicircular annulus in XZ opening upward, extruded along Y.
    let seg = 64;
    let mut pts = Vec::new();
    for k in 0..=seg {
        let t = PI + PI * k as f64 / seg as f64;
        pts.push([ro * t.cos(), ro + ro * t.sin()]);
    }
    for k in (0..=seg).rev() {
        let t = PI + PI * k as f64 / seg as f64;
        pts.push([ri * t.cos(), ro + ri * t.sin()]);
    }
    built("half_pipe", Body::of(Prim::Prism { pts, dir: Dir::Y, mid: 0.0, len }), Some(0))
}

/// Holes through a plate: corner holes inset, or a count on a grid.
fn plate_with_holes(r: &Reading) -> Outcome {
    let s = block_dims(r)?;
    let [x, y, t] = s;
    let hole = r.diameter(&["hole"], &["counterbore"]).or_else(|| r.diameter(&[], &["counterbore", "pitch", "bolt"]));
    // "four 8mm holes": a bare size that qualifies the holes is their diameter.
    let hole = hole.or_else(|| {
        r.dims
            .iter()
            .find(|d| d.role == Role::Bare && d.has("hole") && d.list.is_none() && d.axis.is_none())
            .map(|d| d.mm)
    });
    let d = need(hole, "hole diameter")?;
    let count = r.count("hole").unwrap_or(4);
    let inset = r.mm(Role::Inset, &[], &[]);
    let spacing = r.mm(Role::Spacing, &[], &[]);
    let cbore = r.diameter(&["counterbore"], &[]);
    let cdepth = r.mm(Role::Depth, &["counterbore"], &[]).or_else(|| r.mm(Role::Depth, &[], &[]));
    let centers: Vec<[f64; 2]> = match (count, inset, spacing) {
        (4, Some(i), _) => vec![
            [-x / 2.0 + i, -y / 2.0 + i],
            [x / 2.0 - i, -y / 2.0 + i],
            [x / 2.0 - i, y / 2.0 - i],
            [-x / 2.0 + i, y / 2.0 - i],
        ],
        (n, _, Some(p)) => (0..n).map(|k| [(k as f64 - (n as f64 - 1.0) / 2.0) * p, 0.0]).collect(),
        (1, _, _) => vec![[0.0, 0.0]],
        (n, _, None) => {
            // n holes on a line along the long side, evenly spaced.
            let p = x / n as f64;
            (0..n).map(|k| [(k as f64 - (n as f64 - 1.0) / 2.0) * p, 0.0]).collect()
        }
    };
    let mut body = Body::of(Prim::Box { c: [0.0, 0.0, t / 2.0], s, edges: None });
    for c in &centers {
        if c[0].abs() + d / 2.0 >= x / 2.0 || c[1].abs() + d / 2.0 >= y / 2.0 {
            return Err(format!("a {d} mm hole at ({:.1}, {:.1}) does not fit the {x} × {y} mm plate", c[0], c[1]));
        }
        match (cbore, cdepth) {
            (Some(cd), Some(depth)) if cd > d && depth < t => {
                body = body
                    .minus(Prim::Cyl {
                        c: [c[0], c[1], (t - depth) / 2.0],
                        r: d / 2.0,
                        len: t - depth,
                        dir: Dir::Z,
                        edge: None,
                    })
                    .minus(Prim::Cyl {
                        c: [c[0], c[1], t - depth / 2.0],
                        r: cd / 2.0,
                        len: depth,
                        dir: Dir::Z,
                        edge: None,
                    });
            }
            _ => body = body.minus(Prim::Cyl { c: [c[0], c[1], t / 2.0], r: d / 2.0, len: t, dir: Dir::Z, edge: None }),
        }
    }
    let n = centers.len() as u32;
    built("plate_with_holes", body, Some(n))
}

/// A disc with a centre bore and bolt holes on a pitch circle.
fn flange(r: &Reading) -> Outcome {
    let od = need(
        r.diameter(&["outer"], &[]).or_else(|| r.diameter(&[], &["bore", "hole", "pitch", "bolt", "inner"])),
        "outer diameter",
    )?;
    let t = need(r.mm(Role::Thickness, &[], &[]).or_else(|| r.mm(Role::Height, &[], &[])), "thickness")?;
    let bore = r.diameter(&["bore"], &["pitch"]).or_else(|| r.diameter(&["inner"], &[]));
    let pcd = r.diameter(&["pitch"], &[]).or_else(|| r.diameter(&["circle"], &[]));
    let hole = r.diameter(&["hole"], &["pitch", "bore"]).or_else(|| r.diameter(&["bolt"], &["pitch"]));
    let n = r.count("hole").or_else(|| r.count("bolt")).unwrap_or(if pcd.is_some() { 4 } else { 0 });
    let mut body = Body::of(Prim::Cyl { c: [0.0, 0.0, t / 2.0], r: od / 2.0, len: t, dir: Dir::Z, edge: None });
    let mut genus = 0;
    if let Some(b) = bore {
        body = body.minus(Prim::Cyl { c: [0.0, 0.0, t / 2.0], r: b / 2.0, len: t, dir: Dir::Z, edge: None });
        genus += 1;
    }
    if n > 0 {
        let pcd = need(pcd, "pitch circle diameter")?;
        let hole = need(hole, "bolt hole diameter")?;
        if pcd / 2.0 + hole / 2.0 >= od / 2.0 || bore.is_some_and(|b| pcd / 2.0 - hole / 2.0 <= b / 2.0) {
            return Err("the bolt holes do not fit between the bore and the rim".into());
        }
        for k in 0..n {
            let a = 2.0 * PI * f64::from(k) / f64::from(n);
            let c = [pcd / 2.0 * a.cos(), pcd / 2.0 * a.sin(), t / 2.0];
            body = body.minus(Prim::Cyl { c, r: hole / 2.0, len: t, dir: Dir::Z, edge: None });
        }
        genus += n;
    }
    built("flange", body, Some(genus))
}

fn hex_nut(r: &Reading) -> Outcome {
    let d = need(
        r.diameter(&["circumscribed"], &[]).or_else(|| r.diameter(&[], &["hole", "bore", "across", "inner"])),
        "circumscribed diameter",
    )?;
    let h = need(r.mm(Role::Height, &[], &[]).or_else(|| r.mm(Role::Thickness, &[], &[])), "height")?;
    let hole = need(
        r.diameter(&["hole"], &[]).or_else(|| r.diameter(&["bore"], &[])).or_else(|| r.diameter(&["inner"], &[])),
        "hole diameter",
    )?;
    let body = Body::of(Prim::Prism { pts: regular(6, d / 2.0, 0.0), dir: Dir::Z, mid: h / 2.0, len: h })
        .minus(Prim::Cyl { c: [0.0, 0.0, h / 2.0], r: hole / 2.0, len: h, dir: Dir::Z, edge: None });
    built("hex_nut", body, Some(1))
}

fn hex_bolt(r: &Reading) -> Outcome {
    let shaft = need(r.diameter(&[], &["head", "circumscribed", "across"]), "shaft diameter")?;
    let len = need(r.mm(Role::Length, &[], &["head"]), "shaft length")?;
    let head = need(r.diameter(&["circumscribed"], &[]).or_else(|| r.diameter(&["head"], &[])), "head diameter")?;
    let hh = need(
        r.mm(Role::Height, &["head"], &[])
            .or_else(|| r.mm(Role::Height, &[], &[]))
            .or_else(|| r.mm(Role::Thickness, &[], &[])),
        "head height",
    )?;
    let body = Body::of(Prim::Cyl { c: [0.0, 0.0, len / 2.0], r: shaft / 2.0, len, dir: Dir::Z, edge: None })
        .plus(Prim::Prism { pts: regular(6, head / 2.0, 0.0), dir: Dir::Z, mid: len + hh / 2.0, len: hh });
    built("hex_bolt", body, Some(0))
}

/// Coaxial cylinders stacked along Z (bushings, shoulder screws, flanged shafts), a bore
/// through them and bolt holes in the flange.
fn stacked(r: &Reading) -> Outcome {
    // Sections in the order the prompt gives them: a diameter followed by its length, or
    // by its span in Z ("20mm outer diameter (Z=3 to Z=33)").
    let mut sections: Vec<(f64, f64, bool)> = Vec::new();
    let mut spans: Vec<(f64, f64, f64, bool)> = Vec::new();
    let mut pending: Option<(f64, bool)> = None;
    let mut zs: Vec<f64> = Vec::new();
    let is_bore = |d: &super::measure::Dim| {
        d.has("bore") || d.has("hole") || d.has("pitch") || d.has("bolt") || d.has("circle") || d.clause_has("bore")
    };
    for d in r.dims.iter().filter(|d| !d.paren || d.coord.is_some()) {
        if d.coord == Some(Axis::Z) {
            zs.push(d.mm);
            if let (Some((dia, fl)), [a, b]) = (pending, zs.as_slice()) {
                spans.push((dia, a.min(*b), a.max(*b), fl));
                zs.clear();
            }
            continue;
        }
        if d.coord.is_some() {
            continue;
        }
        match d.role {
            Role::Diameter | Role::Radius if !is_bore(d) => {
                let dia = if d.role == Role::Radius { 2.0 * d.mm } else { d.mm };
                pending = Some((dia, d.clause_has("flange")));
                zs.clear();
            }
            Role::Length | Role::Height | Role::Thickness => {
                if let Some((dia, fl)) = pending {
                    sections.push((dia, d.mm, fl));
                }
            }
            _ => {}
        }
    }
    let mut body = Body::default();
    let mut flange: Option<(f64, f64, f64)> = None;
    let mut top = 0.0f64;
    if spans.len() >= 2 {
        // Each section from its own span; the spans must not overlap.
        spans.sort_by(|a, b| a.1.total_cmp(&b.1));
        for w in spans.windows(2) {
            if w[1].1 < w[0].2 - 1e-9 {
                return Err("two sections overlap in Z".into());
            }
        }
        for (dia, z0, z1, is_flange) in &spans {
            body.add.push(Prim::Cyl {
                c: [0.0, 0.0, (z0 + z1) / 2.0],
                r: dia / 2.0,
                len: z1 - z0,
                dir: Dir::Z,
                edge: None,
            });
            if *is_flange && flange.is_none() {
                flange = Some((*dia, *z0, z1 - z0));
            }
            top = top.max(*z1);
        }
        let sections: Vec<(f64, f64, bool)> = spans.iter().map(|s| (s.0, s.2 - s.1, s.3)).collect();
        return finish_stacked(r, body, &sections, flange, top);
    }
    if sections.len() < 2 {
        return Err("a stepped part needs at least two sections, each a diameter and a length".into());
    }
    // A flange given first sits at the bottom.
    let mut z = 0.0;
    for (dia, len, is_flange) in &sections {
        body.add.push(Prim::Cyl { c: [0.0, 0.0, z + len / 2.0], r: dia / 2.0, len: *len, dir: Dir::Z, edge: None });
        if *is_flange && flange.is_none() {
            flange = Some((*dia, z, *len));
        }
        z += len;
    }
    finish_stacked(r, body, &sections, flange, z)
}

/// The bore through a stacked part and the bolt holes through its flange.
fn finish_stacked(
    r: &Reading,
    mut body: Body,
    sections: &[(f64, f64, bool)],
    flange: Option<(f64, f64, f64)>,
    z: f64,
) -> Outcome {
    let mut genus = 0;
    if let Some(b) = r.diameter(&["bore"], &["pitch"]) {
        let min = sections.iter().map(|s| s.0).fold(f64::INFINITY, f64::min);
        if b >= min {
            return Err(format!("the bore ({b} mm) is wider than the part"));
        }
        body.cut.push(Prim::Cyl { c: [0.0, 0.0, z / 2.0], r: b / 2.0, len: z, dir: Dir::Z, edge: None });
        genus += 1;
    }
    let pcd = r.diameter(&["circle"], &[]).or_else(|| r.diameter(&["pitch"], &[]));
    if let (Some(pcd), Some((fd, fz, fl))) = (pcd, flange) {
        let hole = need(r.diameter(&["hole"], &["pitch", "circle"]), "bolt hole diameter")?;
        let n = r.count("hole").unwrap_or(4);
        let neighbour = sections.iter().filter(|s| !s.2).map(|s| s.0).fold(0.0, f64::max);
        if pcd / 2.0 + hole / 2.0 >= fd / 2.0 || pcd / 2.0 - hole / 2.0 <= neighbour / 2.0 {
            return Err("the bolt holes do not fit the flange".into());
        }
        for k in 0..n {
            let a = 2.0 * PI * f64::from(k) / f64::from(n);
            let c = [pcd / 2.0 * a.cos(), pcd / 2.0 * a.sin(), fz + fl / 2.0];
            body.cut.push(Prim::Cyl { c, r: hole / 2.0, len: fl, dir: Dir::Z, edge: None });
        }
        genus += n;
    }
    built("stacked_shaft", body, Some(genus))
}

fn gear(r: &Reading) -> Outcome {
    let teeth = r.count("teeth").or_else(|| r.count("vertices").map(|v| v / 2)).ok_or("no number of teeth given")?;
    if !(3..=400).contains(&teeth) {
        return Err(format!("{teeth} teeth is not a gear"));
    }
    let tip = need(r.diameter(&["tip"], &[]), "tip diameter")?;
    let root = need(r.diameter(&["root"], &[]), "root diameter")?;
    let t = need(r.mm(Role::Thickness, &[], &[]).or_else(|| r.mm(Role::Width, &["face"], &[])), "thickness")?;
    let bore = r.diameter(&["bore"], &[]);
    let hub = r.diameter(&["hub"], &[]);
    let mut body =
        Body::of(Prim::Prism { pts: star(teeth as usize, tip / 2.0, root / 2.0), dir: Dir::Z, mid: t / 2.0, len: t });
    let mut top = t;
    if let Some(hd) = hub {
        let total = r
            .dims
            .iter()
            .filter(|d| {
                d.coord == Some(Axis::Z) || (d.coord.is_none() && matches!(d.role, Role::Length | Role::Height))
            })
            .map(|d| d.mm)
            .fold(0.0, f64::max);
        if total > t && hd < root {
            body.add.push(Prim::Cyl {
                c: [0.0, 0.0, (t + total) / 2.0],
                r: hd / 2.0,
                len: total - t,
                dir: Dir::Z,
                edge: None,
            });
            top = total;
        }
    }
    let mut genus = 0;
    if let Some(b) = bore {
        if b >= root || hub.is_some_and(|h| top > t && b >= h) {
            return Err("the bore is wider than the gear".into());
        }
        body.cut.push(Prim::Cyl { c: [0.0, 0.0, top / 2.0], r: b / 2.0, len: top, dir: Dir::Z, edge: None });
        genus = 1;
    }
    built("gear", body, Some(genus))
}

/// A cross-section in YZ extruded along X.
fn section(template: &'static str, pts: Vec<[f64; 2]>, len: f64) -> Outcome {
    built(template, Body::of(Prim::Prism { pts, dir: Dir::X, mid: 0.0, len }), Some(0))
}

fn beam_common(r: &Reading) -> Result<(f64, f64, f64), String> {
    let len = need(r.mm(Role::Length, &[], &[]).or_else(|| along(r, Axis::X, &[])), "length")?;
    let h = need(r.mm(Role::Height, &[], &["web"]).or_else(|| along(r, Axis::Z, &[])), "height")?;
    let w = need(r.mm(Role::Width, &["flange"], &[]).or_else(|| r.mm(Role::Width, &[], &[])), "flange width")?;
    Ok((len, h, w))
}

fn i_beam(r: &Reading) -> Outcome {
    let (len, h, w) = beam_common(r)?;
    let tf = need(
        r.mm(Role::Thickness, &["flange"], &[]).or_else(|| r.mm(Role::Thickness, &[], &["web"])),
        "flange thickness",
    )?;
    let tw = need(r.mm(Role::Thickness, &["web"], &[]), "web thickness")?;
    if 2.0 * tf >= h || tw >= w {
        return Err("the flanges or the web do not fit the beam".into());
    }
    let (y, z, a) = (w / 2.0, h / 2.0, tw / 2.0);
    let pts = vec![
        [-y, -z],
        [y, -z],
        [y, -z + tf],
        [a, -z + tf],
        [a, z - tf],
        [y, z - tf],
        [y, z],
        [-y, z],
        [-y, z - tf],
        [-a, z - tf],
        [-a, -z + tf],
        [-y, -z + tf],
    ];
    section("i_beam", pts, len)
}

fn t_beam(r: &Reading) -> Outcome {
    let (len, h, w) = beam_common(r)?;
    let tw = need(r.mm(Role::Thickness, &["web"], &[]), "web thickness")?;
    let tf = need(
        r.mm(Role::Thickness, &["flange"], &[]).or_else(|| r.mm(Role::Thickness, &[], &["web"])),
        "flange thickness",
    )?;
    if tf >= h || tw >= w {
        return Err("the flange or the web do not fit the beam".into());
    }
    let (y, a) = (w / 2.0, tw / 2.0);
    let pts = vec![[-a, 0.0], [a, 0.0], [a, h - tf], [y, h - tf], [y, h], [-y, h], [-y, h - tf], [-a, h - tf]];
    section("t_beam", pts, len)
}

fn l_bracket(r: &Reading) -> Outcome {
    // Wall: tall (Z) × wide (X) × thick (Y); base: deep (Y) × wide (X) × thick (Z).
    let tall = need(r.mm(Role::Height, &[], &[]), "wall height")?;
    let wide = need(r.mm(Role::Width, &[], &[]), "width")?;
    let deep = need(r.mm(Role::Depth, &[], &[]).or_else(|| r.mm(Role::Length, &[], &[])), "base depth")?;
    let t = need(r.mm(Role::Thickness, &[], &[]), "thickness")?;
    let tb = r.dims.iter().filter(|d| d.role == Role::Thickness).nth(1).map_or(t, |d| d.mm);
    if t >= deep || tb >= tall {
        return Err("the bracket is thicker than it is long".into());
    }
    // The wall and the base share the corner: the wall at Y = 0…t, the base at Z = 0…tb.
    let pts = vec![[0.0, 0.0], [deep, 0.0], [deep, tb], [t, tb], [t, tall], [0.0, tall]];
    section("l_bracket", pts, wide)
}

fn channel(r: &Reading) -> Outcome {
    let len = need(along(r, Axis::X, &[Role::Length]), "length")?;
    let w = need(along(r, Axis::Y, &[Role::Width]), "width")?;
    let h = need(along(r, Axis::Z, &[Role::Height]), "height")?;
    let tw = need(r.mm(Role::Thickness, &["wall"], &[]).or_else(|| r.mm(Role::Thickness, &[], &[])), "wall thickness")?;
    let tb = r.mm(Role::Thickness, &["base"], &[]).unwrap_or(tw);
    if 2.0 * tw >= w || tb >= h {
        return Err("the walls do not fit the channel".into());
    }
    let (y, z) = (w / 2.0, h / 2.0);
    let pts =
        vec![[-y, -z], [y, -z], [y, z], [y - tw, z], [y - tw, -z + tb], [-y + tw, -z + tb], [-y + tw, z], [-y, z]];
    section("channel", pts, len)
}

fn rect_tube(r: &Reading) -> Outcome {
    let len = need(along(r, Axis::X, &[Role::Length]), "length")?;
    let w = need(along(r, Axis::Y, &[Role::Width]), "width")?;
    let h = need(along(r, Axis::Z, &[Role::Height]), "height")?;
    let t = need(r.mm(Role::Thickness, &[], &[]), "wall thickness")?;
    if 2.0 * t >= w.min(h) {
        return Err("the walls do not fit the tube".into());
    }
    let body = Body::of(Prim::Box { c: [0.0; 3], s: [len, w, h], edges: None }).minus(Prim::Box {
        c: [0.0; 3],
        s: [len, w - 2.0 * t, h - 2.0 * t],
        edges: None,
    });
    built("rect_tube", body, Some(1))
}
