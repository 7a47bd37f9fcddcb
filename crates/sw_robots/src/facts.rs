//! Mounting facts from a measurement of a robot at its home pose: keep-out boxes (a column
//! over the base and the rest), footprint, height, reach, base radius. Used for robots
//! whose facts are not written down (user directories); the measurement itself is done in
//! MuJoCo by `sw_sim`.

use crate::RobotKind;

/// One body of a robot at home, in the robot's base frame.
#[derive(Debug, Clone, PartialEq)]
pub struct MeasuredBody {
    pub name: String,
    /// Index of the parent body in the same list (`None` for the root).
    pub parent: Option<usize>,
    /// The body frame's origin.
    pub origin: [f64; 3],
    /// Box around the body's collision geometry (`min > max` when it has none).
    pub min: [f64; 3],
    pub max: [f64; 3],
}

/// What the layout needs to know about a robot.
#[derive(Debug, Clone, PartialEq)]
pub struct Facts {
    pub footprint_radius: f64,
    pub height: f64,
    pub reach: f64,
    pub base_radius: f64,
    pub keepout: Vec<([f64; 3], [f64; 3])>,
}

/// Margin around the measured geometry, m.
const MARGIN: f64 = 0.01;
/// Bodies centred within this distance of the base axis form the column box, m.
const COLUMN: f64 = 0.12;

/// Facts from a measurement. `bodies[0]` is the root.
pub fn facts_from_measurement(kind: RobotKind, bodies: &[MeasuredBody]) -> Facts {
    let mut column = Bounds::default();
    let mut rest = Bounds::default();
    for b in bodies.iter().filter(|b| (0..3).all(|i| b.min[i] <= b.max[i])) {
        let c = [(b.min[0] + b.max[0]) / 2.0, (b.min[1] + b.max[1]) / 2.0];
        if kind != RobotKind::Arm || c[0].hypot(c[1]) <= COLUMN || b.parent.is_none() {
            column.add(b.min, b.max);
        } else {
            rest.add(b.min, b.max);
        }
    }
    let mut keepout = Vec::new();
    for b in [column, rest] {
        if let Some((lo, hi)) = b.get() {
            keepout.push((lo.map(|v| v - MARGIN).map(|v| round_cm(v, false)), hi.map(|v| round_cm(v + MARGIN, true))));
        }
    }
    for k in &mut keepout {
        k.0[2] = k.0[2].max(0.0);
    }
    let footprint_radius = keepout
        .iter()
        .flat_map(|(lo, hi)| [[lo[0], lo[1]], [lo[0], hi[1]], [hi[0], lo[1]], [hi[0], hi[1]]])
        .map(|p| p[0].hypot(p[1]))
        .fold(0.0, f64::max);
    let height = keepout.iter().map(|(_, hi)| hi[2]).fold(0.0, f64::max);
    let base_radius = bodies
        .first()
        .filter(|b| (0..3).all(|i| b.min[i] <= b.max[i]))
        .map_or(0.1, |b| [b.min[0], b.max[0], b.min[1], b.max[1]].iter().map(|v| v.abs()).fold(0.0, f64::max))
        .clamp(0.03, 0.4);
    let reach = if kind == RobotKind::MobileBase { 0.0 } else { chain_length(bodies) };
    Facts { footprint_radius, height, reach, base_radius, keepout }
}

/// The longest chain of body origins from the root: an upper bound on the arm's reach.
fn chain_length(bodies: &[MeasuredBody]) -> f64 {
    let mut best: f64 = 0.0;
    for (i, _) in bodies.iter().enumerate() {
        let mut len = 0.0;
        let mut at = i;
        let mut guard = 0;
        while let Some(p) = bodies[at].parent {
            let (a, b) = (bodies[at].origin, bodies[p].origin);
            len += ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt();
            at = p;
            guard += 1;
            if guard > bodies.len() {
                break;
            }
        }
        best = best.max(len);
    }
    // The first link rises from the mount to the shoulder; it adds height, not reach.
    let first_rise = bodies.get(1).map_or(0.0, |b| b.origin[2].abs());
    (best - first_rise).max(0.1)
}

#[derive(Debug, Default, Clone, Copy)]
struct Bounds(Option<([f64; 3], [f64; 3])>);

impl Bounds {
    fn add(&mut self, lo: [f64; 3], hi: [f64; 3]) {
        self.0 = Some(match self.0 {
            None => (lo, hi),
            Some((a, b)) => (
                [a[0].min(lo[0]), a[1].min(lo[1]), a[2].min(lo[2])],
                [b[0].max(hi[0]), b[1].max(hi[1]), b[2].max(hi[2])],
            ),
        });
    }

    fn get(self) -> Option<([f64; 3], [f64; 3])> {
        self.0
    }
}

/// Rounds outwards to the centimetre.
fn round_cm(v: f64, up: bool) -> f64 {
    let s = v * 100.0;
    // Tolerate float noise: 0.55 + 0.01 is 0.56, not 0.57.
    (if up { (s - 1e-9).ceil() } else { (s + 1e-9).floor() }) / 100.0
}

#[cfg(test)]
mod tests {
    use super::*;

    fn body(name: &str, parent: Option<usize>, origin: [f64; 3], min: [f64; 3], max: [f64; 3]) -> MeasuredBody {
        MeasuredBody { name: name.into(), parent, origin, min, max }
    }

    #[test]
    fn an_arm_gets_a_column_and_a_reach_box() {
        let bodies = [
            body("base", None, [0.0; 3], [-0.07, -0.07, 0.0], [0.07, 0.07, 0.1]),
            body("upper", Some(0), [0.0, 0.0, 0.15], [-0.05, -0.05, 0.1], [0.05, 0.05, 0.5]),
            body("fore", Some(1), [0.0, 0.0, 0.5], [0.05, -0.04, 0.45], [0.45, 0.04, 0.55]),
        ];
        let f = facts_from_measurement(RobotKind::Arm, &bodies);
        assert_eq!(f.keepout.len(), 2);
        assert_eq!(f.keepout[0], ([-0.08, -0.08, 0.0], [0.08, 0.08, 0.51]));
        assert_eq!(f.keepout[1], ([0.04, -0.05, 0.44], [0.46, 0.05, 0.56]));
        assert!((f.height - 0.56).abs() < 1e-9, "{}", f.height);
        assert!((f.reach - 0.35).abs() < 1e-9, "{}", f.reach);
        assert!((f.base_radius - 0.07).abs() < 1e-9);
    }
}
