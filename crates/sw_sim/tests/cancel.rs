//! Verification stops when its job is cancelled: inside `sw_geom::cancel::scope`, a set
//! flag ends the settle at its next check, and the unfinished verification fails saying
//! so — the thread does not step on for the rest of the settle.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

/// A scene slow to settle: `n` free boxes on a floor, apart.
fn many_boxes(n: usize) -> String {
    let side = (n as f64).sqrt().ceil() as usize;
    let mut bodies = String::new();
    for i in 0..n {
        let (x, y) = ((i % side) as f64 * 0.3, (i / side) as f64 * 0.3);
        bodies.push_str(&format!(
            "<body name=\"box_{i}\" pos=\"{x} {y} 0.1\"><freejoint/><geom type=\"box\" size=\"0.1 0.1 0.1\" mass=\"1\"/></body>\n"
        ));
    }
    format!(
        "<mujoco><option timestep=\"0.002\"/><worldbody><geom name=\"floor\" type=\"plane\" size=\"50 50 0.1\"/>\n{bodies}</worldbody></mujoco>"
    )
}

#[test]
fn a_cancelled_settle_stops_at_its_next_check() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("scene.xml");
    std::fs::write(&path, many_boxes(400)).unwrap();
    let opts = sw_sim::VerifyOptions::default();

    // Uncancelled, for scale: the whole 2 s settle.
    let t0 = Instant::now();
    let full = sw_sim::verify_file(&path, &opts);
    let whole = t0.elapsed();
    assert!(full.compiled && full.settle.is_some(), "{:?}", full.failures);

    // Cancelled a little into the settle: it ends within a fraction of that.
    let flag = Arc::new(AtomicBool::new(false));
    let setter = {
        let flag = Arc::clone(&flag);
        let after = whole / 5;
        std::thread::spawn(move || {
            std::thread::sleep(after);
            flag.store(true, Ordering::Relaxed);
        })
    };
    let t0 = Instant::now();
    let v = sw_geom::cancel::scope(&flag, || sw_sim::verify_file(&path, &opts));
    let took = t0.elapsed();
    setter.join().unwrap();
    assert!(!v.passed, "an unfinished verification does not pass");
    assert!(v.failures.iter().any(|f| f.contains("cancelled")), "{:?}", v.failures);
    assert!(v.settle.is_none(), "no settle result from an unfinished settle");
    assert!(took < whole / 2 + Duration::from_millis(200), "cancelled run took {took:?}; the whole one {whole:?}");

    // Outside any scope the flag means nothing.
    let again = sw_sim::verify_file(&path, &opts);
    assert!(again.settle.is_some());
}
