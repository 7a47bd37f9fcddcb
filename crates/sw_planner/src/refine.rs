//! Prompt refinement, offline: what a plan leaves underspecified (the room's kind, what it
//! holds, its size, counts that were guessed, the robot, its task, words that were not
//! understood), as questions, and how an answer is folded back into the prompt so that the
//! offline planner reads it.
//!
//! An empty room is asked about first: "a small workshop" gets "what should it contain?"
//! (skipped, the suggestion for its kind or task is used — a scene with nothing in it is
//! never the result). The task is not a list of objects (its nouns are not placed), but it
//! decides where the robot works: with a robot in the prompt, the answer becomes "the UR5e
//! works at the workbench" (the work the task names: a conveyor, a machine, the shelves, or
//! the first work surface), which the planner reads as the arm's reach relation; a robot
//! named in a later answer works at the scene's work the same way.

use sw_plan::ScenePlan;

/// What a question is about.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord)]
pub enum Topic {
    RoomKind,
    /// What the room holds, when the prompt names nothing in it.
    Contents,
    RoomSize,
    /// A plural with no count: the words of the prompt.
    Count(String),
    Task,
    Robot,
    /// Words that were not understood.
    Unknown(String),
}

/// A question and the default used when it is skipped.
#[derive(Debug, Clone, PartialEq)]
pub struct Question {
    pub topic: Topic,
    pub text: String,
    pub default: String,
}

/// Robots to suggest for a task, by its words.
fn robot_for_task(task: &str) -> &'static str {
    let t = task.to_lowercase();
    let has = |ws: &[&str]| ws.iter().any(|w| t.contains(w));
    if has(&["navigat", "deliver", "transport", "patrol", "drive", "inventory", "map"]) {
        if has(&["pick", "grasp", "fetch", "manipulat"]) { "mobile manipulator" } else { "TurtleBot" }
    } else {
        "UR5e"
    }
}

/// What a room of this kind, for this task, is suggested to hold (phrases the offline
/// planner reads: catalog categories with counts and a relation).
fn contents_for(kind: &str, task: Option<&str>) -> &'static str {
    let t = task.unwrap_or("").to_lowercase();
    let has = |ws: &[&str]| ws.iter().any(|w| t.contains(w));
    if has(&["deliver", "transport", "inventory", "restock", "stock", "store ", "storage", "logistic"]) {
        return "two shelving racks and six boxes";
    }
    if has(&["machine", "tend", "conveyor", "sort", "inspect", "load"]) {
        return "a conveyor and two machines";
    }
    if has(&["cook", "dish", "serve", "wash", "kitchen"]) {
        return "a counter, a sink and two mugs";
    }
    if has(&["pick", "place", "assembl", "pack", "kit", "screw", "weld"]) {
        return "a workbench with four bins on it";
    }
    match kind {
        "warehouse" | "storage room" | "loading dock" | "retail store" | "pharmacy" | "closet" => {
            "two shelving racks and six boxes"
        }
        "factory" => "a conveyor and two machines",
        "kitchen" => "a counter, a sink and two mugs",
        "office" | "classroom" => "two desks and two chairs",
        _ => "a workbench with four bins on it and a shelf",
    }
}

/// The words of a phrase after its article or count ("a workbench" → "workbench").
fn noun(phrase: &str) -> String {
    let words: Vec<&str> = phrase.split_whitespace().collect();
    let skip = words.first().is_some_and(|w| {
        let w = w.to_lowercase();
        matches!(
            w.as_str(),
            "a" | "an" | "the" | "one" | "two" | "three" | "four" | "five" | "six" | "some" | "several"
        ) || w.chars().all(|c| c.is_ascii_digit())
    });
    words[usize::from(skip)..].join(" ")
}

/// The object group a robot's work is at: the one the task names by kind (conveyor,
/// machine, shelves …), else the first work surface; its words, to say "at the …".
fn work_of(plan: &ScenePlan, task: Option<&str>) -> Option<String> {
    let t = task.unwrap_or("").to_lowercase();
    let wanted: &[&str] = if t.contains("conveyor") || t.contains("sort") {
        &["conveyor"]
    } else if t.contains("machine") || t.contains("tend") {
        &["machine", "cnc", "lathe"]
    } else if t.contains("shel") || t.contains("stock") || t.contains("inventory") {
        &["shelf", "rack"]
    } else {
        &[]
    };
    let work = ["workbench", "table", "conveyor", "counter", "desk", "machine", "shelf"];
    let pick = |cats: &[&str]| plan.objects.iter().find(|o| cats.iter().any(|c| o.category.contains(c)));
    let o = pick(wanted).or_else(|| pick(&work))?;
    Some(noun(&o.phrase))
}

/// The questions a plan raises, most important first, leaving out `asked` topics.
pub fn questions(plan: &ScenePlan, asked: &[Topic], task: Option<&str>) -> Vec<Question> {
    let mut out = Vec::new();
    let approx = &plan.understanding.approximated;
    let kind = plan.room.kind.name().replace('_', " ");
    if approx.iter().any(|a| a.text == "(no room named)") {
        out.push(Question {
            topic: Topic::RoomKind,
            text: format!("What kind of room is it? (a lab, a warehouse, a kitchen, …; I assumed a {kind})"),
            default: kind.clone(),
        });
    }
    if plan.objects.is_empty() {
        let suggestion = contents_for(&kind, task);
        out.push(Question {
            topic: Topic::Contents,
            text: format!(
                "What should the {kind} hold? (the furniture and things in it, e.g. \"{suggestion}\"; I'd use that)"
            ),
            default: suggestion.to_string(),
        });
    }
    if !plan.room.size_fixed {
        let s = plan.room.size;
        out.push(Question {
            topic: Topic::RoomSize,
            text: format!("How big is the room? (e.g. \"8 by 6 m\"; a {kind} is usually {} × {} m)", s.width, s.depth),
            default: format!("{} by {} m", s.width, s.depth),
        });
    }
    for a in approx.iter().filter(|a| a.reason == "no count was given for a plural") {
        out.push(Question {
            topic: Topic::Count(a.text.clone()),
            text: format!("How many {}? (I'd use {})", a.text, a.became),
            default: a.became.clone(),
        });
    }
    out.push(Question {
        topic: Topic::Task,
        text: "What will the robots do here? (e.g. pick and place parts, deliver boxes, inspect machines; or \"skip\")"
            .into(),
        default: String::new(),
    });
    if plan.robots.is_empty() {
        let suggestion = task.map_or("UR5e", robot_for_task);
        out.push(Question {
            topic: Topic::Robot,
            text: format!(
                "Which robot works here? (UR5e, UR10e, Panda, Kinova Gen3, TurtleBot, mobile manipulator, or \"none\"; I'd use a {suggestion})"
            ),
            default: suggestion.to_string(),
        });
    }
    for n in plan.understanding.not_understood.iter().take(3) {
        out.push(Question {
            topic: Topic::Unknown(n.text.clone()),
            text: format!(
                "I did not understand \"{}\". What is it? (a short description, or \"skip\" to drop it)",
                n.text
            ),
            default: String::new(),
        });
    }
    out.retain(|q| !asked.contains(&q.topic));
    out
}

fn skip(answer: &str) -> bool {
    matches!(
        answer.trim().to_lowercase().as_str(),
        "" | "skip" | "no" | "n/a" | "-" | "default" | "don't know" | "dont know"
    )
}

/// The prompt with an answer folded in (as a sentence the offline planner reads).
pub fn fold(prompt: &str, q: &Question, answer: &str) -> String {
    let a = answer.trim().trim_end_matches('.');
    let base = prompt.trim().trim_end_matches('.');
    let sentence = |s: String| format!("{base}. {s}.");
    match &q.topic {
        // An empty room is never the result: skipped, the suggestion is used.
        Topic::Contents => {
            let what = if skip(a) { q.default.trim() } else { a.trim_start_matches("with ").trim() };
            if what.is_empty() { prompt.to_string() } else { sentence(format!("It has {what}")) }
        }
        _ if skip(a) && !matches!(q.topic, Topic::Unknown(_)) => prompt.to_string(),
        Topic::RoomKind => sentence(format!("It is a {a}")),
        Topic::RoomSize => {
            let sized = if a.chars().any(|c| c.is_ascii_digit())
                && !a.contains('m')
                && !a.contains("feet")
                && !a.contains("ft")
            {
                format!("{a} m")
            } else {
                a.to_string()
            };
            sentence(format!("The room is {sized}"))
        }
        Topic::Count(phrase) => match prompt.find(phrase.as_str()) {
            Some(i) => format!("{}{a} {}{}", &prompt[..i], phrase, &prompt[i + phrase.len()..]),
            None => prompt.to_string(),
        },
        // The task's nouns are not objects to place; it says where the robot works.
        Topic::Task => {
            let Ok(plan) = crate::plan(prompt) else { return prompt.to_string() };
            match (plan.robots.iter().find(|r| r.near.is_none()), work_of(&plan, Some(a))) {
                (Some(robot), Some(work)) => sentence(format!("The {} works at the {work}", noun(&robot.phrase))),
                _ => prompt.to_string(),
            }
        }
        Topic::Robot => {
            let lower = a.to_lowercase();
            if matches!(lower.as_str(), "none" | "no robot" | "nothing") {
                prompt.to_string()
            } else {
                let article = if lower.starts_with(|c: char| c.is_ascii_digit())
                    || lower.starts_with("a ")
                    || lower.starts_with("an ")
                    || lower.starts_with("two")
                {
                    ""
                } else {
                    "a "
                };
                // The robot works at the scene's work (the first work surface, conveyor …).
                let at = crate::plan(prompt).ok().and_then(|p| work_of(&p, None));
                match at {
                    Some(work) => sentence(format!("There is {article}{a} working at the {work}")),
                    None => sentence(format!("There is {article}{a}")),
                }
            }
        }
        Topic::Unknown(text) => {
            let replacement = if skip(a) { "" } else { a };
            let out = prompt.replacen(text.as_str(), replacement, 1);
            out.split_whitespace().collect::<Vec<_>>().join(" ")
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Answers questions in turn (as the refinement does), `answers` in order, then "skip".
    fn converse(prompt: &str, answers: &[&str]) -> (String, Vec<Topic>) {
        let mut prompt = prompt.to_string();
        let mut asked: Vec<Topic> = Vec::new();
        let mut task: Option<String> = None;
        for k in 0..10 {
            let plan = crate::plan(&prompt).unwrap();
            let Some(q) = questions(&plan, &asked, task.as_deref()).into_iter().next() else { break };
            let a = answers.get(k).copied().unwrap_or("skip");
            if q.topic == Topic::Task && !skip(a) {
                task = Some(a.to_string());
            }
            prompt = fold(&prompt, &q, a);
            asked.push(q.topic);
        }
        (prompt, asked)
    }

    #[test]
    fn an_empty_room_is_asked_what_it_holds_and_never_stays_empty() {
        // Answered: what was said is in the scene.
        let (prompt, asked) = converse("a small workshop", &["a workbench and two shelves"]);
        assert_eq!(asked[0], Topic::Contents, "{asked:?}");
        let plan = crate::plan(&prompt).unwrap();
        let cats: Vec<&str> = plan.objects.iter().map(|o| o.category.as_str()).collect();
        assert!(cats.contains(&"workbench") && cats.contains(&"shelf"), "{prompt}: {cats:?}");
        // Skipped throughout: the suggestion for the room's kind, not an empty room.
        for room in ["a small workshop", "an empty warehouse", "a kitchen", "a factory hall"] {
            let (prompt, _) = converse(room, &[]);
            let plan = crate::plan(&prompt).unwrap();
            assert!(plan.object_count() >= 2, "{room} → {prompt}");
            assert!(plan.understanding.not_understood.is_empty(), "{prompt}: {:?}", plan.understanding.not_understood);
        }
    }

    #[test]
    fn the_task_decides_where_the_robot_works() {
        // The robot in the prompt: the task says at what it works.
        let (prompt, _) =
            converse("a 6 by 5 m lab with a workbench, a conveyor and a UR5e", &["sort parts off the conveyor"]);
        let plan = crate::plan(&prompt).unwrap();
        assert_eq!(plan.robots[0].near.as_deref(), Some("conveyor"), "{prompt}");
        assert!(plan.understanding.not_understood.is_empty(), "the task's words are not objects: {prompt}");
        assert_eq!(plan.object_count(), 2, "{prompt}");
        // The robot named later: it works at the scene's work surface.
        let (prompt, asked) = converse(
            "a small workshop",
            &["a workbench with four bins on it", "6 by 5", "pick and place bins", "a UR5e"],
        );
        assert!(asked.contains(&Topic::Task) && asked.contains(&Topic::Robot), "{asked:?}");
        let plan = crate::plan(&prompt).unwrap();
        assert_eq!(plan.robots.len(), 1, "{prompt}");
        assert_eq!(plan.robots[0].near.as_deref(), Some("workbench"), "{prompt}");
        assert!(plan.understanding.not_understood.is_empty(), "{prompt}: {:?}", plan.understanding.not_understood);
    }

    #[test]
    fn gaps_become_questions_and_answers_fold_into_the_prompt() {
        let p = "boxes on a table and a mystery gizmo";
        let plan = crate::plan(p).unwrap();
        let qs = questions(&plan, &[], None);
        let topics: Vec<&Topic> = qs.iter().map(|q| &q.topic).collect();
        assert!(matches!(topics[0], Topic::RoomKind), "{topics:?}");
        assert!(topics.contains(&&Topic::RoomSize));
        assert!(topics.iter().any(|t| matches!(t, Topic::Count(c) if c == "boxes")));
        assert!(topics.contains(&&Topic::Robot));
        let mut prompt = p.to_string();
        for (q, a) in qs.iter().zip(["lab", "12 by 9", "6", "pick and place", "UR5e"]) {
            prompt = fold(&prompt, q, a);
        }
        let plan = crate::plan(&prompt).unwrap();
        assert_eq!(plan.room.kind, sw_plan::RoomKind::Lab, "{prompt}");
        assert!(plan.room.size_fixed && plan.room.size.width == 12.0, "{prompt}");
        assert_eq!(plan.objects.iter().find(|o| o.category == "cardboard_box").unwrap().count, 6, "{prompt}");
        assert_eq!(plan.robots[0].model, "ur5e");
        let asked: Vec<Topic> = qs.iter().map(|q| q.topic.clone()).collect();
        let left = questions(&plan, &asked, Some("pick and place"));
        assert!(
            left.iter().all(|q| !matches!(q.topic, Topic::RoomKind | Topic::RoomSize | Topic::Robot | Topic::Task)),
            "{left:?}"
        );
    }
}
