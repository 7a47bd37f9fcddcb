//! The task reader alone on real task wordings from public robot-learning suites
//! (`bench/demos/task_wordings_dev.tsv`): goals over noun phrases, or a refusal that names
//! the words. No scene and no physics, so it runs in CI. Prints every miss and the score;
//! fails below the floor the reader has reached.

use std::path::Path;

/// Share of the suite the reader must read exactly (raised as the reader improves).
const FLOOR: f64 = 0.95;

#[test]
fn task_wordings_from_public_suites() {
    // SW_TASK_WORDINGS scores another file of the same form (a held-out set), floor aside.
    let other = std::env::var_os("SW_TASK_WORDINGS");
    let path = match &other {
        Some(p) => Path::new(p).to_path_buf(),
        None => Path::new(env!("CARGO_MANIFEST_DIR")).join("../../bench/demos/task_wordings_dev.tsv"),
    };
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let (mut right, mut total) = (0usize, 0usize);
    let mut misses = Vec::new();
    for line in text.lines().filter(|l| !l.trim().is_empty() && !l.starts_with('#')) {
        let cols: Vec<&str> = line.split('\t').collect();
        assert!(cols.len() == 3, "a row is instruction, expected, source: {line}");
        let (instruction, expected) = (cols[0], cols[1].trim());
        total += 1;
        let got = sw_task::read_goals(instruction);
        let ok = match (expected.strip_prefix("refuse:"), &got) {
            (Some(word), Err(e)) => e.to_string().to_lowercase().contains(&word.trim().to_lowercase()),
            (None, Ok(goals)) => goals.join(" ; ") == expected,
            _ => false,
        };
        if ok {
            right += 1;
        } else {
            let got = match got {
                Ok(g) => g.join(" ; "),
                Err(e) => format!("refused: {e}"),
            };
            misses.push(format!("  {instruction}\n      want {expected}\n      got  {got}"));
        }
    }
    for m in &misses {
        println!("{m}");
    }
    let share = right as f64 / total as f64;
    println!("task wordings read right: {right} / {total} ({:.0} %)", 100.0 * share);
    if other.is_some() {
        return;
    }
    assert!(total >= 80, "the suite holds {total} wordings");
    assert!(share >= FLOOR, "{right} / {total} read right, below the floor {FLOOR}");
}
