//! Validation of plans, with errors that name the field (`objects[2].count`).
//!
//! Plans come from the offline planner, from an LLM, or from a user's JSON file; all go
//! through [`ScenePlan::from_json`] or [`ScenePlan::validate`] before any stage uses them.

use std::collections::BTreeSet;
use std::fmt;

use crate::{LaidOutScene, Mount, RelationKind, SCHEMA_VERSION, ScenePlan};

/// Largest room side the pipeline accepts, m.
pub const MAX_ROOM_SIDE: f64 = 500.0;
/// Largest count of one object group.
pub const MAX_GROUP_COUNT: u32 = 5000;
/// Largest count of one robot group (and of all robots in a scene).
pub const MAX_ROBOT_COUNT: u32 = 16;

/// One problem, located by a JSON path.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FieldError {
    /// JSON path of the field, e.g. `relations[1].target`.
    pub path: String,
    pub message: String,
}

impl fmt::Display for FieldError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.path, self.message)
    }
}

/// Every problem found in a document, in document order.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ValidationErrors(pub Vec<FieldError>);

impl fmt::Display for ValidationErrors {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let parts: Vec<String> = self.0.iter().map(ToString::to_string).collect();
        write!(f, "{}", parts.join("; "))
    }
}

impl std::error::Error for ValidationErrors {}

/// Why a plan document was rejected.
#[derive(Debug, thiserror::Error)]
pub enum PlanError {
    /// Not JSON, or JSON of the wrong shape; `path` names the field.
    #[error("{path}: {message}")]
    Shape { path: String, message: String },
    #[error("invalid plan: {0}")]
    Invalid(#[from] ValidationErrors),
}

impl ScenePlan {
    /// Parses and validates a plan document.
    pub fn from_json(text: &str) -> Result<ScenePlan, PlanError> {
        let de = &mut serde_json::Deserializer::from_str(text);
        let plan: ScenePlan = serde_path_to_error::deserialize(de).map_err(|e| {
            let path = e.path().to_string();
            let inner = e.into_inner();
            PlanError::Shape { path: if path == "." { "$".to_string() } else { path }, message: inner.to_string() }
        })?;
        plan.validate()?;
        Ok(plan)
    }

    /// Checks everything serde cannot: ranges, finiteness, unique ids and references.
    pub fn validate(&self) -> Result<(), ValidationErrors> {
        let mut errs = Vec::new();
        let mut err = |path: String, message: String| errs.push(FieldError { path, message });

        if self.schema_version != SCHEMA_VERSION {
            err(
                "schema_version".into(),
                format!("is {}, this build reads version {SCHEMA_VERSION}", self.schema_version),
            );
        }
        let size = &self.room.size;
        for (name, v, lo) in [("width", size.width, 0.5), ("depth", size.depth, 0.5), ("height", size.height, 1.0)] {
            if !v.is_finite() || v < lo || v > MAX_ROOM_SIDE {
                err(format!("room.size.{name}"), format!("must be between {lo} and {MAX_ROOM_SIDE} m, got {v}"));
            }
        }
        if self.rules_profile.trim().is_empty() {
            err("rules_profile".into(), "must not be empty".into());
        }

        let mut ids = BTreeSet::new();
        for (i, o) in self.objects.iter().enumerate() {
            let at = |f: &str| format!("objects[{i}].{f}");
            if o.id.trim().is_empty() {
                err(at("id"), "must not be empty".into());
            } else if !ids.insert(o.id.as_str()) {
                err(at("id"), format!("'{}' is used twice", o.id));
            }
            if o.category.trim().is_empty() {
                err(at("category"), "must not be empty".into());
            }
            if o.count == 0 || o.count > MAX_GROUP_COUNT {
                err(at("count"), format!("must be between 1 and {MAX_GROUP_COUNT}, got {}", o.count));
            }
            if let Some(c) = &o.color
                && c.rgba.iter().any(|v| !v.is_finite() || !(0.0..=1.0).contains(v))
            {
                err(at("color.rgba"), format!("components must be in 0..1, got {:?}", c.rgba));
            }
            for (name, v) in o.size.explicit.stated() {
                if !v.is_finite() || v <= 0.0 {
                    err(at(&format!("size.explicit.{name}")), format!("must be a positive length, got {v}"));
                }
            }
            match (&o.proxy, o.category == "proxy") {
                (Some(p), true) => {
                    for (name, v) in [("width", p.size.width), ("depth", p.size.depth), ("height", p.size.height)] {
                        if !v.is_finite() || v <= 0.0 {
                            err(at(&format!("proxy.size.{name}")), format!("must be a positive length, got {v}"));
                        }
                    }
                    if p.label.trim().is_empty() {
                        err(at("proxy.label"), "must not be empty".into());
                    }
                }
                (None, true) => err(at("proxy"), "is required when category is 'proxy'".into()),
                (Some(_), false) => err(at("proxy"), "is only allowed when category is 'proxy'".into()),
                (None, false) => {}
            }
        }

        let mut robot_ids = BTreeSet::new();
        for (i, r) in self.robots.iter().enumerate() {
            let at = |f: &str| format!("robots[{i}].{f}");
            if r.id.trim().is_empty() {
                err(at("id"), "must not be empty".into());
            } else if ids.contains(r.id.as_str()) || !robot_ids.insert(r.id.as_str()) {
                err(at("id"), format!("'{}' is used twice", r.id));
            }
            if r.model.trim().is_empty() {
                err(at("model"), "must not be empty".into());
            }
            if r.count == 0 || r.count > MAX_ROBOT_COUNT {
                err(at("count"), format!("must be between 1 and {MAX_ROBOT_COUNT}, got {}", r.count));
            }
            if let Mount::OnSurface { target } = &r.mount
                && !ids.contains(target.as_str())
            {
                err(at("mount.target"), format!("refers to unknown object group '{target}'"));
            }
            if let Some(near) = &r.near
                && !ids.contains(near.as_str())
            {
                err(at("near"), format!("refers to unknown object group '{near}'"));
            }
        }

        for (i, rel) in self.relations.iter().enumerate() {
            // Robots may be the subject of placement relations ("a TurtleBot between the
            // racks") and of reach, and the target of relations that stand things near
            // them ("screens around the robot"); stacks, loads, supports are objects'.
            let robot_subject = robot_ids.contains(rel.subject.as_str());
            let object_only = matches!(
                rel.kind,
                RelationKind::On { .. }
                    | RelationKind::Under { .. }
                    | RelationKind::Stacked { .. }
                    | RelationKind::Inside { .. }
                    | RelationKind::SetInto { .. }
                    | RelationKind::BackToBack
                    | RelationKind::OnOppositeWalls { .. }
                    | RelationKind::Loaded { .. }
                    | RelationKind::FullOf { .. }
                    | RelationKind::Leaning { .. }
                    | RelationKind::EachWith { .. }
                    | RelationKind::InRow
                    | RelationKind::InRows { .. }
                    | RelationKind::InAisles
                    | RelationKind::FacingEachOther
                    | RelationKind::OnTwoWalls
            );
            let robot_only = matches!(rel.kind, RelationKind::Reach { .. });
            if robot_only && !robot_subject {
                err(
                    format!("relations[{i}].subject"),
                    format!("'{}' is not a robot group: only arms reach", rel.subject),
                );
            } else if !ids.contains(rel.subject.as_str()) && !robot_subject {
                err(format!("relations[{i}].subject"), format!("refers to unknown object group '{}'", rel.subject));
            } else if robot_subject && object_only {
                err(
                    format!("relations[{i}].relation"),
                    format!(
                        "'{}' is a relation of object groups, and '{}' is a robot group",
                        rel.kind.name(),
                        rel.subject
                    ),
                );
            }
            let robot_targets = matches!(
                rel.kind,
                RelationKind::Around { .. }
                    | RelationKind::NextTo { .. }
                    | RelationKind::Near { .. }
                    | RelationKind::InFrontOf { .. }
                    | RelationKind::Behind { .. }
                    | RelationKind::Between { .. }
                    | RelationKind::EachWith { .. }
                    | RelationKind::Facing { .. }
                    | RelationKind::OnEachSideOf { .. }
                    | RelationKind::AtEndOf { .. }
            );
            let fields: Vec<(&str, &str)> = match &rel.kind {
                RelationKind::Between { first, second } => {
                    vec![("first", first), ("second", second)]
                }
                other => other.targets().into_iter().map(|t| ("target", t)).collect(),
            };
            for (field, target) in fields {
                let known = ids.contains(target) || (robot_targets && robot_ids.contains(target));
                if !known {
                    err(format!("relations[{i}].{field}"), format!("refers to unknown object group '{target}'"));
                } else if target == rel.subject {
                    err(format!("relations[{i}].{field}"), format!("'{target}' cannot be related to itself"));
                }
            }
        }

        if let Some(a) = &self.anomaly {
            if !a.rate.is_finite() || !(0.0..=1.0).contains(&a.rate) {
                err("anomaly.rate".into(), format!("must be in 0..1, got {}", a.rate));
            }
            if a.kinds.is_empty() {
                err("anomaly.kinds".into(), "must name at least one kind".into());
            }
        }

        if errs.is_empty() { Ok(()) } else { Err(ValidationErrors(errs)) }
    }
}

impl LaidOutScene {
    /// Checks names are unique and every pose is finite.
    pub fn validate(&self) -> Result<(), ValidationErrors> {
        let mut errs = Vec::new();
        let mut names = BTreeSet::new();
        for (i, o) in self.objects.iter().enumerate() {
            if !names.insert(o.name.as_str()) {
                errs.push(FieldError {
                    path: format!("objects[{i}].name"),
                    message: format!("'{}' is used twice", o.name),
                });
            }
            if o.pos.iter().chain([&o.yaw]).chain(o.size.iter()).any(|v| !v.is_finite()) {
                errs.push(FieldError { path: format!("objects[{i}]"), message: "pose and size must be finite".into() });
            }
        }
        for (i, r) in self.robots.iter().enumerate() {
            if !names.insert(r.name.as_str()) {
                errs.push(FieldError {
                    path: format!("robots[{i}].name"),
                    message: format!("'{}' is used twice", r.name),
                });
            }
            if r.pos.iter().chain([&r.yaw]).any(|v| !v.is_finite()) {
                errs.push(FieldError { path: format!("robots[{i}]"), message: "pose must be finite".into() });
            }
        }
        if errs.is_empty() { Ok(()) } else { Err(ValidationErrors(errs)) }
    }
}
