#include "graspecmf/viz/html_view.hpp"

#include <fmt/format.h>

#include "graspecmf/core/error.hpp"

namespace graspecmf::viz {
namespace {

// Escapes the characters that matter in HTML text.
std::string escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '<') {
      out += "&lt;";
    } else if (c == '>') {
      out += "&gt;";
    } else if (c == '&') {
      out += "&amp;";
    } else {
      out += c;
    }
  }
  return out;
}

void append_point(std::string& out, const geometry::Vec3& p) {
  if (!p.allFinite()) throw Error("html view: a coordinate is not finite");
  out += fmt::format("{:.6g},{:.6g},{:.6g}", p.x(), p.y(), p.z());
}

// The viewer: orthographic projection, painter's algorithm for the triangles (sorted by depth on
// every redraw), Lambert shading with a light at the camera, segments drawn last.
constexpr const char* kScript = R"JS(
const scene = JSON.parse(document.getElementById('scene').textContent);
const canvas = document.getElementById('view');
const ctx = canvas.getContext('2d');
let yaw = 0.6, pitch = -1.1, zoom = 1.0, drag = null;
const V = scene.vertices, T = scene.triangles, S = scene.segments;
let lo = [1e9, 1e9, 1e9], hi = [-1e9, -1e9, -1e9];
for (let i = 0; i < V.length; i += 3)
  for (let k = 0; k < 3; ++k) { lo[k] = Math.min(lo[k], V[i + k]); hi[k] = Math.max(hi[k], V[i + k]); }
const centre = [0, 1, 2].map(k => (lo[k] + hi[k]) / 2);
const radius = Math.max(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
function rotate(p) {
  const x = p[0] - centre[0], y = p[1] - centre[1], z = p[2] - centre[2];
  const cy = Math.cos(yaw), sy = Math.sin(yaw), cp = Math.cos(pitch), sp = Math.sin(pitch);
  const x1 = cy * x - sy * y, y1 = sy * x + cy * y;
  return [x1, cp * y1 - sp * z, sp * y1 + cp * z];
}
function draw() {
  const w = canvas.width = canvas.clientWidth, h = canvas.height = canvas.clientHeight;
  const s = zoom * 0.8 * Math.min(w, h) / (2 * radius);
  const P = [];
  for (let i = 0; i < V.length; i += 3) P.push(rotate([V[i], V[i + 1], V[i + 2]]));
  const faces = [];
  for (let t = 0; t < T.length; t += 3) {
    const a = P[T[t]], b = P[T[t + 1]], c = P[T[t + 2]];
    const u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]], v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
    const n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
    const len = Math.hypot(n[0], n[1], n[2]) || 1;
    faces.push([a[2] + b[2] + c[2], a, b, c, Math.abs(n[2]) / len]);
  }
  faces.sort((f, g) => f[0] - g[0]);
  ctx.fillStyle = '#fff';
  ctx.fillRect(0, 0, w, h);
  for (const f of faces) {
    const shade = Math.round(60 + 170 * f[4]);
    ctx.fillStyle = ctx.strokeStyle = `rgb(${shade},${shade},${Math.min(255, shade + 25)})`;
    ctx.beginPath();
    for (const p of [f[1], f[2], f[3]]) ctx.lineTo(w / 2 + s * p[0], h / 2 - s * p[1]);
    ctx.closePath();
    ctx.fill();
    ctx.stroke();
  }
  ctx.lineWidth = 1.5;
  for (let i = 0; i < S.length; i += 9) {
    const a = rotate(S.slice(i, i + 3)), b = rotate(S.slice(i + 3, i + 6));
    ctx.strokeStyle = `rgb(${S[i + 6]},${S[i + 7]},${S[i + 8]})`;
    ctx.beginPath();
    ctx.moveTo(w / 2 + s * a[0], h / 2 - s * a[1]);
    ctx.lineTo(w / 2 + s * b[0], h / 2 - s * b[1]);
    ctx.stroke();
  }
}
canvas.onmousedown = e => { drag = [e.clientX, e.clientY]; };
window.onmouseup = () => { drag = null; };
window.onmousemove = e => {
  if (!drag) return;
  yaw += (e.clientX - drag[0]) * 0.01;
  pitch += (e.clientY - drag[1]) * 0.01;
  drag = [e.clientX, e.clientY];
  draw();
};
canvas.onwheel = e => { e.preventDefault(); zoom *= Math.exp(-e.deltaY * 0.001); draw(); };
window.onresize = draw;
draw();
)JS";

}  // namespace

std::string html_view(const geometry::TriangleMesh& mesh, const std::vector<Segment>& segments,
                      const std::string& title) {
  if (mesh.triangles.empty()) throw Error("html view: the mesh has no triangles");
  std::string data = "{\"vertices\":[";
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    if (i > 0) data += ',';
    append_point(data, mesh.vertices[i]);
  }
  data += "],\"triangles\":[";
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    data += fmt::format("{}{},{},{}", t > 0 ? "," : "", tri[0], tri[1], tri[2]);
  }
  data += "],\"segments\":[";
  for (std::size_t i = 0; i < segments.size(); ++i) {
    if (i > 0) data += ',';
    append_point(data, segments[i].a);
    data += ',';
    append_point(data, segments[i].b);
    const auto& c = segments[i].rgb;
    data += fmt::format(",{},{},{}", c[0], c[1], c[2]);
  }
  data += "]}";
  return fmt::format(R"(<!DOCTYPE html>
<html><head><meta charset="utf-8"><title>{0}</title>
<style>body{{margin:0;font:14px sans-serif}} #view{{width:100vw;height:calc(100vh - 2em);display:block}}
p{{margin:0.4em}}</style></head>
<body><p>{0} — drag to rotate, wheel to zoom</p><canvas id="view"></canvas>
<script id="scene" type="application/json">{1}</script>
<script>{2}</script>
</body></html>
)",
                     escaped(title), data, kScript);
}

}  // namespace graspecmf::viz
