//! Kinds of things: the coarse classes every category belongs to (its `kind`), each with
//! a size prior for a labelled proxy of a noun the catalog has no generator for and no
//! category it is a kind of ("an air purifier" is a small appliance: a box about 30 cm
//! across on a surface, never a 2 m machine).

use sw_geom::PlacementKind;

/// What sort of thing a category (or an unknown noun) is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Kind {
    /// Floor-standing household appliances (washing machine, dishwasher, oven).
    LargeAppliance,
    /// Countertop and hand-carried appliances and equipment (toaster, kettle, centrifuge).
    SmallAppliance,
    /// Furniture: tables, seats, beds, storage.
    Furniture,
    /// Building fixtures and plumbing (doors, toilets, radiators, panels).
    Fixture,
    /// Industrial and workshop machines.
    Machine,
    /// Containers that hold goods (boxes, bins, drums, baskets).
    Container,
    /// Tools and utensils held in one hand (hammer, spoon, pen).
    HandHeld,
    /// Small things that stand on a table (mug, lamp, phone, jar).
    Tabletop,
    /// Food and produce.
    Food,
    /// Toys and games.
    Toy,
    /// Soft goods: towels, cushions, rugs, clothes.
    Textile,
    /// Vehicles and wheeled equipment.
    Vehicle,
    /// Plants.
    Plant,
}

/// The size prior of a kind: a typical overall box, whether such things are free bodies,
/// and where they stand.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KindPrior {
    /// Width, depth, height, m.
    pub size: [f64; 3],
    pub movable: bool,
    pub placement: PlacementKind,
}

impl Kind {
    pub const ALL: [Kind; 13] = [
        Kind::LargeAppliance,
        Kind::SmallAppliance,
        Kind::Furniture,
        Kind::Fixture,
        Kind::Machine,
        Kind::Container,
        Kind::HandHeld,
        Kind::Tabletop,
        Kind::Food,
        Kind::Toy,
        Kind::Textile,
        Kind::Vehicle,
        Kind::Plant,
    ];

    /// What people call things of this kind (also the report's wording).
    pub fn name(self) -> &'static str {
        match self {
            Kind::LargeAppliance => "large appliance",
            Kind::SmallAppliance => "small appliance",
            Kind::Furniture => "furniture",
            Kind::Fixture => "fixture",
            Kind::Machine => "machine",
            Kind::Container => "container",
            Kind::HandHeld => "hand-held item",
            Kind::Tabletop => "tabletop item",
            Kind::Food => "food",
            Kind::Toy => "toy",
            Kind::Textile => "textile",
            Kind::Vehicle => "vehicle",
            Kind::Plant => "plant",
        }
    }

    /// The kind with this name.
    pub fn from_name(name: &str) -> Option<Kind> {
        Kind::ALL.iter().copied().find(|k| k.name() == name)
    }

    /// Typical size and behaviour, from the middle of each class's product ranges: a
    /// front-loading washer or dishwasher is 60 × 60 × 85 cm; a toaster or kettle about
    /// 25 × 20 × 25 cm; a hand tool 20 × 5 × 4 cm; a piece of fruit 8 cm.
    pub fn prior(self) -> KindPrior {
        use PlacementKind::{AgainstWall, Floor, OnSurface};
        let (size, movable, placement) = match self {
            Kind::LargeAppliance => ([0.6, 0.62, 0.85], false, AgainstWall),
            Kind::SmallAppliance => ([0.3, 0.24, 0.28], true, OnSurface),
            Kind::Furniture => ([1.0, 0.6, 0.75], false, Floor),
            Kind::Fixture => ([0.6, 0.5, 0.9], false, AgainstWall),
            Kind::Machine => ([1.4, 1.0, 1.7], false, Floor),
            Kind::Container => ([0.4, 0.3, 0.3], true, OnSurface),
            Kind::HandHeld => ([0.2, 0.05, 0.04], true, OnSurface),
            Kind::Tabletop => ([0.1, 0.1, 0.14], true, OnSurface),
            Kind::Food => ([0.08, 0.08, 0.08], true, OnSurface),
            Kind::Toy => ([0.2, 0.15, 0.15], true, OnSurface),
            Kind::Textile => ([0.4, 0.3, 0.08], true, OnSurface),
            Kind::Vehicle => ([2.6, 1.2, 2.0], false, Floor),
            Kind::Plant => ([0.45, 0.45, 1.0], false, Floor),
        };
        KindPrior { size, movable, placement }
    }
}
