//! Prompt refinement, offline: what a plan leaves underspecified (the room's kind and
//! size, counts that were guessed, the robot, its task, words that were not understood),
//! as questions, and how an answer is folded back into the prompt so that the offline
//! planner reads it.

use sw_plan::ScenePlan;

/// What a question is about.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord)]
pub enum Topic {
    RoomKind,
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
        // The task is kept beside the prompt: its nouns are not objects to place.
        Topic::Task => prompt.to_string(),
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
                sentence(format!("There is {article}{a}"))
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
