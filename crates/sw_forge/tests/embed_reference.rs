#![allow(clippy::unwrap_used, clippy::expect_used)]
//! The embedder against an independent reference: `bench/forge/minilm_reference.py`, a
//! NumPy forward pass of all-MiniLM-L6-v2 over the same weights, tokenised by HuggingFace
//! `tokenizers` from the same `tokenizer.json`. For every sentence our WordPiece must give
//! exactly the reference's token ids and our candle vector must point the same way
//! (cosine ≥ 0.9999). Needs `scripts/setup.sh --tests` (the model in `.cache/minilm` and
//! the reference's venv `.cache/minilm-ref-venv`); fails, never skips, without them.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use sw_forge::embed::{DIM, MiniLm, default_model_dir};
use sw_forge::runner::checkout_cache;

const MIN_COSINE: f64 = 0.9999;

/// A long description: well past 128 word pieces, and (repeated) past 256.
const LONG: &str = "A freestanding industrial shelving unit made of powder-coated grey steel, \
    1.8 m tall, 0.9 m wide and 0.45 m deep, with five adjustable shelves on 25 mm hole \
    spacing, each rated for 120 kg of evenly distributed load; the uprights are \
    roll-formed 1.5 mm sheet with bolted diagonal braces at the back, levelling feet with \
    M10 threads, and a label holder on every front beam. It is meant for a workshop or a \
    warehouse aisle, holds plastic bins, cardboard boxes and small motors, and should be \
    anchored to the wall when the top shelf carries more than 40 kg. Assembly takes two \
    people about thirty minutes with a rubber mallet and a 13 mm spanner.";

fn sentences() -> Vec<String> {
    let mut s: Vec<String> = [
        // Short labels.
        "chair",
        "shelving unit",
        "storage rack",
        "self-driving car",
        "traffic cone",
        "office desk",
        "a",
        "x",
        "Table",
        "TABLE LAMP",
        "KiTcHeN CaBiNeT",
        "fire extinguisher",
        "conveyor belt",
        "robot arm base",
        "pallet",
        // Dimensions, digits and units.
        "A flat washer: outer diameter 20mm, inner diameter 10.5mm, thickness 2mm",
        "M8x1.25 hex bolt, 40 mm long",
        "plate 100x50x5 with 4 holes Ø6.5 on a 80×30 pattern",
        "spur gear, module 2, 24 teeth, 10mm bore",
        "a 3/4\" pipe flange (PN16), 2.5kg",
        "box 0.5 m × 0.3 m × 0.2 m",
        "pipe of 1,250.75 mm length at 20°C",
        "±0.05mm tolerance, 12µm finish",
        "1234567890 9876543210",
        "3.14159 2.71828 1.41421",
        "version 2.0-beta_3",
        // Punctuation.
        "hello, world!",
        "what's this? (a bracket) [square] {curly} <angle>",
        "dash-separated--words---here",
        "e-mail: someone@example.com; url: https://example.org/path?x=1&y=2",
        "quotes “curly” ‘single’ «guillemets» — em dash … ellipsis",
        "~!@#$%^&*()_+`-={}|[]\\:\";'<>?,./",
        "semi;colon:colon,comma.period",
        "#hashtag @mention $100 50% 3+4=7",
        // Accents and other scripts.
        "Café crème brûlée",
        "naïve façade über Straße",
        "São Paulo, Kraków, Łódź, Øresund, Ærø",
        "Čeština, Slovenščina, Hrvatski: čćžšđ",
        "Ελληνικά γράμματα",
        "русский стол и стул",
        "椅子と机",
        "中文的桌子",
        "한국어 의자",
        "עברית וערבית العربية",
        "हिन्दी कुर्सी",
        "emoji chair 🪑 and rocket 🚀",
        "ﬁne ligature and ＦＵＬＬＷＩＤＴＨ",
        "soft\u{ad}hyphen and zero\u{200b}width",
        "tab\tseparated\twords",
        "vertical\u{b}tab, form\u{c}feed, next\u{85}line, line\u{2028}separator, no\u{a0}break",
        "",
        "   ",
        "İstanbul DİNAMO",
        // Mixed case and run-together words.
        "CamelCaseIdentifier snake_case_name",
        "HTTPServer XMLHttpRequest",
        "supercalifragilisticexpialidocious",
        "antidisestablishmentarianism pneumonoultramicroscopicsilicovolcanoconiosis",
        // Descriptions.
        "A wooden bookshelf with three shelves, painted white.",
        "An aluminium extrusion profile, 40 by 40 millimetres, slot 8.",
        "The quick brown fox jumps over the lazy dog.",
    ]
    .iter()
    .map(|t| t.to_string())
    .collect();
    s.push(LONG.to_string());
    s.push(format!("{LONG} {LONG}"));
    s.push("word ".repeat(300).trim_end().to_string());
    s.push(format!("a{}", "b".repeat(120)));
    s
}

struct Reference {
    text: String,
    ids: Vec<u32>,
    vector: Vec<f64>,
}

fn reference(texts: &[String], model_dir: &Path) -> Vec<Reference> {
    let python = checkout_cache().join("minilm-ref-venv/bin/python");
    assert!(
        python.is_file(),
        "the reference embedder's venv is missing: {} (run scripts/setup.sh --tests)",
        python.display()
    );
    let script = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../bench/forge/minilm_reference.py");
    let mut child = Command::new(&python)
        .arg(&script)
        .arg(model_dir)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap_or_else(|e| panic!("{} {}: {e} (run scripts/setup.sh --tests)", python.display(), script.display()));
    let mut input = String::new();
    for t in texts {
        assert!(!t.contains('\n'), "one sentence a line: {t:?}");
        input.push_str(t);
        input.push('\n');
    }
    // Written from a thread, so a large input cannot deadlock against the output.
    let mut stdin = child.stdin.take().unwrap();
    let writer = std::thread::spawn(move || stdin.write_all(input.as_bytes()));
    let out = child.wait_with_output().unwrap();
    writer.join().unwrap().unwrap();
    assert!(
        out.status.success(),
        "the reference failed ({}; run scripts/setup.sh --tests):\n{}",
        out.status,
        String::from_utf8_lossy(&out.stderr)
    );
    let rows: Vec<Reference> = String::from_utf8(out.stdout)
        .unwrap()
        .lines()
        .map(|line| {
            let v: serde_json::Value = serde_json::from_str(line).unwrap();
            Reference {
                text: v["text"].as_str().unwrap().to_string(),
                ids: v["ids"].as_array().unwrap().iter().map(|x| x.as_u64().unwrap() as u32).collect(),
                vector: v["vector"].as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect(),
            }
        })
        .collect();
    assert_eq!(rows.len(), texts.len(), "one reference row per sentence");
    rows
}

fn cosine(a: &[f32], b: &[f64]) -> f64 {
    let dot: f64 = a.iter().zip(b).map(|(x, y)| f64::from(*x) * y).sum();
    let na: f64 = a.iter().map(|x| f64::from(*x).powi(2)).sum::<f64>().sqrt();
    let nb: f64 = b.iter().map(|y| y * y).sum::<f64>().sqrt();
    dot / (na * nb)
}

#[test]
fn tokens_and_vectors_match_an_independent_numpy_reference() {
    let dir = default_model_dir();
    let model = MiniLm::load(&dir).unwrap_or_else(|e| panic!("{e} (run scripts/setup.sh --tests)"));
    let texts = sentences();
    assert!(texts.len() >= 60, "{} sentences", texts.len());
    let refs = reference(&texts, &dir);
    let refs_text: Vec<&str> = texts.iter().map(String::as_str).collect();
    let ours = model.embed(&refs_text).unwrap();

    let mut problems = Vec::new();
    let (mut min_cos, mut max_cos) = (f64::INFINITY, f64::NEG_INFINITY);
    let mut same_ids = 0;
    let mut longest = 0;
    for ((text, r), v) in texts.iter().zip(&refs).zip(&ours) {
        assert_eq!(&r.text, text, "the reference answered out of order");
        assert_eq!(r.vector.len(), DIM);
        let ids = model.tokenizer().encode(text);
        longest = longest.max(r.ids.len());
        if ids == r.ids {
            same_ids += 1;
        } else {
            problems.push(format!("{text:?}: token ids differ\n  ours      {ids:?}\n  reference {:?}", r.ids));
        }
        let c = cosine(v, &r.vector);
        min_cos = min_cos.min(c);
        max_cos = max_cos.max(c);
        if c.is_nan() || c < MIN_COSINE {
            problems.push(format!("{text:?}: cosine {c:.6} < {MIN_COSINE}"));
        }
    }
    println!(
        "embed reference: {} sentences, token ids identical for {same_ids}, cosine min {min_cos:.9} max {max_cos:.9} \
         (1 - min = {:.1e}), longest {longest} tokens",
        texts.len(),
        1.0 - min_cos
    );
    // The long inputs really are long: past 128 tokens, up to the 256-token limit.
    assert!(longest > 128, "no sentence is longer than 128 tokens ({longest})");
    assert!(problems.is_empty(), "{} mismatches:\n{}", problems.len(), problems.join("\n"));
}
