// The fixstep film player: draws the embedded frames on a canvas, with the same painter's
// algorithm as the Rust rasteriser (src/viewer/raster.rs). No network, no libraries.
// ?stop=T pauses at the first frame at or after tick T; ?view=NAME picks the view.
"use strict";
const film = JSON.parse(document.getElementById("film").textContent);
const canvas = document.getElementById("view");
const ctx = canvas.getContext("2d");
const overlay = document.getElementById("overlay");
const playButton = document.getElementById("play");
const scrub = document.getElementById("scrub");
const views = document.getElementById("views");
const energyCanvas = document.getElementById("energy");
const params = new URLSearchParams(location.search);
const stopTick = params.has("stop") ? Number(params.get("stop")) : Infinity;
canvas.width = film.width;
canvas.height = film.height;
scrub.max = String(film.frames.length - 1);
for (const name of Object.keys(film.views)) {
  const option = document.createElement("option");
  option.value = option.textContent = name;
  views.appendChild(option);
}
let view = film.views[params.get("view")] ? params.get("view") : film.view;
views.value = view;
let index = 0;
let playing = true;

const LIGHT = normalize([0.3, 0.85, 0.45]);
const unit = Math.min(film.width, film.height);
function dot(a, b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
function normalize(a) { const l = Math.hypot(a[0], a[1], a[2]); return l > 0 ? a.map(c => c / l) : [0, 0, 0]; }
function cross(a, b) { return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]; }
function colour(rgb, light) {
  const k = Math.min(Math.max(light, 0), 1);
  return "rgb(" + [(rgb >> 16) & 255, (rgb >> 8) & 255, rgb & 255].map(c => Math.round(c * k)).join(",") + ")";
}
function mix(rgb, toward, f) {
  return "rgb(" + [(rgb >> 16) & 255, (rgb >> 8) & 255, rgb & 255].map(c => Math.round(c + (toward - c) * f)).join(",") + ")";
}
function lighting(n) { return 0.55 + 0.45 * Math.max(0, dot(n, LIGHT)); }

// An item is [kind, layer, rgb, ...numbers]: 0 dot x y z · 1 line a b · 2 ball c r ·
// 3 capsule a b r · 4 cuboid c h0 h1 h2 · 5 polygon n corners · 6 ground polygon n corners.
function point(item, at) { return [item[at], item[at + 1], item[at + 2]]; }
function corners(item) {
  const out = [];
  for (let k = 0; k < item[3]; k++) out.push(point(item, 4 + 3 * k));
  return out;
}
function centre(item) {
  switch (item[0]) {
    case 0: case 2: case 4: return point(item, 3);
    case 1: case 3: { const a = point(item, 3), b = point(item, 6); return [0, 1, 2].map(k => (a[k] + b[k]) / 2); }
    default: {
      const cs = corners(item), c = [0, 0, 0];
      for (const p of cs) for (let k = 0; k < 3; k++) c[k] += p[k] / Math.max(cs.length, 1);
      return c;
    }
  }
}

function draw() {
  const frame = film.frames[index];
  const v = film.views[view];
  const screen = p => [v.cx + v.s * dot(p, v.r), v.cy - v.s * dot(p, v.u)];
  ctx.fillStyle = colour(film.background, 1);
  ctx.fillRect(0, 0, canvas.width, canvas.height);
  const order = frame.items.map((item, i) => [item[1], item[0] === 6 ? -Infinity : dot(centre(item), v.t), i]);
  order.sort((a, b) => a[0] - b[0] || (a[1] < b[1] ? -1 : a[1] > b[1] ? 1 : 0) || a[2] - b[2]);
  ctx.lineJoin = "round";
  for (const [, , i] of order) {
    const item = frame.items[i], rgb = item[2];
    switch (item[0]) {
      case 0: { const [x, y] = screen(point(item, 3)); circle(x, y, Math.max(unit / 220, 1.5), colour(rgb, 1)); break; }
      case 1: segment(screen(point(item, 3)), screen(point(item, 6)), Math.max(unit / 400, 1), colour(rgb, 1)); break;
      case 2: ball(screen(point(item, 3)), item[6] * v.s, rgb); break;
      case 3: {
        const a = screen(point(item, 3)), b = screen(point(item, 6)), w = 2 * item[9] * v.s;
        if (!film.flat) segment(a, b, w + 2, colour(rgb, 0.55));
        segment(a, b, Math.max(w, 1), colour(rgb, 1));
        break;
      }
      case 4: {
        const c = point(item, 3), h = [point(item, 6), point(item, 9), point(item, 12)];
        for (let k = 0; k < 3; k++) {
          const i1 = (k + 1) % 3, i2 = (k + 2) % 3;
          for (const sign of [1, -1]) {
            const n = normalize(h[k].map(x => x * sign));
            if (dot(n, v.t) <= 1e-9) continue;
            const m = c.map((x, j) => x + sign * h[k][j]);
            const u = h[i1], w = h[i2];
            const face = [[1, 1], [-1, 1], [-1, -1], [1, -1]].map(([a, b]) => m.map((x, j) => x + a * u[j] + b * w[j]));
            polygon(face.map(screen), rgb, film.flat ? 1 : lighting(n));
          }
        }
        break;
      }
      case 5: {
        const cs = corners(item);
        let light = 1;
        if (!film.flat && cs.length >= 3) {
          const n = normalize(cross(cs[1].map((x, j) => x - cs[0][j]), cs[2].map((x, j) => x - cs[0][j])));
          light = 0.55 + 0.45 * Math.abs(dot(n, LIGHT));
        }
        polygon(cs.map(screen), rgb, light);
        break;
      }
      case 6: polygon(corners(item).map(screen), rgb, 1); break;
    }
  }
  const time = frame.tick / film.tickRate;
  overlay.textContent = "tick " + frame.tick + "  t = " + time.toFixed(3) + " s\n" +
    "energy " + frame.energy.toPrecision(6) + " J\nchecksum " + frame.checksum;
  scrub.value = String(index);
  document.body.dataset.tick = String(frame.tick);
  drawEnergy();
}

function polygon(points, rgb, light) {
  if (points.length < 3) return;
  ctx.beginPath();
  ctx.moveTo(points[0][0], points[0][1]);
  for (const p of points.slice(1)) ctx.lineTo(p[0], p[1]);
  ctx.closePath();
  ctx.fillStyle = colour(rgb, light);
  ctx.fill();
  if (!film.flat) { ctx.strokeStyle = colour(rgb, light * 0.6); ctx.lineWidth = 1; ctx.stroke(); }
}
function circle(x, y, r, style) {
  ctx.beginPath();
  ctx.arc(x, y, Math.max(r, 0.5), 0, 2 * Math.PI);
  ctx.fillStyle = style;
  ctx.fill();
}
function segment(a, b, width, style) {
  if (Math.hypot(a[0] - b[0], a[1] - b[1]) < 0.25) { circle(a[0], a[1], Math.max(width / 2, 1), style); return; }
  ctx.beginPath();
  ctx.moveTo(a[0], a[1]);
  ctx.lineTo(b[0], b[1]);
  ctx.lineCap = "round";
  ctx.lineWidth = width;
  ctx.strokeStyle = style;
  ctx.stroke();
}
function ball([x, y], r, rgb) {
  r = Math.max(r, 0.75);
  if (film.flat) { circle(x, y, r, colour(rgb, 1)); return; }
  const g = ctx.createRadialGradient(x - 0.35 * r, y - 0.35 * r, 0, x, y, r);
  g.addColorStop(0, mix(rgb, 255, 2 / 3));
  g.addColorStop(0.45, colour(rgb, 1));
  g.addColorStop(1, colour(rgb, 0.62));
  circle(x, y, r, g);
  ctx.strokeStyle = colour(rgb, 0.5);
  ctx.lineWidth = 1;
  ctx.stroke();
}

// The energy of every frame as a line, with the current frame marked.
function drawEnergy() {
  const e = energyCanvas.getContext("2d"), w = energyCanvas.width, h = energyCanvas.height;
  const values = film.frames.map(f => f.energy);
  let lo = Math.min(...values), hi = Math.max(...values);
  if (!(hi > lo)) { lo -= 1; hi += 1; }
  const x = i => 4 + (w - 8) * i / Math.max(values.length - 1, 1);
  const y = value => h - 14 - (h - 20) * (value - lo) / (hi - lo);
  e.clearRect(0, 0, w, h);
  e.strokeStyle = "#457b9d";
  e.lineWidth = 1.5;
  e.beginPath();
  values.forEach((value, i) => (i ? e.lineTo(x(i), y(value)) : e.moveTo(x(i), y(value))));
  e.stroke();
  e.fillStyle = "#e76f51";
  e.beginPath();
  e.arc(x(index), y(values[index]), 3, 0, 2 * Math.PI);
  e.fill();
  e.fillStyle = "#1d2330";
  e.font = "10px ui-monospace, monospace";
  e.fillText("energy, J", 4, h - 3);
}

function setPlaying(on) {
  playing = on;
  playButton.textContent = on ? "Pause" : "Play";
}
playButton.addEventListener("click", () => {
  if (!playing && index === film.frames.length - 1) index = 0;
  setPlaying(!playing);
});
scrub.addEventListener("input", () => { index = Number(scrub.value); setPlaying(false); draw(); });
views.addEventListener("change", () => { view = views.value; draw(); });

const framePeriod = 1000 * film.every / film.tickRate;
function advance() {
  if (playing) {
    if (film.frames[index].tick >= stopTick || index === film.frames.length - 1) setPlaying(false);
    else { index += 1; draw(); if (film.frames[index].tick >= stopTick) setPlaying(false); }
  }
  setTimeout(advance, framePeriod);
}
draw();
setTimeout(advance, framePeriod);
