//! Industrial rules as data: `rules/profiles.json` names each rule with its published
//! number and standard, and groups them into profiles per room kind. The solver keeps the
//! space the rules ask for (working space in front of electrical equipment, gaps around
//! machines, egress routes, the robot's restricted space off the exit route) and
//! [`check`] measures the final layout against them.

mod check;
mod egress;

use std::collections::BTreeMap;
use std::sync::OnceLock;

use serde::Deserialize;

pub use check::check;
pub(crate) use egress::EgressGrid;

/// One rule, as written in `rules/profiles.json`.
#[derive(Debug, Clone, Deserialize, PartialEq)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum RuleDef {
    /// Every working front must connect to the door by a route at least this wide.
    Egress { width_m: f64, standard: String },
    /// Keep-clear space around objects carrying all of `tags`.
    Clearance {
        tags: Vec<String>,
        #[serde(default)]
        exclude_tags: Vec<String>,
        #[serde(default)]
        front_m: f64,
        #[serde(default)]
        back_m: f64,
        #[serde(default)]
        sides_m: f64,
        #[serde(default)]
        min_width_m: f64,
        #[serde(default)]
        height_m: Option<f64>,
        standard: String,
    },
    /// An arm's reach (plus a margin) stays off the doorway.
    RobotSpace { margin_m: f64, standard: String },
    /// Guards (objects with all of `tags`) stand this far outside an arm's reach.
    FenceDistance { tags: Vec<String>, distance_m: f64, standard: String },
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RuleBook {
    #[allow(dead_code)]
    note: String,
    rules: BTreeMap<String, RuleDef>,
    profiles: BTreeMap<String, Vec<String>>,
}

/// The rules that apply to one scene.
#[derive(Debug, Clone, PartialEq)]
pub struct Profile {
    pub name: String,
    pub rules: Vec<(String, RuleDef)>,
}

/// The keep-clear depths around one object and the rule behind each side.
#[derive(Debug, Clone, Default, PartialEq)]
pub(crate) struct Clearance {
    pub front: f64,
    pub back: f64,
    pub sides: f64,
    pub min_width: f64,
    pub rule_front: Option<String>,
    pub rule_back: Option<String>,
    pub rule_sides: Option<String>,
}

impl Clearance {
    pub fn is_empty(&self) -> bool {
        self.front <= 0.0 && self.back <= 0.0 && self.sides <= 0.0
    }
}

fn book() -> &'static RuleBook {
    static BOOK: OnceLock<RuleBook> = OnceLock::new();
    BOOK.get_or_init(|| {
        // The file is part of the crate and checked by a test; a broken edit fails the build's tests.
        serde_json::from_str(include_str!("../../rules/profiles.json")).unwrap_or_else(|_| RuleBook {
            note: String::new(),
            rules: BTreeMap::new(),
            profiles: BTreeMap::new(),
        })
    })
}

/// Names of every profile.
pub fn profile_names() -> Vec<String> {
    book().profiles.keys().cloned().collect()
}

/// The named profile, or `None` when there is no such profile.
pub fn profile(name: &str) -> Option<Profile> {
    let ids = book().profiles.get(name)?;
    let rules = ids.iter().filter_map(|id| book().rules.get(id).map(|r| (id.clone(), r.clone()))).collect();
    Some(Profile { name: name.to_string(), rules })
}

impl Profile {
    /// The egress rule, if the profile has one.
    pub fn egress(&self) -> Option<(&str, f64, &str)> {
        self.rules.iter().find_map(|(id, r)| match r {
            RuleDef::Egress { width_m, standard } => Some((id.as_str(), *width_m, standard.as_str())),
            _ => None,
        })
    }

    pub fn robot_space(&self) -> Option<(&str, f64, &str)> {
        self.rules.iter().find_map(|(id, r)| match r {
            RuleDef::RobotSpace { margin_m, standard } => Some((id.as_str(), *margin_m, standard.as_str())),
            _ => None,
        })
    }

    pub fn standard_of(&self, rule: &str) -> &str {
        self.rules.iter().find(|(id, _)| id == rule).map_or("", |(_, r)| match r {
            RuleDef::Egress { standard, .. }
            | RuleDef::Clearance { standard, .. }
            | RuleDef::RobotSpace { standard, .. }
            | RuleDef::FenceDistance { standard, .. } => standard.as_str(),
        })
    }

    /// The guard-distance rule, if the profile has one: (id, tags, distance, standard).
    pub fn fence_distance(&self) -> Option<(&str, &[String], f64, &str)> {
        self.rules.iter().find_map(|(id, r)| match r {
            RuleDef::FenceDistance { tags, distance_m, standard } => {
                Some((id.as_str(), tags.as_slice(), *distance_m, standard.as_str()))
            }
            _ => None,
        })
    }

    /// The keep-clear space the profile asks around an object with these tags.
    pub(crate) fn clearance(&self, tags: &[String]) -> Clearance {
        let mut c = Clearance::default();
        for (id, r) in &self.rules {
            let RuleDef::Clearance { tags: need, exclude_tags, front_m, back_m, sides_m, min_width_m, .. } = r else {
                continue;
            };
            let has = |t: &String| tags.iter().any(|x| x == t);
            if !need.iter().all(has) || exclude_tags.iter().any(has) {
                continue;
            }
            if *front_m > c.front {
                c.front = *front_m;
                c.rule_front = Some(id.clone());
            }
            if *back_m > c.back {
                c.back = *back_m;
                c.rule_back = Some(id.clone());
            }
            if *sides_m > c.sides {
                c.sides = *sides_m;
                c.rule_sides = Some(id.clone());
            }
            c.min_width = c.min_width.max(*min_width_m);
        }
        c
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_rule_book_parses_and_every_profile_names_real_rules() {
        let text = include_str!("../../rules/profiles.json");
        let b: RuleBook = serde_json::from_str(text).unwrap();
        assert!(!b.rules.is_empty());
        for (name, ids) in &b.profiles {
            for id in ids {
                assert!(b.rules.contains_key(id), "profile {name} names unknown rule {id}");
            }
            let p = profile(name).unwrap();
            assert!(p.egress().is_some(), "profile {name} has no egress rule");
        }
        // Every room kind's profile exists.
        for k in sw_plan::RoomKind::ALL {
            assert!(profile(k.rules_profile()).is_some(), "no profile '{}' for {k:?}", k.rules_profile());
        }
    }

    #[test]
    fn electrical_equipment_gets_the_nec_working_space() {
        let p = profile("general").unwrap();
        let c = p.clearance(&["electrical".to_string(), "tall".to_string()]);
        assert_eq!(c.front, 0.9);
        assert_eq!(c.min_width, 0.76);
        assert_eq!(c.rule_front.as_deref(), Some("nec_working_space"));
        assert!(p.clearance(&["furniture".to_string()]).is_empty());
    }
}
