//! The pipeline's side of `--fill` (`sw_layout::fill` decides what goes where): which
//! level applies (the option, else the prompt's own words), the added objects joined to
//! the layout and the forged assets (so that the bridge writes them and verification
//! settles them with everything else), and the fill words taken off the planner's list
//! of words it did not understand once they were acted on. Laying the scene out again
//! (after a stack was shortened) fills it again from scratch, deterministically.

use std::collections::BTreeMap;

use sw_layout::fill::{FILL_GROUP, FillInput, FillLevel};
use sw_plan::{LaidOutScene, ScenePlan};

use crate::{Forged, ForgedObject, Options};

/// At most this many objects are added to one room: settling a scene costs time in its
/// free bodies and their contacts.
pub(crate) const MAX_ADDED: usize = 160;

/// The level that applies to this run.
pub(crate) fn level(plan: &ScenePlan, opts: &Options) -> FillLevel {
    opts.fill.unwrap_or_else(|| FillLevel::from_prompt(&plan.prompt).unwrap_or_default())
}

/// Removes what an earlier fill added, then fills `layout` at the run's level.
pub(crate) fn apply(plan: &mut ScenePlan, layout: &mut LaidOutScene, forged: &mut Forged, opts: &Options) {
    forged.objects.retain(|o| o.group != FILL_GROUP);
    layout.objects.retain(|o| !o.added);
    let level = level(plan, opts);
    if level == FillLevel::None {
        return;
    }
    let assets: BTreeMap<String, &sw_geom::Asset> = forged.objects.iter().map(|o| (o.name.clone(), &o.asset)).collect();
    let input = FillInput {
        prompt: &plan.prompt,
        room_kind: plan.room.kind,
        scene: layout,
        assets: &assets,
        robots: &forged.robots,
        seed: opts.seed,
        max_added: MAX_ADDED,
    };
    let outcome = sw_layout::fill::fill(&input, level);
    for w in outcome.warnings {
        if !layout.warnings.iter().any(|x| x.code == w.code) {
            layout.warnings.push(w);
        }
    }
    for a in outcome.added {
        forged.objects.push(ForgedObject {
            name: a.placed.name.clone(),
            group: FILL_GROUP.to_string(),
            category: a.placed.category.clone(),
            label: a.placed.label.clone(),
            asset: a.asset,
            tags: a.tags,
            carries_robot: None,
        });
        layout.objects.push(a.placed);
    }
    // The words that asked for it were understood after all.
    plan.understanding.not_understood.retain(|n| FillLevel::from_prompt(&n.text).is_none());
}
