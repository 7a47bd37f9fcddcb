//! Sport, games, toys and music from the public lists (COCO, Objects365, YCB, LVIS).
//! Balls keep their regulation sizes; boards and sticks lie flat on the floor or a table.

use super::{
    BLACK_C, BLACKS, BRIGHTS, CONE, DISC, LEATHER, Look, METAL, STEEL_C, TUMBLER, WHITE, WHITE_C, WOOD_C, WOODS, thing,
};

type Rgba = [f32; 4];

const SPORT: &[&str] = &["home", "sport", "toy", "graspable"];
const BALL: &[&str] = &["home", "sport", "toy", "graspable", "round", "uniform"];
const BOARD: &[&str] = &["home", "sport", "large"];
const GAME: &[&str] = &["home", "toy", "game", "tabletop", "small", "graspable"];
const MUSIC: &[&str] = &["home", "music", "instrument"];

const BRASS: &[Rgba] = &[[0.85, 0.68, 0.28, 1.0], [0.78, 0.6, 0.25, 1.0]];
const VARNISH: &[Rgba] = &[[0.5, 0.25, 0.1, 1.0], [0.6, 0.32, 0.12, 1.0]];
const BRASS_C: Rgba = [0.85, 0.68, 0.28, 1.0];

const fn ball(body: &'static [Rgba]) -> Look {
    Look::Blob { body, accent: BLACK_C, stem: false }
}
const fn stick(grip: f64, handle: &'static [Rgba], head: Rgba) -> Look {
    Look::Long { grip, grip_w: 0.35, grip_h: 0.7, handle, head }
}
const fn horn(body: &'static [Rgba]) -> Look {
    Look::Instrument { body, neck: BRASS_C, body_len: 0.35 }
}

// --- balls (regulation and YCB sizes) -----------------------------------------------
// Baseball: 7.3–7.5 cm (YCB 055_baseball).
thing!(BASEBALL: "baseball", "baseball", ["baseball ball", "hardball"], BALL, "a white leather baseball with red stitching",
    ["ball", "sports equipment"], Toy @ OnSurface, true, [0.074, 0.074, 0.074], 650.0, ball(WHITE));
// Softball: 9.7 cm (YCB 054_softball).
thing!(SOFTBALL: "softball", "softball", ["softball ball"], BALL, "a yellow softball",
    ["ball", "sports equipment"], Toy @ OnSurface, true, [0.097, 0.097, 0.097], 400.0, ball(&[[0.9, 0.95, 0.2, 1.0]]));
// Racquetball: 5.7 cm (YCB 057_racquetball).
thing!(RACQUETBALL: "racquetball", "racquetball", ["racquet ball"], BALL, "a small hollow rubber ball",
    ["ball", "sports equipment"], Toy @ OnSurface, true, [0.057, 0.057, 0.057], 400.0, ball(&[[0.15, 0.3, 0.8, 1.0], [0.1, 0.1, 0.1, 1.0]]));

// --- boards, sticks and bats --------------------------------------------------------
// Frisbee: 27 cm (Ultimate 175 g disc).
thing!(FRISBEE: "frisbee", "frisbee", ["flying disc", "frisbee disc"], SPORT, "a round plastic flying disc",
    ["toy", "sports equipment"], Toy @ OnSurface, true, [0.27, 0.27, 0.03], 100.0, Look::Turned { profile: DISC, body: BRIGHTS, top: 1.0, cap_r: 1.0, cap: WHITE_C });
// Diamond kite, 80 × 60 cm, lying.
thing!(KITE: "kite", "kite", ["diamond kite", "stunt kite"], SPORT, "a diamond-shaped fabric kite on its spars",
    ["toy"], Toy @ OnSurface, true, [0.80, 0.60, 0.03], 30.0, Look::Flat { body: BRIGHTS, panel: WHITE_C });
// Pair of skis: 170 cm, lying.
thing!(SKIS: "skis", "skis", ["ski", "pair of skis", "alpine skis"], BOARD, "a pair of skis lying side by side",
    ["sports equipment"], Toy @ Floor, true, [1.70, 0.20, 0.06], 150.0, stick(0.15, BRIGHTS, [0.2, 0.2, 0.25, 1.0]));
// Snowboard: 155 × 26 cm.
thing!(SNOWBOARD: "snowboard", "snowboard", ["snow board"], BOARD, "a long flat snowboard with bindings",
    ["sports equipment", "board"], Toy @ Floor, true, [1.55, 0.26, 0.08], 100.0, Look::Flat { body: BRIGHTS, panel: BLACK_C });
// Surfboard: 2 m shortboard.
thing!(SURFBOARD: "surfboard", "surfboard", ["surf board", "shortboard", "longboard surfboard"], BOARD, "a long pointed surfboard",
    ["sports equipment", "board"], Toy @ Floor, true, [2.00, 0.55, 0.08], 60.0, ball(&[[0.95, 0.95, 0.9, 1.0], [0.2, 0.6, 0.8, 1.0]]));
// Baseball glove, 30 × 22 × 10 cm.
thing!(BASEBALL_GLOVE: "baseball_glove", "baseball glove", ["baseball mitt", "catcher's mitt", "softball glove"], SPORT,
    "a leather baseball glove", ["sports equipment", "glove"], Toy @ OnSurface, true, [0.30, 0.22, 0.10], 100.0, ball(LEATHER));
// Ice hockey stick: 150 cm.
thing!(HOCKEY_STICK: "hockey_stick", "hockey stick", ["ice hockey stick", "field hockey stick"], SPORT, "a long hockey stick with a flat blade",
    ["sports equipment", "stick"], Toy @ Floor, true, [1.50, 0.10, 0.03], 200.0, stick(0.8, BLACKS, [0.85, 0.85, 0.85, 1.0]));
// Golf club (driver): 112 cm.
thing!(GOLF_CLUB: "golf_club", "golf club", ["putter", "golf driver", "golf iron"], SPORT, "a golf club with its head",
    ["sports equipment"], Toy @ Floor, true, [1.10, 0.10, 0.05], 100.0, stick(0.88, BLACKS, STEEL_C));
// Pool cue: 145 cm.
thing!(POOL_CUE: "pool_cue", "pool cue", ["cue", "billiard cue", "snooker cue", "cue stick"], SPORT, "a long tapered wooden cue",
    ["sports equipment", "stick"], Toy @ Floor, true, [1.45, 0.03, 0.03], 300.0, stick(0.4, VARNISH, WOOD_C));
// Table tennis bat: 26 × 15 cm.
thing!(TABLE_TENNIS_BAT: "table_tennis_bat", "table tennis bat", ["ping pong paddle", "ping pong bat", "table tennis paddle", "table tennis racket"],
    SPORT, "a round rubber-faced table tennis bat", ["sports equipment", "bat"], Toy @ OnSurface, true, [0.26, 0.15, 0.025], 300.0,
    stick(0.38, WOODS, [0.8, 0.1, 0.1, 1.0]));
// Canoe paddle: 140 cm.
thing!(PADDLE: "paddle", "paddle", ["canoe paddle", "kayak paddle"], SPORT, "a long wooden paddle with a flat blade",
    ["sports equipment"], Toy @ Floor, true, [1.40, 0.20, 0.04], 200.0, stick(0.7, WOODS, WOOD_C));
// Fishing rod: 180 cm (two-piece, assembled).
thing!(FISHING_ROD: "fishing_rod", "fishing rod", ["fishing pole", "rod and reel"], SPORT, "a long thin fishing rod with a reel",
    ["sports equipment"], Toy @ Floor, true, [1.80, 0.05, 0.05], 100.0, stick(0.3, BLACKS, [0.2, 0.2, 0.22, 1.0]));
// Barbell with plates: 150 cm, 30 cm plates.
thing!(BARBELL: "barbell", "barbell", ["weight bar", "weightlifting bar", "olympic bar"], &["home", "sport", "gym", "heavy"],
    "a long steel bar with weight plates at each end", ["exercise equipment"], Toy @ Floor, true, [1.50, 0.30, 0.30], 150.0,
    Look::Long { grip: 0.82, grip_w: 0.1, grip_h: 0.55, handle: METAL, head: [0.1, 0.1, 0.11, 1.0] });
// Self-balancing board: 60 × 20 × 18 cm.
thing!(HOVERBOARD: "hoverboard", "hoverboard", ["self-balancing board"], BOARD, "a two-wheeled self-balancing board",
    ["toy", "vehicle"], Toy @ Floor, true, [0.60, 0.20, 0.18], 80.0, Look::Pack { body: BLACKS, band: [0.2, 0.5, 0.9, 1.0] });

// --- games and toys -----------------------------------------------------------------
// Deck of playing cards: 9 × 6.5 × 2 cm (poker size in its box).
thing!(PLAYING_CARDS: "playing_cards", "playing cards", ["deck of cards", "pack of cards", "poker cards", "playing card", "cards"], GAME,
    "a deck of playing cards in its box", ["game", "toy"], Toy @ OnSurface, true, [0.09, 0.065, 0.02], 600.0,
    Look::Pack { body: &[[0.75, 0.1, 0.1, 1.0], [0.1, 0.2, 0.6, 1.0]], band: WHITE_C });
// Foam brick (YCB 061_foam_brick): 5 × 7.5 × 5 cm.
thing!(FOAM_BRICK: "foam_brick", "foam brick", ["foam block", "sponge brick", "foam cube"], GAME, "a red foam brick",
    ["toy", "block"], Toy @ OnSurface, true, [0.075, 0.05, 0.05], 100.0, Look::Pack { body: &[[0.8, 0.15, 0.12, 1.0]], band: [0.7, 0.12, 0.1, 1.0] });
// Toy airplane (YCB 072): 25 × 20 × 8 cm.
thing!(TOY_AIRPLANE: "toy_airplane", "toy airplane", ["toy plane", "model airplane", "model aeroplane", "toy aeroplane", "toy jet"], GAME,
    "a toy aeroplane with wings and a tail", ["toy"], Toy @ OnSurface, true, [0.25, 0.20, 0.08], 150.0,
    Look::Instrument { body: BRIGHTS, neck: [0.9, 0.9, 0.9, 1.0], body_len: 0.75 });

// --- music --------------------------------------------------------------------------
// Full-size violin: 60 × 21 × 10 cm.
thing!(VIOLIN: "violin", "violin", ["fiddle"], MUSIC, "a wooden violin with its neck and scroll",
    ["string instrument", "instrument"], Toy @ OnSurface, true, [0.60, 0.21, 0.10], 60.0,
    Look::Instrument { body: VARNISH, neck: BLACK_C, body_len: 0.6 });
// Cello, lying: 120 × 45 × 25 cm.
thing!(CELLO: "cello", "cello", ["violoncello"], MUSIC, "a large wooden cello",
    ["string instrument", "instrument"], Toy @ Floor, true, [1.20, 0.45, 0.25], 25.0, Look::Instrument { body: VARNISH, neck: BLACK_C, body_len: 0.62 });
// Alto saxophone, lying: 70 × 30 × 15 cm.
thing!(SAXOPHONE: "saxophone", "saxophone", ["sax", "alto sax", "tenor sax"], MUSIC, "a curved brass saxophone with keys",
    ["wind instrument", "instrument"], Toy @ OnSurface, true, [0.70, 0.30, 0.15], 40.0, horn(BRASS));
// Trumpet: 50 × 13 × 15 cm.
thing!(TRUMPET: "trumpet", "trumpet", ["cornet", "bugle", "brass trumpet", "pocket trumpet"], MUSIC, "a brass trumpet with valves and a flared bell",
    ["brass instrument", "instrument"], Toy @ OnSurface, true, [0.50, 0.13, 0.15], 80.0, horn(BRASS));
// Trombone: 100 × 20 × 15 cm.
thing!(TROMBONE: "trombone", "trombone", ["slide trombone"], MUSIC, "a brass trombone with its slide",
    ["brass instrument", "instrument"], Toy @ Floor, true, [1.00, 0.20, 0.15], 50.0, horn(BRASS));
// Tuba, lying: 90 × 50 × 40 cm.
thing!(TUBA: "tuba", "tuba", ["bass tuba"], MUSIC, "a large coiled brass tuba",
    ["brass instrument", "instrument"], Toy @ Floor, true, [0.90, 0.50, 0.40], 30.0, horn(BRASS));
// Concert flute: 67 cm.
thing!(FLUTE: "flute", "flute", ["concert flute", "transverse flute"], MUSIC, "a silver flute",
    ["wind instrument", "instrument"], Toy @ OnSurface, true, [0.67, 0.03, 0.03], 500.0, stick(0.3, METAL, STEEL_C));
// Descant recorder: 32 cm.
thing!(RECORDER: "recorder", "recorder", ["descant recorder", "treble recorder"], MUSIC, "a plastic recorder with finger holes",
    ["wind instrument", "instrument"], Toy @ OnSurface, true, [0.32, 0.035, 0.035], 400.0, stick(0.8, WHITE, [0.85, 0.8, 0.7, 1.0]));
// Crash cymbal: 40 cm.
thing!(CYMBAL: "cymbal", "cymbal", ["crash cymbal", "ride cymbal", "hi hat"], MUSIC, "a round brass cymbal",
    ["percussion instrument", "instrument"], Toy @ OnSurface, true, [0.40, 0.40, 0.03], 300.0,
    Look::Turned { profile: CONE, body: BRASS, top: 1.0, cap_r: 1.0, cap: WHITE_C });
// Handheld microphone: 20 × 5 × 5 cm.
thing!(MICROPHONE: "microphone", "microphone", ["mic", "handheld microphone", "vocal microphone"], &["home", "music", "electronics", "tabletop", "small", "graspable"],
    "a handheld microphone with a mesh head", ["audio equipment", "electronics"], HandHeld @ OnSurface, true, [0.20, 0.05, 0.05], 400.0,
    Look::Long { grip: 0.7, grip_w: 0.6, grip_h: 0.7, handle: BLACKS, head: [0.5, 0.5, 0.52, 1.0] });
// Megaphone: 20 cm bell, 30 cm tall.
thing!(MEGAPHONE: "megaphone", "megaphone", ["bullhorn", "loudhailer"], &["home", "electronics", "tabletop"], "a white megaphone with a flared bell",
    ["audio equipment", "electronics"], Tabletop @ OnSurface, true, [0.20, 0.20, 0.30], 80.0,
    Look::Turned { profile: TUMBLER, body: WHITE, top: 1.0, cap_r: 1.0, cap: WHITE_C });
// Camera tripod, extended: 50 × 50 × 150 cm.
thing!(TRIPOD: "tripod", "tripod", ["camera tripod", "tripod stand"], &["home", "office", "photography"], "a three-legged camera tripod",
    ["stand", "photography equipment"], Furniture @ Floor, true, [0.50, 0.50, 1.50], 15.0,
    Look::Stand { foot: BLACK_C, pole: [0.2, 0.2, 0.22, 1.0], head: BLACKS, head_h: 0.08 });
// Binoculars: 16 × 12 × 6 cm.
thing!(BINOCULARS: "binoculars", "binoculars", ["field glasses", "pair of binoculars"], &["home", "tabletop", "small", "graspable"],
    "a pair of binoculars", ["optical instrument"], Tabletop @ OnSurface, true, [0.16, 0.12, 0.06], 600.0,
    Look::Pack { body: BLACKS, band: [0.3, 0.3, 0.32, 1.0] });
// Compact disc in its case: 14.2 × 12.5 × 1 cm.
thing!(COMPACT_DISC: "compact_disc", "compact disc", ["cd", "cd case", "music cd", "audio cd"], &["home", "music", "tabletop", "small", "graspable"],
    "a compact disc in its plastic case", ["media"], Tabletop @ OnSurface, true, [0.142, 0.125, 0.01], 900.0,
    Look::Flat { body: &[[0.85, 0.88, 0.9, 1.0]], panel: [0.2, 0.3, 0.6, 1.0] });
