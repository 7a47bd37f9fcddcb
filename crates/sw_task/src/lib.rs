//! Tasks: what a robot is asked to do in a scene, as predicates over named bodies.
//!
//! ```text
//! "a Panda on a table that puts the red cube in the bowl"
//!        │ split_prompt
//!        ├─▶ scene words ("a Panda on a table with a red cube and a bowl") ──▶ the pipeline ──▶ package
//!        └─▶ instruction ("puts the red cube in the bowl")
//!                 │ words::read (verbs, things, relation words — tables in `vocab`)
//!                 ▼ bind (noun phrases → bodies by category and colour; the arm that reaches)
//!            task.json ──▶ judge (on a Snapshot of the MuJoCo state)
//! ```
//!
//! This crate is pure: the expert (`sw_expert`) fills a [`judge::Snapshot`] from MuJoCo,
//! and the Python replay check judges with its own code from the official bindings.

pub mod bind;
mod goal;
pub mod judge;
pub mod task;
mod vocab;
mod words;

pub use bind::{SceneFacts, SceneRobot, bind};
pub use goal::read_goals;
pub use judge::{BodyState, Bounds, GoalVerdict, Snapshot, Surface, holds, judge};
pub use task::{Family, GripperInterface, Predicate, TASK_VERSION, Task};

/// Why a task cannot be made. Each is one line that names the part.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum TaskError {
    #[error("{0}")]
    Words(String),
    #[error("{0}")]
    Missing(String),
    #[error("{0}")]
    Robot(String),
    #[error("{0}")]
    Unreachable(String),
    #[error("{0}")]
    Contradiction(String),
}

/// The instruction as a command, its verbs in their base form ("puts the mug in the
/// sink" → "put the mug in the sink"), for a dataset's task string.
pub fn imperative(instruction: &str) -> String {
    let mut out: Vec<String> = Vec::new();
    for (i, w) in instruction.split_whitespace().enumerate() {
        let bare: String = w.chars().filter(|c| c.is_alphanumeric()).collect();
        let tail: String =
            w.chars().rev().take_while(|c| !c.is_alphanumeric()).collect::<Vec<_>>().into_iter().rev().collect();
        match vocab::base_form(&bare) {
            Some(base) if vocab::verb(&bare).is_some() => out.push(format!("{base}{tail}")),
            _ if i == 0 => out.push(w.to_lowercase()),
            _ => out.push(w.to_string()),
        }
    }
    out.join(" ").trim_end_matches(['.', '!', ' ']).to_string()
}

/// A prompt split into the scene it describes and the task it asks for.
#[derive(Debug, Clone, PartialEq)]
pub struct SplitPrompt {
    /// The scene, with every thing the task names (a thing named only in the task is
    /// added: "a Panda sorting the cubes into the bins" makes cubes and bins).
    pub scene: String,
    /// The instruction, as the prompt words it.
    pub instruction: String,
}

/// Splits a prompt that asks for a task ("... that puts the mug in the sink", "... sorting
/// the cubes into the bins", "... . Put the red cube in the bowl"); `None` when it asks
/// for none.
pub fn split_prompt(prompt: &str) -> Option<SplitPrompt> {
    // A robot named in brackets ("(Panda)", "[robot: UR5e]") is part of the scene wherever
    // it stands; the brackets go.
    let (prompt, robots) = lift_bracketed_robots(prompt);
    let prompt = prompt.as_str();
    let t = words::tokens(prompt);
    let start = words::task_start(&t)?;
    // The same clause in the prompt's own text: find the verb's word there.
    let verb = &t[start];
    let lower = prompt.to_lowercase();
    let mut from = 0;
    let mut cut = None;
    let occurrences = t[..start].iter().filter(|w| *w == verb).count();
    for _ in 0..=occurrences {
        let i = find_word(&lower[from..], verb)? + from;
        cut = Some(i);
        from = i + verb.len();
    }
    let cut = cut?;
    let instruction = prompt[cut..].trim().trim_end_matches(|c: char| c.is_whitespace() || words::breaks_clause(c));
    let instruction = instruction.to_string();
    let head = prompt[..cut].trim_start_matches(|c: char| c.is_whitespace() || words::breaks_clause(c));
    let mut scene = trim_scene_tail(head);
    // A robot the instruction names as its instrument ("… with the Franka", "using a
    // Kinova Gen3") is the scene's too.
    let mut robots = robots;
    robots.extend(robots_named(&instruction));
    for r in robots {
        let named = words::tokens(&scene).iter().any(|w| words::tokens(&r).contains(w));
        if !named {
            scene = if scene.is_empty() { format!("a {r}") } else { format!("{scene} and a {r}") };
        }
    }
    let missing = task_things_missing_from(&scene, &instruction);
    // Things to handle need something to stand on within an arm's reach: a table, when
    // the scene names no work surface.
    let surface = if names_a_surface(&scene) { "" } else { " on a table" };
    if !missing.is_empty() {
        scene = format!("{scene}{surface} with {}", join_and(&missing));
    } else if !surface.is_empty() {
        scene = format!("{scene}{surface}");
    }
    Some(SplitPrompt { scene, instruction })
}

/// The scene words before a task clause without what joined them to it: trailing
/// punctuation, dashes, brackets and linking words ("… a bowl — ", "… a Panda that",
/// "… Task:").
fn trim_scene_tail(scene: &str) -> String {
    let mut s = scene.to_string();
    loop {
        let t = s.trim_end_matches(|c: char| c.is_whitespace() || c == '-' || words::breaks_clause(c)).to_string();
        let lower = t.to_lowercase();
        let tail = [" that", " which", " who", " to", " and", " then", " task", " goal", " instruction"]
            .iter()
            .find(|w| lower.ends_with(*w) || lower == w.trim_start());
        match tail {
            Some(w) => s = t[..t.len() - w.trim_start().len()].to_string(),
            None => return t,
        }
    }
}

/// Bracketed groups that name a robot, taken out of the prompt: the prompt without them
/// and the robots' words ("UR5e" from "[robot: UR5e]").
/// The robot models a text names by model ("Franka", "Kinova Gen3", "UR5e"), each with a
/// model number that follows its name; a bare "robot" or "arm" names none.
fn robots_named(text: &str) -> Vec<String> {
    let t = words::tokens(text);
    let mut out = Vec::new();
    for (i, w) in t.iter().enumerate() {
        if matches!(w.as_str(), "robot" | "robots" | "arm" | "arms")
            || !matches!(sw_planner::vocab::noun(w), sw_planner::vocab::Noun::Robot { .. })
        {
            continue;
        }
        let mut name = w.clone();
        if let Some(next) = t.get(i + 1).filter(|n| n.chars().any(|c| c.is_ascii_digit())) {
            name = format!("{name} {next}");
        }
        if !out.contains(&name) {
            out.push(name);
        }
    }
    out
}

fn lift_bracketed_robots(prompt: &str) -> (String, Vec<String>) {
    let mut out = String::with_capacity(prompt.len());
    let mut robots = Vec::new();
    let mut rest = prompt;
    while let Some(open) = rest.find(['(', '[']) {
        let close_char = if rest[open..].starts_with('(') { ')' } else { ']' };
        let Some(len) = rest[open + 1..].find(close_char) else { break };
        let inner = &rest[open + 1..open + 1 + len];
        let t = words::tokens(inner);
        let names_robot = t.iter().any(|w| matches!(sw_planner::vocab::noun(w), sw_planner::vocab::Noun::Robot { .. }));
        let robot: Vec<String> = t
            .into_iter()
            .filter(|w| !matches!(w.as_str(), "," | "robot" | "arm" | "by" | "using" | "with" | "the" | "a" | "an"))
            .collect();
        out.push_str(&rest[..open]);
        if !names_robot || robot.is_empty() {
            out.push_str(&rest[open..open + 2 + len]);
        } else {
            // The group is a clause break where it stood.
            out.push_str(", ");
            robots.push(robot.join(" "));
        }
        rest = &rest[open + 2 + len..];
    }
    out.push_str(rest);
    (out, robots)
}

/// The byte index of `word` as a whole word in `text`.
fn find_word(text: &str, word: &str) -> Option<usize> {
    let mut from = 0;
    while let Some(i) = text[from..].find(word).map(|i| i + from) {
        let before = text[..i].chars().last().is_none_or(|c| !c.is_alphanumeric());
        let after = text[i + word.len()..].chars().next().is_none_or(|c| !c.is_alphanumeric());
        if before && after {
            return Some(i);
        }
        from = i + word.len();
    }
    None
}

/// Whether the scene words name a work surface things can stand on.
fn names_a_surface(scene: &str) -> bool {
    let t = words::tokens(scene);
    (0..t.len()).any(|i| {
        [t[i].clone(), t.get(i + 1).map_or(String::new(), |n| format!("{} {n}", t[i]))].iter().any(|p| {
            matches!(sw_planner::vocab::noun(p), sw_planner::vocab::Noun::Category(c) if vocab::SURFACES.contains(&c))
        })
    })
}

fn join_and(items: &[String]) -> String {
    match items {
        [] => String::new(),
        [one] => one.clone(),
        [rest @ .., last] => format!("{} and {last}", rest.join(", ")),
    }
}

/// The things an instruction names that the scene words do not, as phrases the planner
/// reads as new objects ("3 cubes", "a red cube").
fn task_things_missing_from(scene: &str, instruction: &str) -> Vec<String> {
    let Ok(clauses) = words::read(instruction) else { return Vec::new() };
    let scene_categories: Vec<&'static str> = words::tokens(scene)
        .windows(2)
        .flat_map(|w| [w[0].clone(), format!("{} {}", w[0], w[1]), w[1].clone()])
        .filter_map(|p| match sw_planner::vocab::noun(&p) {
            sw_planner::vocab::Noun::Category(c) => Some(c),
            _ => None,
        })
        .chain(words::tokens(scene).iter().filter_map(|w| match sw_planner::vocab::noun(w) {
            sw_planner::vocab::Noun::Category(c) => Some(c),
            _ => None,
        }))
        .collect();
    let mut out: Vec<String> = Vec::new();
    let mut seen: Vec<&'static str> = Vec::new();
    for c in &clauses {
        for np in c.subjects.iter().chain(c.target.iter()) {
            let sw_planner::vocab::Noun::Category(cat) = sw_planner::vocab::noun(&np.text) else { continue };
            if scene_categories.contains(&cat) || seen.contains(&cat) {
                continue;
            }
            seen.push(cat);
            out.push(if np.every { format!("3 {}", np.text) } else { format!("a {}", np.text) });
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_prompt_splits_at_its_task_clause() {
        let s = split_prompt("a Panda on a table that puts the red cube in the bowl").unwrap_or_else(|| panic!());
        assert_eq!(s.instruction, "puts the red cube in the bowl");
        assert_eq!(s.scene, "a Panda on a table with a red cube and a bowl");
        let s = split_prompt("A UR5e sorting the cubes into the bins.").unwrap_or_else(|| panic!());
        assert_eq!(s.instruction, "sorting the cubes into the bins");
        assert_eq!(s.scene, "A UR5e on a table with 3 cubes and 3 bins");
        let s = split_prompt("a kitchen with a mug and a sink and a Panda. Put the mug in the sink!")
            .unwrap_or_else(|| panic!());
        assert_eq!(s.instruction, "Put the mug in the sink");
        // A kitchen names no work surface (a sink is not one): the things stand on a table.
        assert_eq!(s.scene, "a kitchen with a mug and a sink and a Panda on a table");
        // No task: a loading dock is not "load", a set of plates is not "set".
        assert_eq!(split_prompt("a warehouse with a loading dock and a set of plates on a table"), None);
        assert_eq!(split_prompt("a UR5e on a table next to two bins"), None);
        let s = split_prompt("a UR5e on a table sorting the cubes into the bins").unwrap_or_else(|| panic!());
        assert_eq!(
            (s.scene.as_str(), s.instruction.as_str()),
            ("a UR5e on a table with 3 cubes and 3 bins", "sorting the cubes into the bins")
        );
        // A machine doing something is a scene, not a task: no robot named before it.
        assert_eq!(split_prompt("a warehouse with a conveyor moving boxes onto a pallet and a UR5e"), None);
        assert_eq!(imperative("sorting the cubes into the bins."), "sort the cubes into the bins");
        // The task after a dash, a colon or a label; the scene without the joint.
        for (prompt, scene) in [
            (
                "a UR5e on a bench with a tin and a crate — drop the tin into the crate",
                "a UR5e on a bench with a tin and a crate",
            ),
            (
                "a UR5e on a bench with a tin and a crate - drop the tin into the crate",
                "a UR5e on a bench with a tin and a crate",
            ),
            (
                "a UR5e on a bench with a tin and a crate: drop the tin into the crate",
                "a UR5e on a bench with a tin and a crate",
            ),
            (
                "a UR5e on a bench with a tin and a crate. Task: drop the tin into the crate.",
                "a UR5e on a bench with a tin and a crate",
            ),
        ] {
            let s = split_prompt(prompt).unwrap_or_else(|| panic!("{prompt}"));
            assert_eq!((s.scene.as_str(), s.instruction.as_str()), (scene, "drop the tin into the crate"), "{prompt}");
        }
        // A robot in brackets is the scene's, wherever it stands, and never part of the task.
        for prompt in [
            "a bench with a tin and a crate. Drop the tin into the crate (Kinova Gen3)",
            "[robot: Kinova Gen3] a bench with a tin and a crate; drop the tin into the crate",
            "a bench with a tin and a crate (Kinova Gen3) - drop the tin into the crate",
        ] {
            let s = split_prompt(prompt).unwrap_or_else(|| panic!("{prompt}"));
            assert_eq!(s.instruction.to_lowercase(), "drop the tin into the crate", "{prompt}");
            assert!(s.scene.to_lowercase().contains("kinova gen3"), "{prompt}: {}", s.scene);
            assert!(!s.scene.contains(['(', '[']), "{prompt}: {}", s.scene);
        }
        // A robot the instruction does the task with is the scene's too.
        for (prompt, robot) in [
            ("Lift the cube 10 cm off the table with the Franka", "franka"),
            ("pick the yellow block up off the table and put it on the tray, using a kinova gen3", "kinova gen3"),
        ] {
            let s = split_prompt(prompt).unwrap_or_else(|| panic!("{prompt}"));
            assert!(s.scene.to_lowercase().contains(robot), "{prompt}: {}", s.scene);
        }
        let s = split_prompt("a Panda on a table with a mug. Lift the mug with the robot").unwrap_or_else(|| panic!());
        assert_eq!(s.scene, "a Panda on a table with a mug");
        // Brackets that name no robot stay in the scene's words.
        let s = split_prompt("a bench with a tin (empty) and a crate. Drop the tin into the crate")
            .unwrap_or_else(|| panic!());
        assert!(s.scene.contains("(empty)"), "{}", s.scene);
        // Opening and closing parts are tasks too, behind a polite wrapper or not.
        for (prompt, instruction) in [
            ("a UR5e on a table next to a cabinet with a drawer. Close the drawer", "Close the drawer"),
            ("a Panda next to a filing cabinet. Please open the top drawer!", "Please open the top drawer"),
            ("a kitchen with a stove and a Panda; turn on the stove", "turn on the stove"),
        ] {
            let s = split_prompt(prompt).unwrap_or_else(|| panic!("{prompt}"));
            assert_eq!(s.instruction, instruction, "{prompt}");
        }
        assert_eq!(imperative("Put the mug in the sink"), "put the mug in the sink");
        assert_eq!(
            imperative("picks up the red cube and places it in the bowl"),
            "pick up the red cube and place it in the bowl"
        );
    }
}
