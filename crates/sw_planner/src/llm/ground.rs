//! Grounding: a model's plan checked against what the prompt says in so many words, as
//! the offline reader reads it. Small models contradict the prompt ("a kitchen with a
//! fridge" planned as a factory with three fridges); where the two disagree on an
//! explicit fact the prompt's words win and the plan says so in
//! `understanding.approximated`. A model can only add to a faithful reading, never
//! subtract from it:
//!
//! | fact the reader found | the grounded plan |
//! |---|---|
//! | a room kind it was given | that kind (and its rules profile, unless the prompt names one) |
//! | a room size it was given | that size, fixed; else the model's size when plausible for the kind, never fixed |
//! | an object it knows, with a stated count | a group of it with that count (the model's groups of it merged) |
//! | an object it knows, no count | the model's groups of it, or the reader's group when the model left it out |
//! | an unknown noun (a proxy) | the model's group for those words (it may know them), else the reader's proxy |
//! | a named robot | that model with its count; robots the prompt does not name are dropped |
//! | a stated relation | kept, between the matching groups |
//! | a stated dimension | that size on the matching group |
//! | an anomaly request | exactly that request; none when the prompt asks for none |
//!
//! What the reader could not see stays the model's: open-vocabulary objects, implicit
//! furniture, relations it inferred, colours, sizes and mounts.

use std::collections::{BTreeMap, BTreeSet};

use sw_plan::{Approximation, ObjectPlan, Relation, ScenePlan};

use crate::vocab;

/// What grounding changed, one note each (also added to the plan's approximations).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Grounding {
    pub notes: Vec<Approximation>,
}

fn note(g: &mut Grounding, text: &str, became: &str, reason: String) {
    g.notes.push(Approximation { text: text.to_string(), became: became.to_string(), reason });
}

/// The count of `group` was written in the prompt (not a plural the reader gave a
/// default count).
fn count_stated(reading: &ScenePlan, phrase: &str) -> bool {
    !reading
        .understanding
        .approximated
        .iter()
        .any(|a| a.reason.starts_with("no count was given") && (a.text == phrase || phrase.contains(&a.text)))
}

fn room_named(reading: &ScenePlan) -> bool {
    !reading.understanding.approximated.iter().any(|a| a.text == "(no room named)")
}

/// The words that say what a group is: its category, its proxy label and the head noun
/// of its phrase, singular. Not every word of the phrase: a small model writes phrases
/// such as "a car and a TurtleBot" for an air compressor, which is no car.
fn group_words(o: &ObjectPlan) -> BTreeSet<String> {
    let mut w: BTreeSet<String> = head(o).into_iter().collect();
    if o.category != "proxy" {
        w.extend(vocab::words(&o.category.replace('_', " ")));
    }
    if let Some(p) = &o.proxy {
        w.extend(vocab::words(&p.label));
    }
    w
}

/// The head noun of a group as the prompt wrote it (its phrase's last content word).
fn head(o: &ObjectPlan) -> Option<String> {
    vocab::words(&o.phrase).into_iter().rev().find(|w| vocab::color(w).is_none() && vocab::size_word(w).is_none())
}

/// The model's group `o` may be a `noun`: it is a proxy (the model, like the reader,
/// has no category for it) or its category is a kind of that noun: "chair" for an
/// armchair (the noun ends with the category's last word), "tool_chest" for a chest.
/// Whole words, not substrings: an air compressor is no armchair although "armchair"
/// contains "air".
fn may_be(o: &ObjectPlan, noun: &str) -> bool {
    if o.category == "proxy" {
        return true;
    }
    let last = o.category.rsplit('_').next().unwrap_or(&o.category);
    noun.ends_with(last) || vocab::words(&o.category.replace('_', " ")).iter().any(|w| w == noun)
}

/// The model's groups that stand for the reader's `fact`.
fn matches(fact: &ObjectPlan, plan: &ScenePlan, taken: &BTreeSet<String>) -> Vec<String> {
    let same_category = |o: &ObjectPlan| fact.category != "proxy" && o.category == fact.category;
    let mut hits: Vec<String> =
        plan.objects.iter().filter(|o| !taken.contains(&o.id) && same_category(o)).map(|o| o.id.clone()).collect();
    if hits.is_empty()
        && let Some(h) = head(fact)
    {
        // Found by the head noun of its phrase (which a small model may fill with the
        // whole prompt), a group stands for the fact only when its category allows it.
        hits = plan
            .objects
            .iter()
            .filter(|o| !taken.contains(&o.id) && group_words(o).contains(&h) && may_be(o, &h))
            .map(|o| o.id.clone())
            .collect();
    }
    hits
}

fn unique_id(plan: &ScenePlan, base: &str) -> String {
    let used: BTreeSet<&str> =
        plan.objects.iter().map(|o| o.id.as_str()).chain(plan.robots.iter().map(|r| r.id.as_str())).collect();
    let mut id = base.to_string();
    let mut k = 2;
    while used.contains(id.as_str()) {
        id = format!("{base}_{k}");
        k += 1;
    }
    id
}

/// Points every reference to `from` at `to` (relations, robot mounts and `near`).
fn redirect(plan: &mut ScenePlan, from: &str, to: &str) {
    let mut rels: Vec<Relation> = Vec::new();
    for r in plan.relations.drain(..) {
        let mut v = match serde_json::to_value(&r) {
            Ok(v) => v,
            Err(_) => continue,
        };
        if let Some(o) = v.as_object_mut() {
            for val in o.values_mut() {
                if val.as_str() == Some(from) {
                    *val = serde_json::Value::String(to.to_string());
                }
            }
        }
        if let Ok(r2) = serde_json::from_value::<Relation>(v)
            && !r2.kind.targets().contains(&r2.subject.as_str())
            && !rels.contains(&r2)
        {
            rels.push(r2);
        }
    }
    plan.relations = rels;
    for r in plan.robots.iter_mut() {
        if r.near.as_deref() == Some(from) {
            r.near = Some(to.to_string());
        }
        if let sw_plan::Mount::OnSurface { target } = &mut r.mount
            && target == from
        {
            *target = to.to_string();
        }
    }
}

/// Some words of the prompt (one to three in a row) name the robot `model`.
fn mentions(prompt: &str, model: &str) -> bool {
    let words = vocab::words(prompt);
    (1..=3).any(|n| words.windows(n).any(|w| vocab::robot_model(&w.join(" ")).is_some_and(|(m, _)| m == model)))
}

fn plausible(model: f64, typical: f64) -> bool {
    model >= typical * 0.5 && model <= typical * 2.0
}

/// Grounds `plan` (the model's) in `reading` (the offline reader's plan of the same
/// prompt). Returns the grounded plan and what changed.
pub fn ground(mut plan: ScenePlan, reading: &ScenePlan) -> (ScenePlan, Grounding) {
    let mut g = Grounding::default();
    // The room's kind.
    let model_kind = plan.room.kind;
    if room_named(reading) && reading.room.kind != model_kind {
        plan.room.kind = reading.room.kind;
        note(
            &mut g,
            &format!("room: {}", model_kind.name()),
            reading.room.kind.name(),
            format!("the prompt names a {}; the model planned a {}", reading.room.kind.name(), model_kind.name()),
        );
    }
    // The rules profile follows the prompt's words, else the (grounded) room kind.
    let stated_profile = reading.rules_profile != reading.room.kind.rules_profile();
    let profile = if stated_profile {
        reading.rules_profile.clone()
    } else if plan.room.kind != model_kind {
        plan.room.kind.rules_profile().to_string()
    } else {
        plan.rules_profile.clone()
    };
    if profile != plan.rules_profile {
        note(
            &mut g,
            &format!("rules: {}", plan.rules_profile),
            &profile,
            "the rules of the room the prompt names".into(),
        );
        plan.rules_profile = profile;
    }
    // The room's size.
    let s = plan.room.size;
    if reading.room.size_fixed {
        let r = reading.room.size;
        let differs =
            (s.width - r.width).abs() > 0.01 || (s.depth - r.depth).abs() > 0.01 || (s.height - r.height).abs() > 0.01;
        if differs || !plan.room.size_fixed {
            note(
                &mut g,
                &format!("room {} × {} × {} m", s.width, s.depth, s.height),
                &format!("{} × {} × {} m", r.width, r.depth, r.height),
                "the prompt gives the room's size".into(),
            );
        }
        plan.room.size = r;
        plan.room.size_fixed = true;
    } else {
        let typical = plan.room.kind.default_size();
        let fits = plausible(s.width, typical.width)
            && plausible(s.depth, typical.depth)
            && plausible(s.height, typical.height);
        if !fits {
            let r = if reading.room.kind == plan.room.kind { reading.room.size } else { typical };
            note(
                &mut g,
                &format!("room {} × {} × {} m", s.width, s.depth, s.height),
                &format!("{} × {} × {} m", r.width, r.depth, r.height),
                format!("the prompt gives no size and the model's is implausible for a {}", plan.room.kind.name()),
            );
            plan.room.size = r;
        } else if plan.room.size_fixed {
            note(
                &mut g,
                "room size fixed",
                "not fixed",
                "the prompt gives no size; the layout may grow the room".into(),
            );
        }
        plan.room.size_fixed = false;
    }
    // Objects.
    let mut taken: BTreeSet<String> = BTreeSet::new();
    let mut ids: BTreeMap<String, String> = BTreeMap::new();
    for fact in &reading.objects {
        let hits = matches(fact, &plan, &taken);
        let Some(keep) = hits.first().cloned() else {
            let mut added = fact.clone();
            added.id = unique_id(&plan, &fact.id);
            note(&mut g, &fact.phrase, &added.id, "the model left it out; added as the prompt says".into());
            ids.insert(fact.id.clone(), added.id.clone());
            taken.insert(added.id.clone());
            plan.objects.push(added);
            continue;
        };
        taken.extend(hits.iter().cloned());
        ids.insert(fact.id.clone(), keep.clone());
        // A known object named in the prompt keeps its category.
        if fact.category != "proxy"
            && let Some(o) = plan.objects.iter_mut().find(|o| o.id == keep)
            && o.category != fact.category
        {
            note(
                &mut g,
                &fact.phrase,
                &fact.category,
                format!("the prompt names a {}; the model planned a {}", fact.category, o.category),
            );
            o.category = fact.category.clone();
            o.proxy = None;
        }
        // A stated dimension ("a 4.5 m conveyor") is the prompt's, not the model's guess.
        if !fact.size.explicit.is_empty()
            && let Some(o) = plan.objects.iter_mut().find(|o| o.id == keep)
            && o.size.explicit != fact.size.explicit
        {
            let stated: Vec<String> = fact.size.explicit.stated().iter().map(|(n, v)| format!("{n} {v} m")).collect();
            note(&mut g, &fact.phrase, &stated.join(", "), "the prompt states the size".into());
            o.size.explicit = fact.size.explicit;
        }
        if count_stated(reading, &fact.phrase) {
            let planned: u32 = plan.objects.iter().filter(|o| hits.contains(&o.id)).map(|o| o.count).sum();
            if planned != fact.count || hits.len() > 1 {
                if planned != fact.count {
                    note(
                        &mut g,
                        &fact.phrase,
                        &fact.count.to_string(),
                        format!("the prompt says {}; the model planned {planned}", fact.count),
                    );
                }
                for other in hits.iter().skip(1) {
                    redirect(&mut plan, other, &keep);
                }
                plan.objects.retain(|o| o.id == keep || !hits.contains(&o.id));
                if let Some(o) = plan.objects.iter_mut().find(|o| o.id == keep) {
                    o.count = fact.count;
                }
            }
        }
    }
    // Robots.
    let named: BTreeMap<&str, (u32, &str, bool)> = reading
        .robots
        .iter()
        .map(|r| (r.model.as_str(), (r.count, r.phrase.as_str(), count_stated(reading, &r.phrase))))
        .collect();
    let mut kept = Vec::new();
    for r in plan.robots.drain(..) {
        let in_prompt =
            named.contains_key(r.model.as_str()) || (named.is_empty() && mentions(&reading.prompt, &r.model));
        if in_prompt {
            kept.push(r);
        } else {
            note(&mut g, &r.phrase, "left out", format!("the prompt names no {}", r.model));
        }
    }
    plan.robots = kept;
    for rr in &reading.robots {
        let (count, phrase, stated) = named.get(rr.model.as_str()).copied().unwrap_or((rr.count, &rr.phrase, true));
        let of_model: Vec<usize> =
            plan.robots.iter().enumerate().filter(|(_, r)| r.model == rr.model).map(|(i, _)| i).collect();
        match of_model.first() {
            None => {
                let mut added = rr.clone();
                added.id = unique_id(&plan, &rr.id);
                added.near = rr.near.as_ref().and_then(|n| ids.get(n)).cloned();
                if let sw_plan::Mount::OnSurface { target } = &rr.mount {
                    added.mount = ids
                        .get(target)
                        .map_or(sw_plan::Mount::Auto, |t| sw_plan::Mount::OnSurface { target: t.clone() });
                }
                note(&mut g, phrase, &added.id, "the model left the robot out; added as the prompt says".into());
                plan.robots.push(added);
            }
            Some(&first) if stated => {
                let planned: u32 = of_model.iter().map(|i| plan.robots[*i].count).sum();
                if planned != count {
                    note(
                        &mut g,
                        phrase,
                        &count.to_string(),
                        format!("the prompt says {count}; the model planned {planned}"),
                    );
                }
                let first_id = plan.robots[first].id.clone();
                plan.robots[first].count = count;
                let drop: BTreeSet<String> = of_model.iter().skip(1).map(|i| plan.robots[*i].id.clone()).collect();
                plan.robots.retain(|r| !drop.contains(&r.id));
                for d in &drop {
                    redirect(&mut plan, d, &first_id);
                }
            }
            Some(_) => {}
        }
        if let Some(r) = plan.robots.iter().find(|r| r.model == rr.model) {
            ids.insert(rr.id.clone(), r.id.clone());
        }
    }
    // Anomalies are injected only when the prompt asks for them, as it asks.
    if plan.anomaly != reading.anomaly {
        let what = |a: &Option<sw_plan::AnomalyRequest>| {
            a.as_ref().map_or("none".to_string(), |a| format!("{:?} at {}", a.kinds, a.rate))
        };
        note(
            &mut g,
            &format!("anomalies: {}", what(&plan.anomaly)),
            &what(&reading.anomaly),
            "as the prompt asks".into(),
        );
        plan.anomaly = reading.anomaly.clone();
    }
    // Relations the prompt states.
    let object_ids: BTreeSet<String> =
        plan.objects.iter().map(|o| o.id.clone()).chain(plan.robots.iter().map(|r| r.id.clone())).collect();
    plan.relations
        .retain(|r| object_ids.contains(&r.subject) && r.kind.targets().iter().all(|t| object_ids.contains(*t)));
    for r in &reading.relations {
        let Ok(mut v) = serde_json::to_value(r) else { continue };
        let mut mapped = true;
        if let Some(o) = v.as_object_mut() {
            for (k, val) in o.iter_mut() {
                let is_ref = k == "subject" || r.kind.targets().contains(&val.as_str().unwrap_or_default());
                if is_ref {
                    match val.as_str().and_then(|s| ids.get(s)) {
                        Some(id) => *val = serde_json::Value::String(id.clone()),
                        None => mapped = false,
                    }
                }
            }
        }
        let Some(rel) = mapped.then(|| serde_json::from_value::<Relation>(v).ok()).flatten() else { continue };
        let same = |x: &Relation| {
            x.subject == rel.subject && x.kind.name() == rel.kind.name() && x.kind.targets() == rel.kind.targets()
        };
        if !plan.relations.iter().any(same) && !rel.kind.targets().contains(&rel.subject.as_str()) {
            let phrase = |id: &str| {
                reading.objects.iter().find(|o| o.id == id).map_or_else(|| id.to_string(), |o| o.phrase.clone())
            };
            let targets: Vec<String> = r.kind.targets().into_iter().map(phrase).collect();
            let words = format!("{} {} {}", phrase(&r.subject), r.kind.name().replace('_', " "), targets.join(" and "));
            note(&mut g, &words, rel.kind.name(), "the prompt states it; the model left it out".into());
            plan.relations.push(rel);
        }
    }
    for n in &g.notes {
        if !plan.understanding.approximated.contains(n) {
            plan.understanding.approximated.push(n.clone());
        }
    }
    (plan, g)
}

#[cfg(test)]
mod tests {
    use serde_json::json;

    use super::*;
    use crate::llm::read_plan;

    fn count_of(plan: &ScenePlan, category: &str) -> u32 {
        plan.objects.iter().filter(|o| o.category == category).map(|o| o.count).sum()
    }

    fn grounded(prompt: &str, answer: serde_json::Value) -> (ScenePlan, Grounding) {
        let model = read_plan(prompt, &answer).unwrap();
        let reading = crate::plan(prompt).unwrap();
        ground(model, &reading)
    }

    #[test]
    fn a_kitchen_planned_as_a_factory_with_three_fridges_is_put_right() {
        let prompt = "a kitchen with a fridge, a sink and a table with two plates";
        let (plan, g) = grounded(
            prompt,
            json!({
                "room": {"kind": "factory", "size": {"width": 45, "depth": 12, "height": 30}, "size_fixed": true, "door": "south"},
                "objects": [
                    {"phrase": "fridge", "id": "fridge", "category": "fridge", "count": 3},
                    {"phrase": "another fridge", "id": "fridge_b", "category": "fridge", "count": 1},
                    {"phrase": "a chair", "id": "chair", "category": "chair", "count": 2}
                ],
                "relations": [{"subject": "fridge_b", "relation": "against_wall"}],
                "robots": [{"phrase": "a UR5e", "id": "arm", "model": "ur5e", "count": 1, "mount": {"mount": "auto"}}],
                "rules_profile": "industrial"
            }),
        );
        assert_eq!(plan.room.kind, sw_plan::RoomKind::Kitchen);
        assert_eq!(plan.rules_profile, "kitchen");
        assert!(!plan.room.size_fixed);
        assert!(plan.room.size.height < 5.0, "{:?}", plan.room.size);
        assert_eq!(count_of(&plan, "fridge"), 1);
        assert_eq!(plan.objects.iter().filter(|o| o.category == "fridge").count(), 1, "the model's fridges merged");
        assert_eq!(count_of(&plan, "plate"), 2);
        assert_eq!(count_of(&plan, "sink"), 1);
        assert_eq!(count_of(&plan, "table"), 1);
        assert_eq!(count_of(&plan, "chair"), 2, "what the model adds stays");
        assert!(plan.robots.is_empty(), "the prompt names no robot");
        // The merged group's relation now points at the kept group; the stated one is there.
        assert!(
            plan.relations.iter().any(|r| r.subject == "fridge" && r.kind.name() == "against_wall"),
            "{:?}",
            plan.relations
        );
        let plate = plan.objects.iter().find(|o| o.category == "plate").unwrap();
        let table = plan.objects.iter().find(|o| o.category == "table").unwrap();
        assert!(plan.relations.iter().any(|r| r.subject == plate.id && r.kind.targets() == vec![table.id.as_str()]));
        assert!(g.notes.len() >= 6, "{:#?}", g.notes);
        assert!(g.notes.iter().all(|n| plan.understanding.approximated.contains(n)));
        plan.validate().unwrap();
    }

    #[test]
    fn ten_turtlebots_for_a_turtlebot_become_one_and_what_the_model_adds_stays() {
        let prompt = "a warehouse aisle with two shelving racks, six boxes and a TurtleBot";
        let (plan, _) = grounded(
            prompt,
            json!({
                "room": {"kind": "warehouse", "size": {"width": 18, "depth": 10, "height": 6}, "size_fixed": false, "door": "south"},
                "objects": [
                    {"phrase": "shelving racks", "id": "racks", "category": "shelf", "count": 2},
                    {"phrase": "boxes", "id": "boxes", "category": "cardboard_box", "count": 10},
                    {"phrase": "a pallet", "id": "pallet", "category": "pallet", "count": 1}
                ],
                "relations": [{"subject": "boxes", "relation": "on", "target": "racks"}],
                "robots": [{"phrase": "TurtleBots", "id": "tb", "model": "turtlebot3", "count": 10, "mount": {"mount": "floor"}}]
            }),
        );
        assert_eq!(plan.robots.len(), 1);
        assert_eq!(plan.robots[0].count, 1);
        assert_eq!(count_of(&plan, "cardboard_box"), 6);
        assert_eq!(count_of(&plan, "shelf"), 2);
        assert_eq!(count_of(&plan, "pallet"), 1);
        assert_eq!(plan.room.size.width, 18.0, "a plausible size the prompt does not contradict stays");
        assert!(plan.relations.iter().any(|r| r.subject == "boxes" && r.kind.name() == "on"));
        assert!(plan.relations.iter().any(|r| r.subject == "racks" && r.kind.name() == "facing_each_other"));
        plan.validate().unwrap();
    }

    #[test]
    fn a_group_whose_phrase_merely_mentions_an_unknown_noun_does_not_stand_for_it() {
        // SmolLM2-135M's plan of this prompt on llama-server: the whole prompt as one
        // group's phrase, "a car and a TurtleBot" as an air compressor's, no car.
        let prompt = "a garage with two tool chests, a car and a TurtleBot";
        let (plan, g) = grounded(
            prompt,
            json!({
                "room": {"kind": "tabletop"},
                "objects": [
                    {"phrase": prompt, "id": "chests", "category": "tool_chest", "count": 2},
                    {"phrase": "a car and a TurtleBot", "id": "compressor", "category": "air_compressor", "count": 3}
                ],
                "robots": [{"phrase": prompt, "id": "tb", "model": "turtlebot3", "count": 1, "mount": {"mount": "floor"}}]
            }),
        );
        let cars: Vec<&ObjectPlan> =
            plan.objects.iter().filter(|o| o.proxy.as_ref().is_some_and(|p| p.label == "car")).collect();
        assert_eq!(cars.iter().map(|o| o.count).collect::<Vec<_>>(), vec![1], "{:#?}", plan.objects);
        assert_eq!(count_of(&plan, "air_compressor"), 3, "what the model adds stays");
        assert_eq!(count_of(&plan, "tool_chest"), 2);
        assert!(g.notes.iter().any(|n| n.text == "a car" && n.reason.contains("left it out")), "{:#?}", g.notes);
        plan.validate().unwrap();
    }

    #[test]
    fn a_whole_prompt_phrase_ending_in_an_unknown_noun_does_not_make_another_category_stand_for_it() {
        // SmolLM2-135M on llama-server (issue 16, run C): one group whose phrase is the
        // whole prompt, planned as two air compressors. Its head noun is "armchair", but
        // an air compressor is no kind of armchair: the reader's two armchairs stay.
        let prompt = "a living room with a sofa, a coffee table and two armchairs";
        let (plan, g) = grounded(
            prompt,
            json!({
                "room": {"kind": "living_room"},
                "objects": [
                    {"phrase": "a sofa", "id": "sofa", "category": "sofa", "count": 1},
                    {"phrase": prompt, "id": "compressors", "category": "air_compressor", "count": 2}
                ]
            }),
        );
        let armchairs: u32 = plan
            .objects
            .iter()
            .filter(|o| o.proxy.as_ref().is_some_and(|p| p.label == "armchair"))
            .map(|o| o.count)
            .sum();
        let reading = crate::plan(prompt).unwrap();
        let read: u32 = reading
            .objects
            .iter()
            .filter(|o| o.proxy.as_ref().is_some_and(|p| p.label == "armchair") || o.category == "armchair")
            .map(|o| o.count)
            .sum();
        assert_eq!(read, 2, "the reader's armchairs: {:#?}", reading.objects);
        assert_eq!(armchairs + count_of(&plan, "armchair"), 2, "{:#?}", plan.objects);
        assert_eq!(count_of(&plan, "air_compressor"), 2, "what the model adds stays");
        assert!(
            g.notes.iter().any(|n| n.text.contains("armchair") && n.reason.contains("left it out")),
            "{:#?}",
            g.notes
        );
        plan.validate().unwrap();
    }

    #[test]
    fn a_category_that_is_a_kind_of_the_head_noun_still_stands_for_it() {
        // "armchair" ends with "chair": a model that plans chairs for the armchairs planned
        // them, and the prompt's count wins.
        let chair = ObjectPlan { category: "chair".into(), ..crate::plan("a chair").unwrap().objects[0].clone() };
        assert!(may_be(&chair, "armchair"));
        assert!(!may_be(&ObjectPlan { category: "air_compressor".into(), ..chair.clone() }, "armchair"));
        assert!(may_be(&ObjectPlan { category: "tool_chest".into(), ..chair.clone() }, "chest"));
        assert!(may_be(&ObjectPlan { category: "proxy".into(), ..chair }, "armchair"));
    }

    #[test]
    fn a_plan_that_leaves_things_out_gets_them_back_and_a_given_size_is_kept() {
        let prompt = "a 10 by 8 m lab with a workbench, three microscopes and a UR5e";
        let (plan, g) = grounded(
            prompt,
            json!({"objects": [{"phrase": "a workbench", "id": "bench", "category": "workbench", "count": 1}], "room": {"kind": "lab"}}),
        );
        let reading = crate::plan(prompt).unwrap();
        assert_eq!(plan.room.size, reading.room.size);
        assert!(plan.room.size_fixed);
        for o in &reading.objects {
            assert_eq!(count_of(&plan, &o.category), o.count, "{}", o.phrase);
        }
        assert_eq!(plan.robots.iter().map(|r| (r.model.as_str(), r.count)).collect::<Vec<_>>(), vec![("ur5e", 1)]);
        assert!(g.notes.iter().any(|n| n.reason.contains("left")), "{:#?}", g.notes);
        plan.validate().unwrap();
    }

    #[test]
    fn the_relations_and_sizes_the_reader_states_reach_a_model_plan_that_left_them_out() {
        // A model that names the things but none of the issue-20 placements: the grounded
        // plan has the reader's inside, set into, each side, facing and stated length.
        let prompt = "a kitchen with a counter, a hob in the counter, three cups in the sink, a table with a chair \
                      on either side of it, a sofa facing the table and a 4.5 m conveyor";
        let (plan, _) = grounded(
            prompt,
            json!({"objects": [
                {"id": "counter", "category": "counter", "count": 1},
                {"id": "hob", "category": "stove", "count": 1},
                {"id": "cups", "category": "cup", "count": 3},
                {"id": "sink", "category": "sink", "count": 1},
                {"id": "table", "category": "table", "count": 1},
                {"id": "chairs", "category": "chair", "count": 2},
                {"id": "sofa", "category": "sofa", "count": 1},
                {"id": "belt", "category": "conveyor", "count": 1}
            ], "room": {"kind": "kitchen"}}),
        );
        plan.validate().unwrap();
        let names: BTreeSet<&str> = plan.relations.iter().map(|r| r.kind.name()).collect();
        for want in ["set_into", "inside", "on_each_side_of", "facing"] {
            assert!(names.contains(want), "{want} missing: {names:?}");
        }
        let belt = plan.objects.iter().find(|o| o.category == "conveyor").unwrap();
        assert_eq!(belt.size.explicit.length, Some(4.5), "{:?}", belt.size);
    }
}
