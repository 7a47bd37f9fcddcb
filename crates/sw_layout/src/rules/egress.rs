//! Egress on a floor grid: is every working front connected to the door by a route of
//! the required width, and how wide is the narrowest point of the best route?

use std::collections::{BinaryHeap, VecDeque};

use sw_geom::Aabb;

/// Largest number of cells a grid may have (the cell grows in large rooms).
const MAX_CELLS: f64 = 40_000.0;

/// The floor, with every obstacle grown by half the required route width, so that a free
/// cell is a place the centre of a person-wide route can pass.
#[derive(Debug, Clone)]
pub(crate) struct EgressGrid {
    cell: f64,
    nx: usize,
    ny: usize,
    x0: f64,
    y0: f64,
    radius: f64,
    blocked: Vec<u16>,
    door: Vec<usize>,
}

impl EgressGrid {
    /// A grid over the room (half extents `half`) for routes `width` wide, starting in
    /// the doorway's keep-clear zone.
    pub fn new(half: [f64; 2], width: f64, door_zone: &Aabb) -> Self {
        let area = 4.0 * half[0] * half[1];
        let cell = (area / MAX_CELLS).sqrt().max(0.1);
        let nx = ((2.0 * half[0]) / cell).ceil().max(1.0) as usize;
        let ny = ((2.0 * half[1]) / cell).ceil().max(1.0) as usize;
        let mut g = Self {
            cell,
            nx,
            ny,
            x0: -half[0],
            y0: -half[1],
            radius: width / 2.0,
            blocked: vec![0; nx * ny],
            door: Vec::new(),
        };
        for j in 0..ny {
            for i in 0..nx {
                let (x, y) = g.centre(i, j);
                let in_door =
                    door_zone.min[0] <= x && x <= door_zone.max[0] && door_zone.min[1] <= y && y <= door_zone.max[1];
                let near_wall =
                    x - g.x0 < g.radius || -g.x0 - x < g.radius || y - g.y0 < g.radius || -g.y0 - y < g.radius;
                if in_door {
                    g.door.push(j * nx + i);
                } else if near_wall {
                    g.blocked[j * nx + i] += 1;
                }
            }
        }
        g
    }

    fn centre(&self, i: usize, j: usize) -> (f64, f64) {
        (self.x0 + (i as f64 + 0.5) * self.cell, self.y0 + (j as f64 + 0.5) * self.cell)
    }

    /// Index range of cells whose centres fall in `[lo, hi]` along one axis.
    fn span(&self, lo: f64, hi: f64, origin: f64, n: usize) -> (usize, usize) {
        let a = ((lo - origin) / self.cell - 0.5).ceil().max(0.0) as usize;
        let b = (((hi - origin) / self.cell - 0.5).floor().max(-1.0) + 1.0) as usize;
        (a.min(n), b.min(n))
    }

    fn cells_in(&self, r: &Aabb) -> impl Iterator<Item = usize> + '_ {
        let (i0, i1) = self.span(r.min[0], r.max[0], self.x0, self.nx);
        let (j0, j1) = self.span(r.min[1], r.max[1], self.y0, self.ny);
        (j0..j1).flat_map(move |j| (i0..i1).map(move |i| j * self.nx + i))
    }

    fn grown(&self, r: &Aabb) -> Aabb {
        Aabb {
            min: [r.min[0] - self.radius, r.min[1] - self.radius, r.min[2]],
            max: [r.max[0] + self.radius, r.max[1] + self.radius, r.max[2]],
        }
    }

    /// Adds an obstacle's floor footprint.
    pub fn add(&mut self, footprint: &Aabb) {
        let cells: Vec<usize> = self.cells_in(&self.grown(footprint)).collect();
        for c in cells {
            self.blocked[c] = self.blocked[c].saturating_add(1);
        }
    }

    fn remove(&mut self, footprint: &Aabb) {
        let cells: Vec<usize> = self.cells_in(&self.grown(footprint)).collect();
        for c in cells {
            self.blocked[c] = self.blocked[c].saturating_sub(1);
        }
    }

    /// Cells reachable from the doorway through free cells.
    fn reachable(&self) -> Vec<bool> {
        let mut seen = vec![false; self.blocked.len()];
        let mut queue: VecDeque<usize> = VecDeque::new();
        for &d in &self.door {
            if !seen[d] {
                seen[d] = true;
                queue.push_back(d);
            }
        }
        while let Some(c) = queue.pop_front() {
            let (i, j) = (c % self.nx, c / self.nx);
            let mut visit = |n: usize| {
                if !seen[n] && self.blocked[n] == 0 {
                    seen[n] = true;
                    queue.push_back(n);
                }
            };
            if i > 0 {
                visit(c - 1);
            }
            if i + 1 < self.nx {
                visit(c + 1);
            }
            if j > 0 {
                visit(c - self.nx);
            }
            if j + 1 < self.ny {
                visit(c + self.nx);
            }
        }
        seen
    }

    /// True when every zone has a cell the doorway reaches.
    pub fn connects(&self, zones: &[Aabb]) -> bool {
        if zones.is_empty() {
            return true;
        }
        let seen = self.reachable();
        zones.iter().all(|z| self.cells_in(z).any(|c| seen[c]))
    }

    /// Whether adding `footprint` keeps every zone (old and new) connected to the door.
    pub fn keeps_connected(&mut self, footprint: &Aabb, zones: &[Aabb]) -> bool {
        if zones.is_empty() {
            return true;
        }
        self.add(footprint);
        let ok = self.connects(zones);
        self.remove(footprint);
        ok
    }

    /// For each zone, the width of the narrowest point on the widest route from the
    /// doorway to it (0 when there is none), measured against `obstacles` and the walls.
    pub fn route_widths(&self, obstacles: &[Aabb], zones: &[Aabb]) -> Vec<f64> {
        let n = self.nx * self.ny;
        // Local width: twice the distance from the cell centre to the nearest obstacle or wall.
        let mut width = vec![0.0f64; n];
        let (hx, hy) = (-self.x0, -self.y0);
        for j in 0..self.ny {
            for i in 0..self.nx {
                let (x, y) = self.centre(i, j);
                let c = j * self.nx + i;
                let in_door = self.door.contains(&c);
                let mut d = if in_door { f64::INFINITY } else { (hx - x.abs()).min(hy - y.abs()).max(0.0) };
                for o in obstacles {
                    let dx = (o.min[0] - x).max(x - o.max[0]).max(0.0);
                    let dy = (o.min[1] - y).max(y - o.max[1]).max(0.0);
                    d = d.min(dx.hypot(dy));
                }
                width[c] = 2.0 * d;
            }
        }
        // Widest path (maximise the minimum) from the doorway.
        let mut best = vec![0.0f64; n];
        let mut heap: BinaryHeap<(u64, usize)> = BinaryHeap::new();
        for &d in &self.door {
            best[d] = f64::INFINITY;
            heap.push((u64::MAX, d));
        }
        while let Some((key, c)) = heap.pop() {
            let v = f64::from_bits(key.min(f64::INFINITY.to_bits()));
            if v < best[c] {
                continue;
            }
            let (i, j) = (c % self.nx, c / self.nx);
            let neighbours = [
                (i > 0).then(|| c - 1),
                (i + 1 < self.nx).then(|| c + 1),
                (j > 0).then(|| c - self.nx),
                (j + 1 < self.ny).then(|| c + self.nx),
            ];
            for m in neighbours.into_iter().flatten() {
                let w = best[c].min(width[m]);
                if w > best[m] {
                    best[m] = w;
                    heap.push((w.to_bits(), m));
                }
            }
        }
        zones.iter().map(|z| self.cells_in(z).map(|c| best[c]).fold(0.0, f64::max).min(1e9)).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Aabb {
        Aabb { min: [x0, y0, 0.0], max: [x1, y1, 1.0] }
    }

    #[test]
    fn a_wall_of_objects_cuts_the_route_and_a_gap_restores_it() {
        // 10 × 6 m room, door on the south wall.
        let door = rect(-0.7, -3.0, 0.7, -1.8);
        let mut g = EgressGrid::new([5.0, 3.0], 0.91, &door);
        let target = rect(-1.0, 2.0, 1.0, 2.9);
        assert!(g.connects(std::slice::from_ref(&target)));
        // A barrier across the room with a 1.5 m gap on the east side.
        g.add(&rect(-5.0, 0.0, 3.5, 0.5));
        assert!(g.connects(std::slice::from_ref(&target)));
        assert!(!g.keeps_connected(&rect(3.5, 0.0, 5.0, 0.5), std::slice::from_ref(&target)));
        let widths = g.route_widths(&[rect(-5.0, 0.0, 3.5, 0.5)], &[target]);
        assert!((widths[0] - 1.5).abs() < 0.25, "{widths:?}");
    }
}
