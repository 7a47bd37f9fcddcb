//! The little linear algebra the expert needs: 3-vectors, row-major 3×3 rotations,
//! quaternions (w, x, y, z, MuJoCo's order) and a dense solve for the IK's normal equations.

pub(crate) type V3 = [f64; 3];
/// Row-major, as MuJoCo's `xmat`.
pub(crate) type M3 = [f64; 9];

pub(crate) fn add(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

pub(crate) fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

pub(crate) fn scale(a: V3, s: f64) -> V3 {
    [a[0] * s, a[1] * s, a[2] * s]
}

pub(crate) fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub(crate) fn cross(a: V3, b: V3) -> V3 {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

pub(crate) fn norm(a: V3) -> f64 {
    dot(a, a).sqrt()
}

/// Column `c` of a row-major matrix (the frame's axis `c` in world coordinates).
pub(crate) fn col(m: &M3, c: usize) -> V3 {
    [m[c], m[3 + c], m[6 + c]]
}

/// The matrix whose columns are `x`, `y`, `z`.
pub(crate) fn from_cols(x: V3, y: V3, z: V3) -> M3 {
    [x[0], y[0], z[0], x[1], y[1], z[1], x[2], y[2], z[2]]
}

pub(crate) fn mat_vec(m: &M3, v: V3) -> V3 {
    [
        m[0] * v[0] + m[1] * v[1] + m[2] * v[2],
        m[3] * v[0] + m[4] * v[1] + m[5] * v[2],
        m[6] * v[0] + m[7] * v[1] + m[8] * v[2],
    ]
}

pub(crate) fn mat_mul(a: &M3, b: &M3) -> M3 {
    let mut out = [0.0; 9];
    for r in 0..3 {
        for c in 0..3 {
            out[3 * r + c] = (0..3).map(|k| a[3 * r + k] * b[3 * k + c]).sum();
        }
    }
    out
}

pub(crate) fn transpose(m: &M3) -> M3 {
    [m[0], m[3], m[6], m[1], m[4], m[7], m[2], m[5], m[8]]
}

/// Rotation about z by `yaw`.
pub(crate) fn rot_z(yaw: f64) -> M3 {
    let (s, c) = yaw.sin_cos();
    [c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0]
}

/// Rotation by `angle` about the unit `axis` (Rodrigues).
pub(crate) fn rot_axis(axis: V3, angle: f64) -> M3 {
    let n = norm(axis).max(1e-12);
    let [x, y, z] = [axis[0] / n, axis[1] / n, axis[2] / n];
    let (s, c) = angle.sin_cos();
    let t = 1.0 - c;
    [
        t * x * x + c,
        t * x * y - s * z,
        t * x * z + s * y,
        t * x * y + s * z,
        t * y * y + c,
        t * y * z - s * x,
        t * x * z - s * y,
        t * y * z + s * x,
        t * z * z + c,
    ]
}

/// The rotation vector (axis × angle) taking `from` to `to`: log(to · fromᵀ).
pub(crate) fn rotation_error(to: &M3, from: &M3) -> V3 {
    let r = mat_mul(to, &transpose(from));
    let cos = ((r[0] + r[4] + r[8] - 1.0) * 0.5).clamp(-1.0, 1.0);
    let angle = cos.acos();
    let v = [r[7] - r[5], r[2] - r[6], r[3] - r[1]];
    let s = angle.sin();
    if angle < 1e-9 {
        return [0.0; 3];
    }
    if s.abs() < 1e-6 {
        // Half a turn: the axis from the symmetric part.
        let axis = [
            ((r[0] + 1.0) * 0.5).max(0.0).sqrt(),
            ((r[4] + 1.0) * 0.5).max(0.0).sqrt(),
            ((r[8] + 1.0) * 0.5).max(0.0).sqrt(),
        ];
        let axis = [axis[0], if r[1] < 0.0 { -axis[1] } else { axis[1] }, if r[2] < 0.0 { -axis[2] } else { axis[2] }];
        return scale(axis, angle);
    }
    scale(v, angle / (2.0 * s))
}

/// Row-major rotation of a unit quaternion (w, x, y, z).
pub(crate) fn quat_to_mat(q: [f64; 4]) -> M3 {
    let [w, x, y, z] = q;
    [
        1.0 - 2.0 * (y * y + z * z),
        2.0 * (x * y - w * z),
        2.0 * (x * z + w * y),
        2.0 * (x * y + w * z),
        1.0 - 2.0 * (x * x + z * z),
        2.0 * (y * z - w * x),
        2.0 * (x * z - w * y),
        2.0 * (y * z + w * x),
        1.0 - 2.0 * (x * x + y * y),
    ]
}

/// The unit quaternion (w, x, y, z) of a rotation matrix.
pub(crate) fn mat_to_quat(m: &M3) -> [f64; 4] {
    let tr = m[0] + m[4] + m[8];
    let q = if tr > 0.0 {
        let s = (tr + 1.0).sqrt() * 2.0;
        [0.25 * s, (m[7] - m[5]) / s, (m[2] - m[6]) / s, (m[3] - m[1]) / s]
    } else if m[0] > m[4] && m[0] > m[8] {
        let s = (1.0 + m[0] - m[4] - m[8]).sqrt() * 2.0;
        [(m[7] - m[5]) / s, 0.25 * s, (m[1] + m[3]) / s, (m[2] + m[6]) / s]
    } else if m[4] > m[8] {
        let s = (1.0 + m[4] - m[0] - m[8]).sqrt() * 2.0;
        [(m[2] - m[6]) / s, (m[1] + m[3]) / s, 0.25 * s, (m[5] + m[7]) / s]
    } else {
        let s = (1.0 + m[8] - m[0] - m[4]).sqrt() * 2.0;
        [(m[3] - m[1]) / s, (m[2] + m[6]) / s, (m[5] + m[7]) / s, 0.25 * s]
    };
    let n = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]).sqrt();
    q.map(|v| v / n)
}

/// Solves `a x = b` for a small dense square system (row-major `a`, n × n) by Gaussian
/// elimination with partial pivoting. `None` when singular.
pub(crate) fn solve(mut a: Vec<f64>, mut b: Vec<f64>, n: usize) -> Option<Vec<f64>> {
    for c in 0..n {
        let p = (c..n).max_by(|&i, &j| a[i * n + c].abs().total_cmp(&a[j * n + c].abs()))?;
        if a[p * n + c].abs() < 1e-12 {
            return None;
        }
        if p != c {
            for k in 0..n {
                a.swap(p * n + k, c * n + k);
            }
            b.swap(p, c);
        }
        for r in c + 1..n {
            let f = a[r * n + c] / a[c * n + c];
            if f != 0.0 {
                for k in c..n {
                    a[r * n + k] -= f * a[c * n + k];
                }
                b[r] -= f * b[c];
            }
        }
    }
    let mut x = vec![0.0; n];
    for r in (0..n).rev() {
        let s: f64 = (r + 1..n).map(|k| a[r * n + k] * x[k]).sum();
        x[r] = (b[r] - s) / a[r * n + r];
    }
    Some(x)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rotations_round_trip() {
        let m = mat_mul(&rot_z(0.7), &quat_to_mat([0.0, 1.0, 0.0, 0.0]));
        let q = mat_to_quat(&m);
        let back = quat_to_mat(q);
        assert!(m.iter().zip(back.iter()).all(|(a, b)| (a - b).abs() < 1e-12));
        let e = rotation_error(&rot_z(0.3), &rot_z(0.1));
        assert!((e[2] - 0.2).abs() < 1e-12 && e[0].abs() < 1e-12);
        let x = solve(vec![2.0, 1.0, 1.0, 3.0], vec![3.0, 5.0], 2).unwrap_or_default();
        assert!((x[0] - 0.8).abs() < 1e-12 && (x[1] - 1.4).abs() < 1e-12);
    }
}
