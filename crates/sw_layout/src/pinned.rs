//! Poses kept from an earlier layout: an edit of a package keeps every object and robot
//! it did not change where it was, and the solver places only the rest around them.

use sw_plan::{LaidOutScene, PlacedObject, PlacedRobot, RoomLayout, Support};

use crate::LayoutInput;
use crate::attempt::{self, Ctx};
use crate::frames::Spot;

/// Objects and robots to keep, and the room they stand in (its size and door are kept).
#[derive(Debug, Clone)]
pub struct Pins {
    pub room: RoomLayout,
    /// Objects by name; each must be an object of the input.
    pub objects: Vec<PlacedObject>,
    /// Robots by name; each must be a robot of the input.
    pub robots: Vec<PlacedRobot>,
}

/// Solves the layout with the pinned objects and robots where they are: the room keeps
/// its size (it never grows) and everything else is placed around them as usual.
pub fn solve_pinned(input: &LayoutInput<'_>, pins: &Pins) -> LaidOutScene {
    attempt::run_pinned(input, pins.room.size, Some(pins)).scene
}

/// Commits the pins into an attempt: hosts before what rests on them.
pub(crate) fn commit(ctx: &mut Ctx<'_>, pins: &Pins) {
    let mut objects: Vec<&PlacedObject> = pins.objects.iter().collect();
    objects.sort_by_key(|o| matches!(o.support, Support::Object { .. }));
    for o in objects {
        let Some(idx) = ctx.input.objects.iter().position(|x| x.name == o.name) else { continue };
        let spot = Spot::new(o.pos[0], o.pos[1], o.pos[2], o.yaw);
        if let Support::Object { object, surface } = &o.support
            && let Some(host) = ctx.input.objects.iter().position(|x| &x.name == object)
            && let Some(host_spot) = ctx.placed[host].as_ref().map(|p| p.spot)
            && let Some(si) = ctx.input.objects[host].asset.surfaces.iter().position(|s| &s.name == surface)
        {
            // Its footprint on the host's surface, in the host's frame.
            let world = crate::space::union(&spot.boxes(&ctx.local[idx]));
            let (s, c) = (-host_spot.yaw).sin_cos();
            let mut rect = [f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY];
            for x in [world.min[0], world.max[0]] {
                for y in [world.min[1], world.max[1]] {
                    let (dx, dy) = (x - host_spot.x, y - host_spot.y);
                    let (lx, ly) = (c * dx - s * dy, s * dx + c * dy);
                    rect = [rect[0].min(lx), rect[1].min(ly), rect[2].max(lx), rect[3].max(ly)];
                }
            }
            let n = ctx.input.objects[host].asset.surfaces.len();
            ctx.surface_use.entry(host).or_insert_with(|| vec![Vec::new(); n])[si].push(rect);
        }
        ctx.commit(idx, spot, o.support.clone());
    }
    for r in &pins.robots {
        let Some(ri) = ctx.input.robots.iter().position(|x| x.name == r.name) else { continue };
        let spot = Spot::new(r.pos[0], r.pos[1], r.pos[2], r.yaw);
        let boxes = spot.boxes(&ctx.input.robots[ri].keepout);
        let on_floor = r.mount == "floor";
        if on_floor && let Some(g) = &mut ctx.egress {
            g.add(&crate::space::union(&boxes));
        }
        ctx.space.add(&r.name, boxes, on_floor);
        ctx.robots[ri] = Some(r.clone());
    }
}
