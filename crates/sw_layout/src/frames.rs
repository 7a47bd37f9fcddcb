//! Quarter-turn poses on the floor plan, and moving boxes between frames.

use std::f64::consts::{FRAC_PI_2, PI};

use sw_geom::{Aabb, Pose};

/// The four yaws objects are placed at.
pub(crate) const QUARTER_TURNS: [f64; 4] = [0.0, FRAC_PI_2, PI, -FRAC_PI_2];

/// A planar pose: position of the asset origin and a yaw.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Spot {
    pub x: f64,
    pub y: f64,
    pub z: f64,
    pub yaw: f64,
}

impl Spot {
    pub fn new(x: f64, y: f64, z: f64, yaw: f64) -> Self {
        Self { x, y, z, yaw: normalize_yaw(yaw) }
    }

    pub fn pose(&self) -> Pose {
        Pose::from_pos_yaw([self.x, self.y, self.z], self.yaw)
    }

    /// Maps a point of the object frame to the world.
    pub fn apply(&self, p: [f64; 3]) -> [f64; 3] {
        let (s, c) = self.yaw.sin_cos();
        [self.x + c * p[0] - s * p[1], self.y + s * p[0] + c * p[1], self.z + p[2]]
    }

    /// Boxes given in the object frame, in the world (exact for quarter turns).
    pub fn boxes(&self, local: &[Aabb]) -> Vec<Aabb> {
        local.iter().map(|b| b.transformed(&self.pose())).collect()
    }
}

/// Yaw in (-π, π], with quarter turns snapped exactly.
pub(crate) fn normalize_yaw(yaw: f64) -> f64 {
    let mut y = yaw % (2.0 * PI);
    if y <= -PI {
        y += 2.0 * PI;
    } else if y > PI {
        y -= 2.0 * PI;
    }
    for q in [0.0, FRAC_PI_2, PI, -FRAC_PI_2] {
        if (y - q).abs() < 1e-9 {
            return q;
        }
    }
    if (y + PI).abs() < 1e-9 { PI } else { y }
}

/// The yaw that turns an object's front (+Y) towards the direction (dx, dy), snapped to
/// a quarter turn.
pub(crate) fn yaw_facing(dx: f64, dy: f64) -> f64 {
    // Front +Y rotated by yaw is (-sin yaw, cos yaw).
    if dx.abs() > dy.abs() {
        if dx > 0.0 { -FRAC_PI_2 } else { FRAC_PI_2 }
    } else if dy >= 0.0 {
        0.0
    } else {
        PI
    }
}

/// The yaw that turns a robot's working direction (+X) towards (dx, dy), snapped.
pub(crate) fn robot_yaw_facing(dx: f64, dy: f64) -> f64 {
    if dx.abs() >= dy.abs() {
        if dx >= 0.0 { 0.0 } else { PI }
    } else if dy > 0.0 {
        FRAC_PI_2
    } else {
        -FRAC_PI_2
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn facing_turns_the_front_the_right_way() {
        for (dx, dy) in [(1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (0.0, -1.0)] {
            let yaw = yaw_facing(dx, dy);
            let front = Spot::new(0.0, 0.0, 0.0, yaw).apply([0.0, 1.0, 0.0]);
            assert!((front[0] - dx).abs() < 1e-9 && (front[1] - dy).abs() < 1e-9, "{dx} {dy} -> {front:?}");
            let ryaw = robot_yaw_facing(dx, dy);
            let fwd = Spot::new(0.0, 0.0, 0.0, ryaw).apply([1.0, 0.0, 0.0]);
            assert!((fwd[0] - dx).abs() < 1e-9 && (fwd[1] - dy).abs() < 1e-9);
        }
    }
}
