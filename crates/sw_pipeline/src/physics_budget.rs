//! `--physics mjx`: after the package is written, MJX's contact limits are measured on it
//! in MuJoCo (`sw_sim::contact_budget`) and written into its `<custom>` numerics
//! (`sw_mjcf::physics::with_contact_budget`), so that big scenes stay steppable in MJX.
//! Native MuJoCo ignores the numerics: the verification that follows is unchanged.

use sw_plan::{LaidOutScene, ScenePlan};

use crate::PipelineError;
use crate::package::Staging;

/// Measures and writes the budget; what was written, in words.
pub(crate) fn write_budget(
    staging: &Staging,
    files: &mut sw_mjcf::SceneFiles,
    plan: &ScenePlan,
    layout: &LaidOutScene,
) -> Result<String, PipelineError> {
    let b = sw_sim::contact_budget(&staging.path().join("scene.xml"))
        .map_err(|e| PipelineError::Internal(format!("measuring the MJX contact budget: {e}")))?;
    let add = |xml: &str| {
        sw_mjcf::physics::with_contact_budget(xml, b.max_geom_pairs, b.max_contact_points)
            .map_err(|e| PipelineError::Internal(format!("writing the MJX contact budget: {e}")))
    };
    files.scene_xml = add(&files.scene_xml)?;
    files.scene_only_xml = add(&files.scene_only_xml)?;
    staging.write_scene(files, plan, layout)?;
    Ok(format!(
        "physics mjx: MJX considers at most {} pairs per pair type (of {} that may collide; {} within {} m at home) and {} contacts (at most {} in the first 0.2 s): <custom> max_geom_pairs, max_contact_points",
        b.max_geom_pairs,
        b.candidate_pairs,
        b.near_pairs,
        sw_sim::NEAR_M,
        b.max_contact_points,
        b.contacts
    ))
}
