//! Rendering an episode's frames with MuJoCo's own renderer, offscreen (EGL; on a machine
//! without a GPU Mesa's software rasteriser): each recorded `qpos` is set, the kinematics
//! and camera poses computed, and every camera drawn. Only solved episodes are rendered,
//! from their recording, so a failed attempt costs no rendering.
//!
//! Shadows and multisampling are off: on a software rasteriser they cost most of a frame
//! and a policy's input does not need them.

use std::path::Path;

use mujoco_rs::prelude::*;
use mujoco_rs::renderer::MjRenderer;

use crate::ExpertError;

/// Takes one camera's frame: (camera index, RGB rows top to bottom).
pub type FrameSink<'a> = dyn FnMut(usize, &[u8]) -> Result<(), ExpertError> + 'a;

/// A camera of the scene and the name its images go under.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CameraSpec {
    /// The dataset's key (`front`, `wrist`).
    pub key: String,
    /// The MJCF camera (`front`, `panda_1_wrist`).
    pub camera: String,
}

/// Draws frames of one scene from several cameras.
#[derive(Debug)]
pub struct FrameRenderer {
    model: MjModel,
    renderer: MjRenderer,
    cameras: Vec<(String, usize)>,
    pub width: usize,
    pub height: usize,
}

fn render_error(e: impl std::fmt::Display) -> ExpertError {
    ExpertError::Render(e.to_string())
}

impl FrameRenderer {
    /// Loads `scene` for drawing (shadows off) and opens an offscreen context of
    /// `width` × `height`.
    pub fn new(scene: &Path, cameras: &[CameraSpec], width: usize, height: usize) -> Result<Self, ExpertError> {
        let mut model = MjModel::from_xml(scene).map_err(|e| ExpertError::Scene(e.to_string()))?;
        for s in model.light_castshadow_mut() {
            *s = false;
        }
        {
            let vis = model.vis_mut();
            vis.quality.offsamples = 0;
            vis.global.offwidth = vis.global.offwidth.max(width as i32);
            vis.global.offheight = vis.global.offheight.max(height as i32);
        }
        let mut ids = Vec::new();
        for c in cameras {
            let id = model.name_to_id(MjtObjBase::mjOBJ_CAMERA, &c.camera).ok_or_else(|| {
                ExpertError::Scene(format!("the scene has no camera '{}' (for the {} images)", c.camera, c.key))
            })?;
            ids.push((c.key.clone(), id));
        }
        let renderer = MjRenderer::builder()
            .width(width as u32)
            .height(height as u32)
            .build(&model)
            .map_err(|e| render_error(format!("no offscreen rendering context (EGL): {e}")))?;
        Ok(Self { model, renderer, cameras: ids, width, height })
    }

    pub fn camera_keys(&self) -> Vec<String> {
        self.cameras.iter().map(|(k, _)| k.clone()).collect()
    }

    /// Draws every camera for each `qpos`, handing `sink(camera index, rgb)` the pixels
    /// (rows top to bottom, RGB).
    pub fn render(&mut self, qposes: &[Vec<f64>], sink: &mut FrameSink<'_>) -> Result<(), ExpertError> {
        let mut data = self.model.make_data();
        let nq = self.model.ffi().nq as usize;
        for q in qposes {
            if q.len() != nq {
                return Err(ExpertError::Render(format!("a recorded state has {} positions, the scene {nq}", q.len())));
            }
            data.qpos_mut().copy_from_slice(q);
            data.kinematics();
            data.camlight();
            for (k, (_, cam)) in self.cameras.iter().enumerate() {
                self.renderer.set_camera(MjvCamera::new_fixed(*cam));
                self.renderer.sync_data(&mut data).map_err(render_error)?;
                self.renderer.render().map_err(render_error)?;
                let rgb = self.renderer.rgb_flat().ok_or_else(|| render_error("no RGB buffer"))?;
                sink(k, rgb)?;
            }
        }
        Ok(())
    }
}
