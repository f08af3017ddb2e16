//! An HTML page with an interactive viewer of a 3D set: one self-contained file (the
//! triangles and a small hand-written canvas viewer inline), so it needs no network.
//!
//! The viewer draws the triangles back to front on a 2D canvas (painter's algorithm), in the
//! colours and opacities of the PNG pictures ([`super::scene3`]): negatively oriented glued
//! surfaces (cavities) opaque orange, positively oriented ones translucent blue. Dragging turns
//! the view (azimuth and elevation, starting from the given [`View`]); the wheel zooms.

use super::scene3::{Facet, View, NEGATIVE, OPACITY, POSITIVE};
use super::svg::escape;
use std::fmt::Write;

/// The viewer: draws `DATA` (flat corner coordinates `p`, orientation flags `s`) from the view
/// `VIEW` in degrees.
const VIEWER: &str = r#"
const canvas = document.getElementById('view');
const ctx = canvas.getContext('2d');
let az = VIEW[0], el = VIEW[1], zoom = 1;
const n = DATA.s.length, P = DATA.p;
let lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
for (let i = 0; i < P.length; i++) { lo[i % 3] = Math.min(lo[i % 3], P[i]); hi[i % 3] = Math.max(hi[i % 3], P[i]); }
const mid = [0, 1, 2].map(k => (lo[k] + hi[k]) / 2);
const radius = Math.max(1e-300, Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) / 2);
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
function draw() {
  const w = canvas.width = canvas.clientWidth * devicePixelRatio;
  const h = canvas.height = canvas.clientHeight * devicePixelRatio;
  const a = az * Math.PI / 180, e = el * Math.PI / 180;
  const t = [Math.cos(e) * Math.cos(a), Math.cos(e) * Math.sin(a), Math.sin(e)];
  const r = [-Math.sin(a), Math.cos(a), 0];
  const u = [t[1] * r[2] - t[2] * r[1], t[2] * r[0] - t[0] * r[2], t[0] * r[1] - t[1] * r[0]];
  const light = [0, 1, 2].map(k => t[k] + 0.5 * u[k] - 0.3 * r[k]);
  const ll = Math.hypot(...light);
  const s = zoom * 0.46 * Math.min(w, h) / radius;
  const xs = new Float64Array(3 * n), ys = new Float64Array(3 * n), depth = new Float64Array(n);
  for (let f = 0; f < n; f++) {
    let d = 0;
    for (let c = 0; c < 3; c++) {
      const i = 9 * f + 3 * c, q = [P[i] - mid[0], P[i + 1] - mid[1], P[i + 2] - mid[2]];
      xs[3 * f + c] = w / 2 + s * dot(q, r);
      ys[3 * f + c] = h / 2 - s * dot(q, u);
      d += dot(q, t);
    }
    depth[f] = d;
  }
  const order = Array.from({length: n}, (_, f) => f).sort((f, g) => depth[f] - depth[g]);
  ctx.fillStyle = '#fff';
  ctx.fillRect(0, 0, w, h);
  for (const f of order) {
    const i = 9 * f, e1 = [0, 1, 2].map(k => P[i + 3 + k] - P[i + k]), e2 = [0, 1, 2].map(k => P[i + 6 + k] - P[i + k]);
    const nv = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
    const nl = Math.hypot(...nv) * ll;
    const shade = nl > 0 ? 0.3 + 0.7 * Math.abs(dot(nv, light)) / nl : 0.3;
    const c = (DATA.s[f] ? POSITIVE : NEGATIVE).map(x => Math.round(x * shade));
    ctx.fillStyle = `rgb(${c[0]},${c[1]},${c[2]})`;
    ctx.strokeStyle = ctx.fillStyle;
    ctx.globalAlpha = DATA.s[f] ? OPACITY : 1;
    ctx.beginPath();
    ctx.moveTo(xs[3 * f], ys[3 * f]);
    ctx.lineTo(xs[3 * f + 1], ys[3 * f + 1]);
    ctx.lineTo(xs[3 * f + 2], ys[3 * f + 2]);
    ctx.closePath();
    ctx.fill();
    if (!DATA.s[f]) ctx.stroke();
  }
  ctx.globalAlpha = 1;
  document.getElementById('angles').textContent = `--view ${az.toFixed(0)},${el.toFixed(0)}`;
}
let drag = null;
canvas.addEventListener('pointerdown', ev => { drag = [ev.clientX, ev.clientY]; canvas.setPointerCapture(ev.pointerId); });
canvas.addEventListener('pointerup', () => { drag = null; });
canvas.addEventListener('pointermove', ev => {
  if (!drag) return;
  az -= (ev.clientX - drag[0]) * 0.5;
  el = Math.max(-90, Math.min(90, el + (ev.clientY - drag[1]) * 0.5));
  drag = [ev.clientX, ev.clientY];
  requestAnimationFrame(draw);
});
canvas.addEventListener('wheel', ev => { ev.preventDefault(); zoom *= Math.exp(-ev.deltaY * 0.001); requestAnimationFrame(draw); }, {passive: false});
addEventListener('resize', () => requestAnimationFrame(draw));
draw();
"#;

/// The HTML page showing `facets` from `view` at first, titled `title`.
pub fn write_html(facets: &[Facet], view: View, title: &str) -> String {
    let mut points = String::new();
    let mut signs = String::new();
    for (k, f) in facets.iter().enumerate() {
        let sep = if k == 0 { "" } else { "," };
        let corners: Vec<String> = f
            .corners
            .iter()
            .flatten()
            .map(|&x| json_number(x))
            .collect();
        let _ = write!(points, "{sep}{}", corners.join(","));
        let _ = write!(signs, "{sep}{}", u8::from(f.positive));
    }
    let title = escape(title);
    let colour = |c: [u8; 3]| format!("[{},{},{}]", c[0], c[1], c[2]);
    format!(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <title>{title}</title>\n<style>\nhtml, body {{ margin: 0; height: 100%; font: 14px sans-serif; }}\n\
         #view {{ width: 100%; height: calc(100% - 2.2em); display: block; touch-action: none; }}\n\
         p {{ margin: 0.5em; }}\n</style>\n</head>\n<body>\n<canvas id=\"view\"></canvas>\n\
         <p>{title}: {n} triangles; blue translucent: positively oriented surfaces, orange: \
         cavities (negatively oriented). Drag to turn, wheel to zoom. <code id=\"angles\"></code></p>\n\
         <script>\nconst DATA = {{\"p\": [{points}], \"s\": [{signs}]}};\n\
         const VIEW = [{az}, {el}];\nconst POSITIVE = {pos}, NEGATIVE = {neg}, OPACITY = {opacity};\n\
         {VIEWER}</script>\n</body>\n</html>\n",
        n = facets.len(),
        az = json_number(view.azimuth),
        el = json_number(view.elevation),
        pos = colour(POSITIVE),
        neg = colour(NEGATIVE),
        opacity = OPACITY,
    )
}

/// `x` as a JavaScript number literal, to `f32` precision (plenty for a picture).
fn json_number(x: f64) -> String {
    let x = x as f32;
    if x.is_finite() {
        x.to_string()
    } else {
        "0".to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn page_holds_the_triangles_and_needs_no_network() {
        let f = Facet {
            corners: [[0.0, 0.5, 1.0], [2.0, 0.0, 0.0], [0.0, 0.0, -3.0]],
            positive: false,
        };
        let page = write_html(
            &[
                f,
                Facet {
                    positive: true,
                    ..f
                },
            ],
            View::default(),
            "a<b>.obj",
        );
        assert!(
            page.contains(
                "const DATA = {\"p\": [0,0.5,1,2,0,0,0,0,-3,0,0.5,1,2,0,0,0,0,-3], \"s\": [0,1]};"
            ),
            "{page}"
        );
        assert!(page.contains("const VIEW = [-60, 25];"));
        assert!(page.contains("<title>a&lt;b&gt;.obj</title>"));
        for remote in ["http:", "https:", "src=", "import "] {
            assert!(!page.contains(remote), "{remote}");
        }
    }
}
