//! A small software rasterizer: perspective camera, z-buffer, flat Lambert shading.
//!
//! Enough to look at an asset or a whole scene without a GPU or OpenGL: the scene
//! previews and the catalog's contact sheet are drawn with it.

use std::io::Write;

use crate::{Aabb, Asset, Mesh, Pose};

/// An RGB image, row-major from the top-left.
#[derive(Debug, Clone)]
pub struct Image {
    pub width: u32,
    pub height: u32,
    pub rgb: Vec<u8>,
}

impl Image {
    pub fn new(width: u32, height: u32, background: [u8; 3]) -> Self {
        let mut rgb = Vec::with_capacity((width * height * 3) as usize);
        for _ in 0..width * height {
            rgb.extend_from_slice(&background);
        }
        Self { width, height, rgb }
    }

    pub fn pixel(&self, x: u32, y: u32) -> [u8; 3] {
        let i = ((y * self.width + x) * 3) as usize;
        [self.rgb[i], self.rgb[i + 1], self.rgb[i + 2]]
    }

    pub fn set(&mut self, x: u32, y: u32, c: [u8; 3]) {
        if x < self.width && y < self.height {
            let i = ((y * self.width + x) * 3) as usize;
            self.rgb[i..i + 3].copy_from_slice(&c);
        }
    }

    /// Copies `tile` into this image with its top-left corner at (`x`, `y`).
    pub fn blit(&mut self, tile: &Image, x: u32, y: u32) {
        for ty in 0..tile.height {
            for tx in 0..tile.width {
                self.set(x + tx, y + ty, tile.pixel(tx, ty));
            }
        }
    }

    /// Encodes the image as PNG.
    pub fn write_png<W: Write>(&self, out: W) -> Result<(), png::EncodingError> {
        let mut enc = png::Encoder::new(out, self.width, self.height);
        enc.set_color(png::ColorType::Rgb);
        enc.set_depth(png::BitDepth::Eight);
        let mut w = enc.write_header()?;
        w.write_image_data(&self.rgb)?;
        w.finish()
    }

    /// Draws `text` in a 5×7 pixel font scaled by `scale`, for labels on contact sheets.
    pub fn text(&mut self, x: u32, y: u32, text: &str, scale: u32, color: [u8; 3]) {
        let mut cx = x;
        for ch in text.chars() {
            let glyph = font_glyph(ch.to_ascii_uppercase());
            for (row, bits) in glyph.iter().enumerate() {
                for col in 0..5u32 {
                    if bits & (1 << (4 - col)) != 0 {
                        for dy in 0..scale {
                            for dx in 0..scale {
                                self.set(cx + col * scale + dx, y + row as u32 * scale + dy, color);
                            }
                        }
                    }
                }
            }
            cx += 6 * scale;
        }
    }
}

/// A pinhole camera looking from `eye` at `target`, +Z up.
#[derive(Debug, Clone, Copy)]
pub struct Camera {
    pub eye: [f64; 3],
    pub target: [f64; 3],
    /// Vertical field of view, radians.
    pub fov_y: f64,
}

impl Camera {
    /// A camera that frames `bounds` from the given azimuth (from +X, counter-clockwise)
    /// and elevation, both in radians.
    pub fn framing(bounds: &Aabb, azimuth: f64, elevation: f64) -> Self {
        let c = bounds.center();
        let s = bounds.size();
        let radius = 0.5 * (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]).sqrt().max(1e-3);
        let fov_y = 35f64.to_radians();
        let dist = radius / (0.5 * fov_y).sin() * 1.05;
        let dir = [elevation.cos() * azimuth.cos(), elevation.cos() * azimuth.sin(), elevation.sin()];
        Self { eye: [c[0] + dir[0] * dist, c[1] + dir[1] * dist, c[2] + dir[2] * dist], target: c, fov_y }
    }
}

/// A picture of an asset: its visual meshes in their materials, seen from a three-quarter
/// view of its front (assets face +Y), on a light background. The catalog's contact sheet,
/// `assets render` and the web app's catalog pictures are drawn with it.
pub fn draw_asset(a: &Asset, width: u32, height: u32) -> Image {
    let poses = a.link_poses();
    let cam = Camera::framing(&a.bounds(), 1.15, 0.45);
    let mut r = Renderer::new(width, height, &cam, [238, 241, 246]);
    for (link, pose) in a.links.iter().zip(&poses) {
        for v in &link.visuals {
            let rgba = a.materials.get(v.material).map_or([0.6, 0.6, 0.6, 1.0], |m| m.rgba);
            r.draw_mesh(&v.mesh, pose, rgba);
        }
    }
    r.finish()
}

/// Draws triangles into an image with a depth buffer.
#[derive(Debug)]
pub struct Renderer {
    image: Image,
    depth: Vec<f32>,
    // Camera basis.
    eye: [f64; 3],
    right: [f64; 3],
    up: [f64; 3],
    forward: [f64; 3],
    focal: f64,
    light: [f64; 3],
}

const NEAR: f64 = 0.01;

impl Renderer {
    pub fn new(width: u32, height: u32, camera: &Camera, background: [u8; 3]) -> Self {
        let forward = normalize(sub(camera.target, camera.eye));
        let world_up = if forward[2].abs() > 0.999 { [0.0, 1.0, 0.0] } else { [0.0, 0.0, 1.0] };
        let right = normalize(cross(forward, world_up));
        let up = cross(right, forward);
        let focal = 0.5 * f64::from(height) / (0.5 * camera.fov_y).tan();
        Self {
            image: Image::new(width, height, background),
            depth: vec![f32::INFINITY; (width * height) as usize],
            eye: camera.eye,
            right,
            up,
            forward,
            focal,
            light: normalize([0.35, -0.5, 0.8]),
        }
    }

    /// Draws `mesh` placed at `pose` in colour `rgba` (alpha below 0.1 is skipped).
    pub fn draw_mesh(&mut self, mesh: &Mesh, pose: &Pose, rgba: [f32; 4]) {
        if rgba[3] < 0.1 {
            return;
        }
        let world: Vec<[f64; 3]> =
            mesh.vertices.iter().map(|v| pose.apply([f64::from(v[0]), f64::from(v[1]), f64::from(v[2])])).collect();
        for t in &mesh.triangles {
            let (Some(a), Some(b), Some(c)) =
                (world.get(t[0] as usize), world.get(t[1] as usize), world.get(t[2] as usize))
            else {
                continue;
            };
            self.draw_triangle([*a, *b, *c], rgba);
        }
    }

    /// Draws one world-space triangle.
    pub fn draw_triangle(&mut self, tri: [[f64; 3]; 3], rgba: [f32; 4]) {
        let n = normalize(cross(sub(tri[1], tri[0]), sub(tri[2], tri[0])));
        // Two-sided lighting: flip normals that face away from the camera.
        let to_eye = sub(self.eye, tri[0]);
        let n = if dot(n, to_eye) < 0.0 { [-n[0], -n[1], -n[2]] } else { n };
        let lambert = dot(n, self.light).max(0.0);
        let shade = 0.35 + 0.65 * lambert;
        let color = [
            (f64::from(rgba[0]) * shade * 255.0).clamp(0.0, 255.0) as u8,
            (f64::from(rgba[1]) * shade * 255.0).clamp(0.0, 255.0) as u8,
            (f64::from(rgba[2]) * shade * 255.0).clamp(0.0, 255.0) as u8,
        ];
        let cam: Vec<[f64; 3]> = tri.iter().map(|p| self.to_camera(*p)).collect();
        if let Some(poly) = clip_near(&cam) {
            self.fill(&poly, color);
        }
    }

    pub fn finish(self) -> Image {
        self.image
    }

    fn to_camera(&self, p: [f64; 3]) -> [f64; 3] {
        let d = sub(p, self.eye);
        [dot(d, self.right), dot(d, self.up), dot(d, self.forward)]
    }

    /// Fills a convex polygon given in camera coordinates (z > NEAR).
    fn fill(&mut self, poly: &[[f64; 3]], color: [u8; 3]) {
        let (w, h) = (f64::from(self.image.width), f64::from(self.image.height));
        let screen: Vec<[f64; 3]> = poly
            .iter()
            .map(|p| [0.5 * w + self.focal * p[0] / p[2], 0.5 * h - self.focal * p[1] / p[2], p[2]])
            .collect();
        for i in 1..screen.len().saturating_sub(1) {
            self.fill_triangle(screen[0], screen[i], screen[i + 1], color);
        }
    }

    fn fill_triangle(&mut self, a: [f64; 3], b: [f64; 3], c: [f64; 3], color: [u8; 3]) {
        let area = edge(a, b, c);
        if area.abs() < 1e-12 {
            return;
        }
        let (w, h) = (self.image.width as i64, self.image.height as i64);
        let x0 = (a[0].min(b[0]).min(c[0]).floor() as i64).max(0);
        let x1 = (a[0].max(b[0]).max(c[0]).ceil() as i64).min(w - 1);
        let y0 = (a[1].min(b[1]).min(c[1]).floor() as i64).max(0);
        let y1 = (a[1].max(b[1]).max(c[1]).ceil() as i64).min(h - 1);
        // Interpolate 1/z for perspective-correct depth.
        let (ia, ib, ic) = (1.0 / a[2], 1.0 / b[2], 1.0 / c[2]);
        for y in y0..=y1 {
            for x in x0..=x1 {
                let p = [x as f64 + 0.5, y as f64 + 0.5, 0.0];
                let w0 = edge(b, c, p) / area;
                let w1 = edge(c, a, p) / area;
                let w2 = edge(a, b, p) / area;
                if w0 < 0.0 || w1 < 0.0 || w2 < 0.0 {
                    continue;
                }
                let z = 1.0 / (w0 * ia + w1 * ib + w2 * ic);
                let idx = (y * w + x) as usize;
                if (z as f32) < self.depth[idx] {
                    self.depth[idx] = z as f32;
                    self.image.set(x as u32, y as u32, color);
                }
            }
        }
    }
}

/// Sutherland–Hodgman clip of a triangle against the near plane `z = NEAR`.
fn clip_near(tri: &[[f64; 3]]) -> Option<Vec<[f64; 3]>> {
    let mut out = Vec::with_capacity(4);
    for i in 0..tri.len() {
        let (p, q) = (tri[i], tri[(i + 1) % tri.len()]);
        let (pin, qin) = (p[2] > NEAR, q[2] > NEAR);
        if pin {
            out.push(p);
        }
        if pin != qin {
            let t = (NEAR - p[2]) / (q[2] - p[2]);
            out.push([p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]), NEAR]);
        }
    }
    (out.len() >= 3).then_some(out)
}

fn edge(a: [f64; 3], b: [f64; 3], p: [f64; 3]) -> f64 {
    (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

fn normalize(a: [f64; 3]) -> [f64; 3] {
    let l = dot(a, a).sqrt();
    if l > 0.0 { [a[0] / l, a[1] / l, a[2] / l] } else { [0.0, 0.0, 1.0] }
}

/// A 5×7 bitmap font: digits, capitals and a few marks; anything else is a blank.
fn font_glyph(c: char) -> [u8; 7] {
    match c {
        '0' => [0x0E, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0E],
        '1' => [0x04, 0x0C, 0x04, 0x04, 0x04, 0x04, 0x0E],
        '2' => [0x0E, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1F],
        '3' => [0x1F, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0E],
        '4' => [0x02, 0x06, 0x0A, 0x12, 0x1F, 0x02, 0x02],
        '5' => [0x1F, 0x10, 0x1E, 0x01, 0x01, 0x11, 0x0E],
        '6' => [0x06, 0x08, 0x10, 0x1E, 0x11, 0x11, 0x0E],
        '7' => [0x1F, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08],
        '8' => [0x0E, 0x11, 0x11, 0x0E, 0x11, 0x11, 0x0E],
        '9' => [0x0E, 0x11, 0x11, 0x0F, 0x01, 0x02, 0x0C],
        'A' => [0x0E, 0x11, 0x11, 0x1F, 0x11, 0x11, 0x11],
        'B' => [0x1E, 0x11, 0x11, 0x1E, 0x11, 0x11, 0x1E],
        'C' => [0x0E, 0x11, 0x10, 0x10, 0x10, 0x11, 0x0E],
        'D' => [0x1C, 0x12, 0x11, 0x11, 0x11, 0x12, 0x1C],
        'E' => [0x1F, 0x10, 0x10, 0x1E, 0x10, 0x10, 0x1F],
        'F' => [0x1F, 0x10, 0x10, 0x1E, 0x10, 0x10, 0x10],
        'G' => [0x0E, 0x11, 0x10, 0x17, 0x11, 0x11, 0x0F],
        'H' => [0x11, 0x11, 0x11, 0x1F, 0x11, 0x11, 0x11],
        'I' => [0x0E, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0E],
        'J' => [0x07, 0x02, 0x02, 0x02, 0x02, 0x12, 0x0C],
        'K' => [0x11, 0x12, 0x14, 0x18, 0x14, 0x12, 0x11],
        'L' => [0x10, 0x10, 0x10, 0x10, 0x10, 0x10, 0x1F],
        'M' => [0x11, 0x1B, 0x15, 0x15, 0x11, 0x11, 0x11],
        'N' => [0x11, 0x11, 0x19, 0x15, 0x13, 0x11, 0x11],
        'O' => [0x0E, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0E],
        'P' => [0x1E, 0x11, 0x11, 0x1E, 0x10, 0x10, 0x10],
        'Q' => [0x0E, 0x11, 0x11, 0x11, 0x15, 0x12, 0x0D],
        'R' => [0x1E, 0x11, 0x11, 0x1E, 0x14, 0x12, 0x11],
        'S' => [0x0F, 0x10, 0x10, 0x0E, 0x01, 0x01, 0x1E],
        'T' => [0x1F, 0x04, 0x04, 0x04, 0x04, 0x04, 0x04],
        'U' => [0x11, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0E],
        'V' => [0x11, 0x11, 0x11, 0x11, 0x11, 0x0A, 0x04],
        'W' => [0x11, 0x11, 0x11, 0x15, 0x15, 0x15, 0x0A],
        'X' => [0x11, 0x11, 0x0A, 0x04, 0x0A, 0x11, 0x11],
        'Y' => [0x11, 0x11, 0x11, 0x0A, 0x04, 0x04, 0x04],
        'Z' => [0x1F, 0x01, 0x02, 0x04, 0x08, 0x10, 0x1F],
        '_' => [0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x1F],
        '-' => [0x00, 0x00, 0x00, 0x1F, 0x00, 0x00, 0x00],
        '.' => [0x00, 0x00, 0x00, 0x00, 0x00, 0x0C, 0x0C],
        ':' => [0x00, 0x0C, 0x0C, 0x00, 0x0C, 0x0C, 0x00],
        '/' => [0x01, 0x01, 0x02, 0x04, 0x08, 0x10, 0x10],
        _ => [0; 7],
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::box_mesh;

    #[test]
    fn a_box_in_front_of_the_camera_covers_the_centre_pixel() {
        let mesh = box_mesh([0.5; 3]);
        let cam = Camera::framing(&mesh.bounds(), 0.6, 0.5);
        let mut r = Renderer::new(64, 64, &cam, [255, 255, 255]);
        r.draw_mesh(&mesh, &Pose::IDENTITY, [1.0, 0.0, 0.0, 1.0]);
        let img = r.finish();
        let c = img.pixel(32, 32);
        assert!(c[0] > 80 && c[1] == 0 && c[2] == 0, "{c:?}");
        assert_eq!(img.pixel(0, 0), [255, 255, 255]);
    }

    #[test]
    fn nearer_surfaces_hide_farther_ones() {
        let cam = Camera { eye: [0.0, -5.0, 0.0], target: [0.0; 3], fov_y: 0.8 };
        let mut r = Renderer::new(32, 32, &cam, [0, 0, 0]);
        r.draw_mesh(&box_mesh([0.5; 3]), &Pose::from_pos([0.0, -1.0, 0.0]), [0.0, 1.0, 0.0, 1.0]);
        r.draw_mesh(&box_mesh([1.0; 3]), &Pose::from_pos([0.0, 2.0, 0.0]), [0.0, 0.0, 1.0, 1.0]);
        let img = r.finish();
        let c = img.pixel(16, 16);
        assert!(c[1] > 0 && c[2] == 0, "{c:?}");
    }
}
