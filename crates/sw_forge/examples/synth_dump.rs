#![allow(clippy::print_stdout, clippy::print_stderr)]
//! Prints what the offline synthesizer makes of every prompt of a suite file.
//! `cargo run -p sw_forge --example synth_dump -- bench/cad/standard_100.tsv [--code]`
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let Some(path) = args.get(1) else {
        eprintln!("usage: synth_dump SUITE.tsv [--code]");
        std::process::exit(2);
    };
    let code = args.iter().any(|a| a == "--code");
    // Write each part's code to DIR/ID.py.
    let emit = args.iter().position(|a| a == "--emit").and_then(|i| args.get(i + 1)).cloned();
    // Reference extents and volumes, to compare with (a development aid: `bench cad` runs the code).
    let refs: std::collections::BTreeMap<String, ([f64; 3], Option<f64>)> = args
        .iter()
        .position(|a| a == "--refs")
        .and_then(|i| args.get(i + 1))
        .and_then(|p| std::fs::read_to_string(p).ok())
        .map(|t| {
            t.lines()
                .filter(|l| !l.starts_with('#'))
                .filter_map(|l| {
                    let c: Vec<&str> = l.split('\t').collect();
                    let f = |i: usize| c.get(i).and_then(|x| x.parse::<f64>().ok());
                    Some((c.first()?.to_string(), ([f(1)?, f(2)?, f(3)?], f(4))))
                })
                .collect()
        })
        .unwrap_or_default();
    let only = args.iter().position(|a| a == "--only").and_then(|i| args.get(i + 1)).cloned();
    let text = match std::fs::read_to_string(path) {
        Ok(t) => t,
        Err(e) => {
            eprintln!("{path}: {e}");
            std::process::exit(2);
        }
    };
    for line in text.lines().filter(|l| !l.starts_with('#') && !l.trim().is_empty()) {
        let cols: Vec<&str> = line.splitn(3, '\t').collect();
        let (id, prompt) = (cols[0], cols.get(2).copied().unwrap_or(""));
        if only.as_deref().is_some_and(|o| o != id) {
            continue;
        }
        if only.is_some() {
            let d = sw_forge::synth::doc::Doc::new(prompt);
            for x in &d.dims {
                println!(
                    "  dim {} {:?} quals={:?} axis={:?} paren={} list={:?}",
                    x.mm, x.role, x.quals, x.axis, x.paren, x.list
                );
            }
            for x in &d.ranges {
                println!("  range {:?} {}..{}", x.axis, x.a, x.b);
            }
            for x in &d.coords {
                println!("  coord {:?} {}", x.axis, x.v);
            }
            for x in &d.tuples {
                println!("  tuple {:?}", x.vals);
            }
            let t = sw_forge::synth::takeoff::Takeoff::read(&d);
            for (k, th) in t.things.iter().enumerate() {
                println!(
                    "  takeoff thing {k} {} {:?} count={:?} place={} dims={:?} solid={:?}",
                    th.noun,
                    th.kind,
                    th.count,
                    th.place,
                    th.dims.iter().map(|k| d.dims[*k].mm).collect::<Vec<_>>(),
                    t.solid(k)
                );
            }
            let (_, els) = sw_forge::synth::mention::read(&d);
            for e in &els {
                println!(
                    "  element {} {:?} mods={:?} shape={:?} count={:?} dims={:?} ranges={:?} coords={:?} tuples={:?} angles={:?} teeth={:?}",
                    e.noun,
                    e.kind,
                    e.mods,
                    e.shape,
                    e.count,
                    e.dims.iter().map(|k| d.dims[*k].mm).collect::<Vec<_>>(),
                    e.ranges,
                    e.coords,
                    e.tuples,
                    e.angles,
                    e.teeth
                );
            }
        }
        match sw_forge::synth::synthesize(prompt) {
            Ok(s) => {
                let verdict = refs.get(id).map_or(String::new(), |(size, vol)| {
                    let (mut a, mut b) = (s.size, *size);
                    a.sort_by(f64::total_cmp);
                    b.sort_by(f64::total_cmp);
                    let be = a.iter().zip(&b).map(|(x, y)| (x - y).abs() / y).fold(0.0, f64::max);
                    let ve = match (s.volume, vol) {
                        (Some(x), Some(y)) => Some((x - y).abs() / y),
                        _ => None,
                    };
                    let ok = be <= 0.01 && ve.is_none_or(|v| v <= 0.02);
                    format!(
                        "\t{} bbox {:.2}% vol {}",
                        if ok { "ok" } else { "BAD" },
                        100.0 * be,
                        ve.map_or("?".into(), |v| format!("{:.2}%", 100.0 * v))
                    )
                });
                println!(
                    "{id}\t{}\t{:.3} x {:.3} x {:.3}\t{}\tgenus {:?}{verdict}",
                    s.template,
                    s.size[0],
                    s.size[1],
                    s.size[2],
                    s.volume.map_or("-".into(), |v| format!("{v:.2}")),
                    s.genus
                );
                if code {
                    println!("{}", s.code);
                }
                if let Some(dir) = &emit {
                    let _ = std::fs::create_dir_all(dir);
                    let _ = std::fs::write(format!("{dir}/{id}.py"), &s.code);
                }
            }
            Err(e) => match sw_forge::freeform::read(prompt) {
                Ok(sw_forge::freeform::Freeform::Catalog { category, asset }) => {
                    let b = asset.bounds().size();
                    println!("{id}\tcatalog:{category}\t{:.0} x {:.0} x {:.0} mm", b[0] * 1e3, b[1] * 1e3, b[2] * 1e3);
                }
                Ok(sw_forge::freeform::Freeform::Composed { synthesis: s, .. }) => {
                    println!("{id}\t{}\t{:.0} x {:.0} x {:.0} mm", s.template, s.size[0], s.size[1], s.size[2]);
                    if let Some(dir) = &emit {
                        let _ = std::fs::create_dir_all(dir);
                        let _ = std::fs::write(format!("{dir}/{id}.py"), &s.code);
                    }
                }
                Err(f) => println!("{id}\tERROR {e} / {f}"),
            },
        }
    }
}
