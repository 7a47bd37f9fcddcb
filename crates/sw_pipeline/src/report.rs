//! Summaries for progress lines, the repair of scenes that fail verification, and the
//! final report.

use std::collections::BTreeSet;

use sw_plan::{LaidOutScene, LeftOut, Report, ScenePlan, SceneSummary, Status, Support, Verification, Warning};

pub(crate) fn plan_summary(plan: &ScenePlan) -> String {
    let s = plan.room.size;
    let robots: u32 = plan.robots.iter().map(|r| r.count).sum();
    let mut out = format!(
        "{} {} × {} × {} m · {} object{} in {} group{} · {} robot{}",
        plan.room.kind.name().replace('_', " "),
        trim(s.width),
        trim(s.depth),
        trim(s.height),
        plan.object_count(),
        if plan.object_count() == 1 { "" } else { "s" },
        plan.objects.len(),
        if plan.objects.len() == 1 { "" } else { "s" },
        robots,
        if robots == 1 { "" } else { "s" },
    );
    let u = &plan.understanding;
    if !u.approximated.is_empty() {
        out.push_str(&format!(" · {} approximated", u.approximated.len()));
    }
    if !u.not_understood.is_empty() {
        out.push_str(&format!(" · {} not understood", u.not_understood.len()));
    }
    out
}

pub(crate) fn layout_summary(l: &LaidOutScene) -> String {
    let s = l.room.size;
    let mut out = format!(
        "{} and {} placed in {} × {} m",
        count(l.objects.len(), "object", "objects"),
        count(l.robots.len(), "robot", "robots"),
        trim(s.width),
        trim(s.depth)
    );
    let left: u32 = l.left_out.iter().map(|x| x.requested - x.placed).sum();
    if left > 0 {
        out.push_str(&format!(" · {left} left out"));
    }
    if !l.warnings.is_empty() {
        out.push_str(&format!(" · {}", count(l.warnings.len(), "warning", "warnings")));
    }
    out
}

pub(crate) fn verify_summary(v: &Verification) -> String {
    if !v.compiled {
        return "MuJoCo rejected the scene".into();
    }
    let contacts = v.initial_contacts.as_ref().map_or(0, |c| c.deep.len());
    let drift = v.settle.as_ref().map_or(0.0, |s| s.max_displacement_m);
    format!(
        "{}: {} · {} contact{} > 1 mm · largest settle drift {:.2} mm",
        v.engine,
        if v.passed { "passed" } else { "FAILED" },
        contacts,
        if contacts == 1 { "" } else { "s" },
        drift * 1000.0
    )
}

/// The bodies whose contacts and motion injected anomalies explain: each corrupted
/// object, the object it was pushed into, and everything resting on either.
pub(crate) fn anomaly_bodies(layout: &LaidOutScene) -> Vec<String> {
    let mut names: BTreeSet<String> = BTreeSet::new();
    for a in &layout.anomalies {
        names.insert(a.object.clone());
        if let Some(w) = &a.with {
            names.insert(w.clone());
        }
    }
    loop {
        let before = names.len();
        for o in &layout.objects {
            if let Support::Object { object, .. } = &o.support
                && names.contains(object)
            {
                names.insert(o.name.clone());
            }
        }
        if names.len() == before {
            break;
        }
    }
    names.into_iter().collect()
}

/// Stacked groups whose columns sank or fell in the settle: for each, how many layers of
/// its columns stayed (the lowest layer that moved, counted from 0 at the floor). A tall
/// column of light things sinks into MuJoCo's soft contacts by roughly the square of its
/// height, its top by more than verification allows; a column that short would not.
pub(crate) fn sunk_columns(
    plan: &ScenePlan,
    layout: &LaidOutScene,
    v: &Verification,
) -> std::collections::BTreeMap<String, usize> {
    let mut caps = std::collections::BTreeMap::new();
    let Some(settle) = &v.settle else { return caps };
    let object = |n: &str| layout.objects.iter().find(|o| o.name == n);
    for m in &settle.moved {
        let Some(o) = object(&m.body).filter(|o| crate::loads::is_stacked(plan, &o.group)) else { continue };
        // Its layer: how many of its group it stands on, one on another, down to the floor.
        let mut layer = 0;
        let mut at = o;
        while let Support::Object { object: below, .. } = &at.support
            && let Some(b) = object(below).filter(|b| b.group == o.group)
            && layer < layout.objects.len()
        {
            layer += 1;
            at = b;
        }
        if layer > 0 {
            let cap = caps.entry(o.group.clone()).or_insert(layer);
            *cap = (*cap).min(layer);
        }
    }
    caps
}

/// Removes the objects a failed verification points at (and whatever rests on them).
/// Robots are never removed. Returns (name, reason) for each removed object.
pub(crate) fn repair(layout: &mut LaidOutScene, v: &Verification, expected: &[String]) -> Vec<(String, String)> {
    let is_object = |n: &str| layout.objects.iter().any(|o| o.name == n);
    let movable = |n: &str| layout.objects.iter().any(|o| o.name == n && o.movable);
    let mut remove: Vec<(String, String)> = Vec::new();
    if let Some(c) = &v.initial_contacts {
        for d in &c.deep {
            let (a, b) = (d.body1.as_str(), d.body2.as_str());
            if expected.iter().any(|e| e == a || e == b) {
                continue;
            }
            let pick = match (is_object(a), is_object(b)) {
                (true, true) => {
                    if movable(b) && !movable(a) {
                        b
                    } else if movable(a) && !movable(b) {
                        a
                    } else {
                        // The later one in placement order.
                        let ia = layout.objects.iter().position(|o| o.name == a).unwrap_or(0);
                        let ib = layout.objects.iter().position(|o| o.name == b).unwrap_or(0);
                        if ia > ib { a } else { b }
                    }
                }
                (true, false) => a,
                (false, true) => b,
                (false, false) => continue,
            };
            let other = if pick == a { b } else { a };
            if !remove.iter().any(|(n, _)| n == pick) {
                remove.push((
                    pick.to_string(),
                    format!("it penetrated {other} by {:.1} mm at t = 0", d.depth_m * 1000.0),
                ));
            }
        }
    }
    if let Some(s) = &v.settle {
        for m in &s.moved {
            if expected.contains(&m.body) {
                continue;
            }
            if is_object(&m.body) && !remove.iter().any(|(n, _)| n == &m.body) {
                remove.push((m.body.clone(), format!("it moved {:.1} cm during the settle", m.displacement_m * 100.0)));
            }
        }
    }
    // Whatever rests on a removed object goes too.
    let mut names: BTreeSet<String> = remove.iter().map(|(n, _)| n.clone()).collect();
    loop {
        let mut added = false;
        for o in &layout.objects {
            if let Support::Object { object, .. } = &o.support
                && names.contains(object)
                && !names.contains(&o.name)
            {
                names.insert(o.name.clone());
                remove.push((o.name.clone(), format!("it rested on {object}, which was removed")));
                added = true;
            }
        }
        if !added {
            break;
        }
    }
    for (name, why) in &remove {
        if let Some(i) = layout.objects.iter().position(|o| &o.name == name) {
            let o = layout.objects.remove(i);
            match layout.left_out.iter_mut().find(|l| l.group == o.group) {
                Some(l) => l.placed = l.placed.saturating_sub(1),
                None => {
                    let requested = layout.objects.iter().filter(|x| x.group == o.group).count() as u32 + 1;
                    layout.left_out.push(LeftOut {
                        group: o.group.clone(),
                        category: o.category.clone(),
                        requested,
                        placed: requested - 1,
                        reason: format!("removed after verification: {why}"),
                    });
                }
            }
        }
    }
    remove
}

pub(crate) fn assemble(
    plan: &ScenePlan,
    layout: &LaidOutScene,
    seed: u64,
    mut warnings: Vec<Warning>,
    verification: Option<Verification>,
) -> Report {
    let groups: BTreeSet<&str> = plan.objects.iter().map(|o| o.id.as_str()).collect();
    let placed = layout.objects.iter().filter(|o| groups.contains(o.group.as_str())).count() as u32;
    let summary = SceneSummary {
        room: plan.room.kind.name().to_string(),
        room_size: layout.room.size.as_array(),
        objects_requested: plan.object_count(),
        objects_placed: placed,
        robots: layout.robots.iter().map(|r| r.name.clone()).collect(),
        objects_added: layout.objects.iter().filter(|o| o.added).map(|o| o.name.clone()).collect(),
    };
    let mut report = Report::new(&plan.prompt, seed, summary);
    report.not_understood = plan.understanding.not_understood.clone();
    report.approximated = plan.understanding.approximated.clone();
    report.left_out = layout.left_out.clone();
    report.violations = layout.violations.clone();
    warnings.extend(layout.warnings.iter().cloned());
    report.warnings = warnings;
    report.status = match &verification {
        None => Status::Unverified,
        Some(v) if v.passed => Status::Verified,
        Some(_) => Status::Failed,
    };
    report.verification = verification;
    report
}

/// "1 body", "3 bodies".
pub(crate) fn count(n: usize, one: &str, many: &str) -> String {
    if n == 1 { format!("1 {one}") } else { format!("{n} {many}") }
}

fn trim(v: f64) -> String {
    let s = format!("{v:.2}");
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}
