//! CAD prompt suites and their references, for `bench cad` and the tests: the prompts
//! (`id<TAB>tier<TAB>prompt`), reference extents and volumes (`SUITE.refs.tsv`), the
//! reference programs (`SUITE.ref.py`: a CadQuery program per prompt, written from its
//! words apart from the synthesizer), plausible sizes of free-form objects
//! (`SUITE.sizes.tsv`); comparing a made part with a reference mesh after aligning their
//! bounding boxes; and a contact sheet of made parts.

use std::collections::BTreeMap;

use sw_geom::Mesh;
use sw_geom::raster::{Camera, Image, Renderer};

use crate::metrics::surface_chamfer;

/// One prompt of a suite.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Prompt {
    pub id: String,
    pub tier: String,
    pub text: String,
    /// The manner it is written in, where the suite says ("drawing", "inch" …).
    pub style: Option<String>,
    /// A prompt that must be refused: the words the refusal must quote (some of them).
    pub refuse_words: Option<String>,
}

/// A reference's extents (mm, per axis as placed) and volume (mm³).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reference {
    pub size: [f64; 3],
    pub volume: Option<f64>,
}

/// The sizes an object of a kind has: its largest extent, mm.
#[derive(Debug, Clone, PartialEq)]
pub struct Plausible {
    pub min: f64,
    pub max: f64,
    pub what: String,
}

fn rows(text: &str) -> impl Iterator<Item = Vec<&str>> {
    text.lines().filter(|l| !l.trim().is_empty() && !l.starts_with('#')).map(|l| l.split('\t').map(str::trim).collect())
}

/// A suite's prompts: `id<TAB>tier<TAB>prompt` per line, or, after a header line naming
/// its columns (`id  level  style  expected  description  refuse_words`), those columns.
pub fn parse_suite(text: &str) -> Vec<Prompt> {
    let header: Option<Vec<&str>> =
        text.lines().find(|l| l.starts_with("id\t")).map(|l| l.split('\t').map(str::trim).collect());
    let Some(h) = header else {
        return rows(text)
            .filter_map(|c| {
                let (id, tier, text) = (c.first()?, c.get(1)?, c.get(2..)?.join("\t"));
                Some(Prompt { id: (*id).into(), tier: (*tier).into(), text, ..Prompt::default() })
            })
            .collect();
    };
    let col = |names: &[&str]| h.iter().position(|x| names.contains(x));
    let (tier, style, expected, text_at, words) = (
        col(&["level", "tier"]),
        col(&["style"]),
        col(&["expected"]),
        col(&["description", "prompt", "text"]),
        col(&["refuse_words"]),
    );
    rows(text)
        .filter(|c| c.first() != Some(&"id"))
        .filter_map(|c| {
            let get = |i: Option<usize>| i.and_then(|i| c.get(i)).map(|s| (*s).to_string());
            let refuse = get(expected).is_some_and(|e| e == "refuse");
            Some(Prompt {
                id: get(Some(0))?,
                tier: get(tier).unwrap_or_default(),
                text: get(text_at)?,
                style: get(style),
                refuse_words: refuse.then(|| get(words).unwrap_or_default()),
            })
        })
        .collect()
}

/// Reference extents and volumes: `id  x  y  z  volume`, or `id  x,y,z  volume` (a row
/// whose size is `refuse` has no reference: the prompt must be refused).
pub fn parse_refs(text: &str) -> BTreeMap<String, Reference> {
    rows(text)
        .filter_map(|c| {
            let num = |s: Option<&&str>| s.and_then(|s| s.parse::<f64>().ok());
            let id = (*c.first()?).to_string();
            if let Some(packed) = c.get(1).filter(|s| s.contains(',')) {
                let v: Vec<f64> = packed.split(',').filter_map(|x| x.trim().parse().ok()).collect();
                let [a, b, d] = v.as_slice() else { return None };
                return Some((id, Reference { size: [*a, *b, *d], volume: num(c.get(2)) }));
            }
            Some((id, Reference { size: [num(c.get(1))?, num(c.get(2))?, num(c.get(3))?], volume: num(c.get(4)) }))
        })
        .collect()
}

pub fn parse_sizes(text: &str) -> BTreeMap<String, Plausible> {
    rows(text)
        .filter_map(|c| {
            let num = |i: usize| c.get(i).and_then(|s| s.parse::<f64>().ok());
            Some((
                (*c.first()?).to_string(),
                Plausible { min: num(1)?, max: num(2)?, what: c.get(3).map_or(String::new(), |s| (*s).to_string()) },
            ))
        })
        .collect()
}

/// The reference programs of a `.ref.py` file: each id's code, its prelude in front.
pub fn parse_programs(text: &str) -> BTreeMap<String, String> {
    let mut sections: Vec<(String, String)> = Vec::new();
    for line in text.lines() {
        if let Some(id) = line.strip_prefix("# ref: ") {
            sections.push((id.trim().to_string(), String::new()));
        } else if let Some((_, body)) = sections.last_mut() {
            body.push_str(line);
            body.push('\n');
        }
    }
    let prelude = sections.iter().find(|(id, _)| id == "_prelude").map(|(_, b)| b.clone()).unwrap_or_default();
    sections
        .into_iter()
        .filter(|(id, _)| id != "_prelude")
        .map(|(id, body)| (id, format!("{prelude}\n{body}")))
        .collect()
}

/// `mesh` moved so that its bounding box lines up with `reference`'s: its axes put in the
/// order (a rotation by quarter turns) whose extents best match, then its centre on the
/// reference's. Made parts and references may differ in where a prompt that does not
/// say put the part, not in its shape.
pub fn align(mesh: &Mesh, reference: &Mesh) -> Mesh {
    let (a, b) = (mesh.bounds(), reference.bounds());
    if a.is_empty() || b.is_empty() {
        return mesh.clone();
    }
    let (sa, sb) = (a.size(), b.size());
    // Even permutations are rotations; the odd ones get one axis flipped (still a rotation).
    let perms: [([usize; 3], bool); 6] = [
        ([0, 1, 2], false),
        ([1, 2, 0], false),
        ([2, 0, 1], false),
        ([1, 0, 2], true),
        ([0, 2, 1], true),
        ([2, 1, 0], true),
    ];
    let score = |p: &[usize; 3]| (0..3).map(|k| ((sa[p[k]] - sb[k]) / sb[k].max(1e-9)).abs()).fold(0.0, f64::max);
    let (perm, flip) =
        perms.iter().min_by(|x, y| score(&x.0).total_cmp(&score(&y.0))).copied().unwrap_or(([0, 1, 2], false));
    let (ca, cb) = (a.center(), b.center());
    let mut out = mesh.clone();
    for v in &mut out.vertices {
        let p = [f64::from(v[0]) - ca[0], f64::from(v[1]) - ca[1], f64::from(v[2]) - ca[2]];
        let mut q = [p[perm[0]], p[perm[1]], p[perm[2]]];
        if flip {
            q[0] = -q[0];
        }
        *v = [(q[0] + cb[0]) as f32, (q[1] + cb[1]) as f32, (q[2] + cb[2]) as f32];
    }
    if flip {
        for t in &mut out.triangles {
            t.swap(1, 2);
        }
    }
    out
}

/// Chamfer distance (mm) between a made part and a reference after [`align`], and the
/// same as a share of the reference's bounding-box diagonal.
pub fn chamfer_aligned(mesh: &Mesh, reference: &Mesh, samples: usize) -> Option<(f64, f64)> {
    let aligned = align(mesh, reference);
    let d = surface_chamfer(&aligned, reference, samples)?;
    let s = reference.bounds().size();
    let diag = (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]).sqrt().max(1e-9);
    Some((d, d / diag))
}

/// One tile of a contact sheet: a label, the part (or none, when it was not made) and a
/// caption.
#[derive(Debug)]
pub struct Tile<'a> {
    pub label: String,
    pub mesh: Option<&'a Mesh>,
    pub caption: String,
    /// The view's azimuth, radians (catalog objects face +Y: about 1.15 shows their front).
    pub azimuth: f64,
}

/// A grid of shaded pictures, each with its label and caption under it.
pub fn contact_sheet(tiles: &[Tile<'_>], columns: u32, size: u32) -> Image {
    let columns = columns.max(1);
    let rows = (tiles.len() as u32).div_ceil(columns).max(1);
    let caption_h = 26;
    let mut sheet = Image::new(columns * size, rows * (size + caption_h), [255, 255, 255]);
    for (i, t) in tiles.iter().enumerate() {
        let (col, row) = (i as u32 % columns, i as u32 / columns);
        let (x, y) = (col * size, row * (size + caption_h));
        let tile = match t.mesh.filter(|m| !m.bounds().is_empty()) {
            Some(m) => {
                // Flat things (a board, a guitar lying down) are seen from higher up.
                let ext = m.bounds().size();
                let flat = ext[2] < 0.2 * ext[0].max(ext[1]);
                let camera = Camera::framing(&m.bounds(), t.azimuth, if flat { 0.95 } else { 0.5 });
                let mut r = Renderer::new(size, size, &camera, [240, 242, 246]);
                r.draw_mesh(m, &sw_geom::Pose::default(), [0.55, 0.62, 0.72, 1.0]);
                r.finish()
            }
            None => Image::new(size, size, [250, 228, 228]),
        };
        sheet.blit(&tile, x, y);
        sheet.text(x + 4, y + size + 3, &t.label, 1, [20, 20, 20]);
        sheet.text(x + 4, y + size + 14, &t.caption, 1, [90, 90, 90]);
    }
    sheet
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn programs_get_their_prelude_and_suites_their_columns() {
        let p = parse_programs(
            "# head\n# ref: _prelude\nimport cadquery as cq\n# ref: A\nresult = 1\n# ref: B\nresult = 2\n",
        );
        assert_eq!(p.len(), 2);
        assert!(p["A"].starts_with("import cadquery as cq\n") && p["A"].ends_with("result = 1\n"));
        let s = parse_suite("# c\nX_1\tT1\tA block 1mm long.\n");
        assert_eq!(
            s,
            vec![Prompt { id: "X_1".into(), tier: "T1".into(), text: "A block 1mm long.".into(), ..Prompt::default() }]
        );
        let r = parse_refs("X_1\t1\t2\t3\t6.5\t-\n");
        assert_eq!(r["X_1"], Reference { size: [1.0, 2.0, 3.0], volume: Some(6.5) });
        // A corpus with a header: its columns by name, refusals with their words; references
        // with packed extents, and none for a refusal.
        let s = parse_suite(
            "# c\nid\tlevel\tstyle\texpected\tdescription\trefuse_words\nW_1\tT1\tdrawing\tmake\tTUBE 50 OD\t\n\
             W_2\tT2\tcontradict\trefuse\tA 50 mm cube, 50 x 40\t50 x 40\n",
        );
        assert_eq!(s.len(), 2);
        assert_eq!(
            (s[0].tier.as_str(), s[0].style.as_deref(), s[0].refuse_words.as_deref()),
            ("T1", Some("drawing"), None)
        );
        assert_eq!((s[1].text.as_str(), s[1].refuse_words.as_deref()), ("A 50 mm cube, 50 x 40", Some("50 x 40")));
        let r = parse_refs("id\tbbox_mm\tvolume_mm3\nW_1\t100.0,50.0,50.0\t7.5\nW_2\trefuse\trefuse\n");
        assert_eq!(r.len(), 1);
        assert_eq!(r["W_1"], Reference { size: [100.0, 50.0, 50.0], volume: Some(7.5) });
    }

    #[test]
    fn a_part_turned_and_moved_aligns_with_its_reference() {
        let reference = sw_geom::box_mesh([10.0, 2.0, 4.0]);
        let mut turned = sw_geom::box_mesh([4.0, 10.0, 2.0]);
        for v in &mut turned.vertices {
            v[0] += 30.0;
        }
        let (d, rel) = chamfer_aligned(&turned, &reference, 1500).unwrap();
        assert!(d < 1e-6 && rel < 1e-6, "{d} {rel}");
        let far = surface_chamfer(&turned, &reference, 1500).unwrap();
        assert!(far > 10.0, "{far}");
    }
}
