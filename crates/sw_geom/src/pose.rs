//! Rigid poses: a position and a unit quaternion `[w, x, y, z]` (MuJoCo's order).

use serde::{Deserialize, Serialize};

/// A rigid transform: rotate by `quat`, then translate by `pos`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Pose {
    pub pos: [f64; 3],
    /// Unit quaternion, `[w, x, y, z]`.
    pub quat: [f64; 4],
}

impl Default for Pose {
    fn default() -> Self {
        Self::IDENTITY
    }
}

impl Pose {
    pub const IDENTITY: Pose = Pose { pos: [0.0; 3], quat: [1.0, 0.0, 0.0, 0.0] };

    pub fn from_pos(pos: [f64; 3]) -> Self {
        Self { pos, quat: [1.0, 0.0, 0.0, 0.0] }
    }

    /// A position and a rotation about +Z by `yaw` radians.
    pub fn from_pos_yaw(pos: [f64; 3], yaw: f64) -> Self {
        Self { pos, quat: quat_from_yaw(yaw) }
    }

    /// A position and a rotation of `angle` radians about the unit `axis`.
    pub fn from_pos_axis_angle(pos: [f64; 3], axis: [f64; 3], angle: f64) -> Self {
        let (s, c) = (angle * 0.5).sin_cos();
        Self { pos, quat: [c, axis[0] * s, axis[1] * s, axis[2] * s] }
    }

    /// Maps a point from this pose's frame into the parent frame.
    pub fn apply(&self, p: [f64; 3]) -> [f64; 3] {
        let r = rotate(self.quat, p);
        [r[0] + self.pos[0], r[1] + self.pos[1], r[2] + self.pos[2]]
    }

    /// `self ∘ child`: the pose of `child` (given in this frame) in the parent frame.
    pub fn compose(&self, child: &Pose) -> Pose {
        Pose { pos: self.apply(child.pos), quat: quat_mul(self.quat, child.quat) }
    }

    /// True when the rotation is the identity (to 1e-12).
    pub fn is_unrotated(&self) -> bool {
        (self.quat[0].abs() - 1.0).abs() < 1e-12
    }
}

/// The quaternion of a rotation about +Z by `yaw` radians.
pub fn quat_from_yaw(yaw: f64) -> [f64; 4] {
    let (s, c) = (yaw * 0.5).sin_cos();
    [c, 0.0, 0.0, s]
}

/// Hamilton product `a * b`.
pub fn quat_mul(a: [f64; 4], b: [f64; 4]) -> [f64; 4] {
    [
        a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
        a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
        a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
        a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
    ]
}

/// Rotates `v` by the unit quaternion `q`.
pub fn rotate(q: [f64; 4], v: [f64; 3]) -> [f64; 3] {
    let [w, x, y, z] = q;
    // t = 2 * cross(q.xyz, v); v' = v + w * t + cross(q.xyz, t)
    let t = [2.0 * (y * v[2] - z * v[1]), 2.0 * (z * v[0] - x * v[2]), 2.0 * (x * v[1] - y * v[0])];
    [
        v[0] + w * t[0] + (y * t[2] - z * t[1]),
        v[1] + w * t[1] + (z * t[0] - x * t[2]),
        v[2] + w * t[2] + (x * t[1] - y * t[0]),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn yaw_quarter_turn_maps_x_to_y() {
        let p = Pose::from_pos_yaw([1.0, 2.0, 0.0], std::f64::consts::FRAC_PI_2);
        let q = p.apply([1.0, 0.0, 0.0]);
        assert!((q[0] - 1.0).abs() < 1e-12 && (q[1] - 3.0).abs() < 1e-12);
    }

    #[test]
    fn compose_matches_sequential_application() {
        let a = Pose::from_pos_axis_angle([0.3, -1.0, 2.0], [0.0, 1.0, 0.0], 0.7);
        let b = Pose::from_pos_yaw([0.1, 0.2, 0.3], -1.1);
        let p = [0.4, 0.5, -0.6];
        let direct = a.compose(&b).apply(p);
        let seq = a.apply(b.apply(p));
        for i in 0..3 {
            assert!((direct[i] - seq[i]).abs() < 1e-12);
        }
    }
}
