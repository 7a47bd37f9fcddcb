//! Labelled stand-ins for nouns the catalog has no generator for.

use sw_geom::{Asset, AssetBuilder, MassModel, PlacementKind, Pose, Shape};

/// A box of `size` (width, depth, height) with a darker base band, so that it reads as a
/// placeholder rather than a real object. Movable proxies get a mass from a
/// density prior of 300 kg/m³ (mixed goods), at least 0.05 kg.
pub fn proxy_asset(label: &str, size: [f64; 3], movable: bool, color: Option<[f32; 4]>, seed: u64) -> Asset {
    let [w, d, h] = size.map(|v| if v.is_finite() { v.clamp(0.01, 50.0) } else { 0.3 });
    let mut b = AssetBuilder::new("proxy", seed);
    b.params(vec![("width".into(), w), ("depth".into(), d), ("height".into(), h)]);
    b.note(format!("'{label}' is a labelled proxy box {w:.2} × {d:.2} × {h:.2} m"));
    let body = b.material("proxy", color.unwrap_or([0.62, 0.56, 0.78, 1.0]), true);
    let band = b.material("proxy_band", [0.3, 0.27, 0.4, 1.0], false);
    b.solid(Shape::Box { half: [w / 2.0, d / 2.0, h / 2.0] }, Pose::from_pos([0.0, 0.0, h / 2.0]), body);
    let band_h = (h * 0.08).min(0.05);
    b.visual(
        Shape::Box { half: [w / 2.0 + 0.002, d / 2.0 + 0.002, band_h / 2.0] },
        Pose::from_pos([0.0, 0.0, band_h / 2.0 + 0.001]),
        band,
    );
    b.surface("top", h, [-w / 2.0, -d / 2.0], [w / 2.0, d / 2.0], None);
    let mass = (w * d * h * 300.0).max(0.05);
    b.build(
        if movable { PlacementKind::OnSurface } else { PlacementKind::Floor },
        if movable { MassModel::Free { mass } } else { MassModel::Static },
    )
}
