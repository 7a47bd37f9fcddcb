#![allow(clippy::print_stdout, clippy::print_stderr)]
//! Prints what the template synthesizer makes of every prompt of a suite file.
//! `cargo run -p sw_forge --example synth_dump -- bench/cad/standard_100.tsv [--code]`
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let Some(path) = args.get(1) else {
        eprintln!("usage: synth_dump SUITE.tsv [--code]");
        std::process::exit(2);
    };
    let code = args.iter().any(|a| a == "--code");
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
            let r = sw_forge::synth::measure::read(prompt);
            for d in &r.dims {
                println!(
                    "  {:?} {:?} mods={:?} axis={:?} coord={:?} paren={} list={:?}",
                    d.mm, d.role, d.mods, d.axis, d.coord, d.paren, d.list
                );
            }
            println!("  counts {:?}", r.counts);
        }
        match sw_forge::synth::synthesize(prompt) {
            Ok(s) => {
                println!(
                    "{id}\t{}\t{:.3} x {:.3} x {:.3}\t{}\tgenus {:?}",
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
            }
            Err(e) => println!("{id}\tERROR {e}"),
        }
    }
}
