//! The words of the feature language: the nouns that name a body, a cut, an edge
//! treatment, a shell or a pattern; the adjectives that give a body its shape; and the
//! words that carry no geometry (articles, verbs of placement, explanation), which the
//! reader may leave unread. Every other word must be read, or the prompt is refused
//! with it.

/// The cross-section a body noun or adjective implies.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ShapeHint {
    Round,
    /// Round and hollow: a ring, tube or washer.
    Ring,
    Rect,
    Ngon(usize),
    Star,
    Ellipse,
    Stadium,
    Sphere,
    Hemisphere,
    Cone,
    Torus,
    Capsule,
    Pyramid,
    Wedge,
    /// A named cross-section extruded along its length.
    Section(Section),
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Section {
    I,
    T,
    U,
    L,
    Z,
    RectTube,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CutKind {
    Hole,
    Bore,
    Slot,
    Keyway,
    Groove,
    Pocket,
    Counterbore,
    Countersink,
}

/// What a noun names.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Noun {
    /// A body of material (with the shape it has unless told otherwise).
    Body(ShapeHint),
    Cut(CutKind),
    Fillet,
    Chamfer,
    /// A circle, pattern, array or grid that places copies.
    Pattern,
    /// The whole part ("part", "assembly", "chassis"): no geometry of its own.
    Whole,
}

/// A noun of the feature language (singular, lower case).
pub fn noun(w: &str) -> Option<Noun> {
    use ShapeHint::*;
    Some(match w {
        "block" | "box" | "cuboid" | "brick" | "slab" | "bar" | "plate" | "panel" | "board" | "sheet" | "tile" | "base"
        | "wall" | "web" | "rail" | "arm" | "fin" | "rib" | "strip" | "tab" | "ear" | "leg" | "platform" | "pad"
        | "foot" | "spoke" | "floor" | "prong" | "cube" | "prism" | "beam" | "bracket" | "lug" | "blank" | "step" | "riser" => {
            Noun::Body(Rect)
        }
        "cylinder" | "rod" | "shaft" | "pin" | "dowel" | "axle" | "journal" | "shank" | "stem" | "disc" | "puck"
        | "coin" | "hub" | "boss" | "flange" | "neck" | "head" | "cap" | "knob" | "post" | "pillar" | "column"
        | "standoff" | "seat" | "shoulder" | "mount" | "section" | "body" | "wheel" | "roller" | "plug" | "spindle"
        | "stud" | "button" | "trunnion" | "spigot" => Noun::Body(Round),
        "ring" | "washer" | "tube" | "pipe" | "branch" | "sleeve" | "collar" | "bushing" | "spacer" | "rim" | "grommet"
        | "ferrule" | "bush" => Noun::Body(Ring),
        "cone" | "frustum" => Noun::Body(Cone),
        "sphere" | "ball" | "globe" | "orb" => Noun::Body(Sphere),
        "hemisphere" | "dome" => Noun::Body(Hemisphere),
        "torus" | "donut" | "doughnut" => Noun::Body(Torus),
        "capsule" | "pill" => Noun::Body(Capsule),
        "pyramid" => Noun::Body(Pyramid),
        "wedge" | "ramp" => Noun::Body(Wedge),
        "gear" | "cog" | "sprocket" => Noun::Body(Star),
        "stadium" | "oblong" | "obround" => Noun::Body(Stadium),
        "ellipse" => Noun::Body(Ellipse),
        "i-beam" | "h-beam" => Noun::Body(Section(self::Section::I)),
        "t-beam" | "tee-beam" | "t-bar" => Noun::Body(Section(self::Section::T)),
        "u-channel" | "c-channel" | "channel" => Noun::Body(Section(self::Section::U)),
        "l-bracket" | "angle-bracket" => Noun::Body(Section(self::Section::L)),
        "z-bracket" => Noun::Body(Section(self::Section::Z)),
        "hole" | "through-hole" | "bolt-hole" => Noun::Cut(CutKind::Hole),
        "bore" => Noun::Cut(CutKind::Bore),
        "slot" => Noun::Cut(CutKind::Slot),
        "keyway" | "keyseat" => Noun::Cut(CutKind::Keyway),
        "groove" | "v-groove" => Noun::Cut(CutKind::Groove),
        "pocket" | "recess" | "socket" | "cavity" | "cutout" | "notch" => Noun::Cut(CutKind::Pocket),
        "counterbore" => Noun::Cut(CutKind::Counterbore),
        "countersink" => Noun::Cut(CutKind::Countersink),
        "fillet" => Noun::Fillet,
        "chamfer" | "bevel" => Noun::Chamfer,
        "circle" | "pattern" | "array" | "grid" | "row" => Noun::Pattern,
        "nut" => Noun::Body(Ngon(6)),
        "container" | "enclosure" | "tray" | "housing" | "case" => Noun::Body(Rect),
        "trough" | "half-pipe" | "gutter" => Noun::Body(Ring),
        "part" | "assembly" | "piece" | "object" | "component" | "chassis" | "frame" | "fitting"
        | "adapter" | "bolt" | "screw" | "clevis" | "elbow" | "bend" | "tee" | "cross" | "coupling" | "flywheel"
        | "handwheel" | "pulley" | "vase" | "duct" | "transition" | "heatsink" | "drone" | "quadcopter" | "fork"
        | "idler" | "bottle" | "sink" => Noun::Whole,
        _ => return None,
    })
}

/// Adjectives that give a body its cross-section.
pub fn shape_adjective(w: &str) -> Option<ShapeHint> {
    use ShapeHint::*;
    Some(match w {
        "cylindrical" | "round" | "circular" | "disc-shaped" | "coin-shaped" | "rod-shaped" => Round,
        "rectangular" | "square" | "box-shaped" | "cuboid" | "flat-bar" => Rect,
        "hollow" | "annular" | "tubular" => Ring,
        "triangular" | "equilateral" => Ngon(3),
        "pentagonal" => Ngon(5),
        "hexagonal" | "hex" | "hexagon" => Ngon(6),
        "heptagonal" => Ngon(7),
        "octagonal" => Ngon(8),
        "decagonal" => Ngon(10),
        "dodecagonal" => Ngon(12),
        "elliptical" | "elliptic" | "oval" => Ellipse,
        "oblong" | "obround" | "stadium-shaped" | "racetrack" => Stadium,
        "star-shaped" | "star-polygon" | "toothed" => Star,
        "spherical" => Sphere,
        "hemispherical" | "domed" => Hemisphere,
        "conical" | "tapered" | "truncated" => Cone,
        "toroidal" => Torus,
        "pyramidal" => Pyramid,
        _ => return None,
    })
}

/// Words that carry no geometry here: articles, pronouns, copulas, verbs of making and
/// placing, explanation, and the names of CadQuery calls a prompt may mention. The reader
/// may leave them unread.
pub fn is_filler(w: &str) -> bool {
    const FILLER: &[&str] = &[
        "a", "an", "the", "this", "that", "these", "those", "it", "its", "they", "them", "their", "there", "which",
        "who", "is", "are", "be", "being", "been", "was", "were", "has", "have", "having", "with", "and", "or", "of",
        "to", "in", "on", "at", "by", "for", "from", "as", "so", "such", "also", "then", "finally", "first", "next",
        "all", "each", "every", "both", "one", "solid", "simple", "simplified", "plain", "basic", "standard", "small",
        "large", "big", "little", "tiny", "huge", "regular", "straight", "smooth", "interior", "bent", "turning", "turns", "turn", "bridging", "bridge", "bridges", "joining", "straight-line", "segment", "spoked", "edge", "four-way", "three-way", "two-way", "rotated", "workplane", "nearest", "diagonally", "diagonal", "pushpoint", "distance", "rectangular-to-round", "exits", "exit", "perpendicular", "perpendicularly", "endpoint", "configuration", "layout", "arrangement", "intersection", "intersects", "intersect", "shared", "common", "circumference", "line", "different", "decreasing", "increasing", "centerline", "quadrant", "curving", "curve", "curves", "heading", "path", "arcing", "returning", "return", "apex", "face", "surface", "part", "alternating", "alternate", "shape", "shaped", "centroid", "vertex", "i.e", "mm", "millimeter", "make", "made", "create",
        "created", "creating", "build", "built", "model", "modelled", "modeled", "design", "designed", "form",
        "formed", "forming", "forms", "give", "giving", "gives", "resembling", "similar",
        "sort", "kind", "type", "use", "uses", "using", "used", "via", "into", "onto", "upon", "it's", "i.e",
        "e.g", "approximately", "about", "around", "roughly", "nominal", "exactly", "overall", "total", "entire",
        "full", "whole", "complete", "same", "matching", "match", "identical", "equal", "respective", "respectively",
        "note", "please", "should", "must", "will", "would", "can", "could", "we", "you", "i", "me", "my", "our",
        "want", "need", "give", "get", "stand", "stands", "standing", "sit", "sits", "sitting", "seated", "lie", "lies",
        "lying", "rest", "rests", "resting", "placed", "positioned", "located", "situated", "set", "sets", "sits",
        "mounted", "attached", "joined", "fused", "connected", "connect", "connects", "connecting", "integrated",
        "union", "unioned", "merge", "merged", "combined", "added", "add", "drilled", "drill", "drilling", "bored",
        "cut", "cuts", "machined", "milled", "removed", "remove", "topped", "extends", "extend", "extending", "extended", "runs",
        "run", "running", "passes", "pass", "passing", "goes", "go", "going", "rises", "rise", "rising", "protrudes",
        "protrude", "protruding", "projects", "sticks", "continues", "continue", "spans", "span", "spanning",
        "reaching", "reaches", "reach", "starting", "starts", "start", "ending", "arranged", "spaced",
        "evenly", "equally", "uniformly", "symmetrically", "symmetric", "symmetrical", "concentric", "coaxial",
        "aligned", "oriented", "orientation", "centered", "centred", "center", "origin", "positions", "position",
        "plane", "axis", "direction", "upright", "vertical", "vertically", "horizontal",
        "horizontally", "flat", "level", "up", "upward", "upwards", "down", "downward", "downwards", "outward",
        "outwards", "inward", "inwards", "above", "below", "over", "under", "beneath", "behind", "between", "along",
        "through", "throughout", "across", "within", "inside", "outside", "past", "beyond", "toward", "towards",
        "against", "off", "out", "only", "just", "but", "since", "because", "thus", "hence", "therefore", "whose",
        "where", "when", "while", "if", "not", "no", "any", "other", "another", "more", "less", "than", "very",
        "quite", "rather", "fairly", "some", "several", "many", "few", "viewed", "seen", "view", "looking", "shows",
        "looks", "call", "called", "named", "known", "referred", "describe", "described", "description",
        "dimension", "dimensions", "size", "sizes", "measure", "measures", "measuring", "units", "unit", "metric",
        "approx", "nearly", "almost", "precisely", "just", "here", "following", "below", "as-is", "per", "do",
        "does", "done", "keep", "keeping", "kept", "preserving", "preserved", "remain", "remains", "leaving",
        "leave", "has", "feature", "features", "featuring", "includes",
        "including", "include", "contains", "containing", "consists", "consisting", "comprises", "comprising",
        "provide", "provided", "providing", "having", "bearing", "carrying", "holding", "hold", "holds",
        "workplane", "workplanes", "pushpoints", "radiusarc", "sketch", "extrusion", "cadquery", "cq", "python",
        "code", "operation", "boolean", "computed", "compute", "calculated", "defined", "define", "defines", "follow",
        "follows", "following", "followed", "sweeping", "swept", "revolving", "lofting", "stacking", "stacked",
        "stack", "sharp", "crisp", "clean", "neat", "nice", "good", "well", "thin", "fine", "heavy", "light",
        "main", "central", "middle", "primary", "secondary", "second", "third", "last", "single", "pair",
        "couple", "clearance", "mounting", "structural", "mechanical", "machine", "engineering", "industrial",
        "part's", "piece's", "object's", "shape's", "manufacturing", "printed", "printable", "3d", "cad",
    ];
    FILLER.contains(&w)
}

/// Number words: "four holes", "a dozen".
pub fn number_word(w: &str) -> Option<u32> {
    Some(match w {
        "one" | "single" => 1,
        "two" | "both" | "pair" | "twin" => 2,
        "three" | "triple" => 3,
        "four" | "quad" => 4,
        "five" => 5,
        "six" => 6,
        "seven" => 7,
        "eight" => 8,
        "nine" => 9,
        "ten" => 10,
        "eleven" => 11,
        "twelve" | "dozen" => 12,
        "sixteen" => 16,
        "twenty" => 20,
        _ => return None,
    })
}
