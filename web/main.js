// The live page: runs a built-in fixstep scene in wasm at its tick rate and draws it with
// three.js. URL parameters: scene=NAME (default showcase), ticks=N (run N ticks, then stop
// and show the checksum), kernels=scalar (load the package built without simd128),
// replay=URL (play that replay file instead of a scene). A page written by
// `fixstep render REPLAY --html PAGE` plays the replay it embeds (window.fixstepReplay).
// A dropped .replay file is verified; a click on a body pushes it (an ApplyImpulse command,
// recorded); "download replay" saves the run for `fixstep verify`.
import * as THREE from 'three';
import { OrbitControls } from './vendor/OrbitControls.js';
import { SceneView } from './scene-view.js';

const params = new URLSearchParams(location.search);
const scalar = params.get('kernels') === 'scalar';
const pkg = await import(scalar ? './pkg/scalar/fixstep_web.js' : './pkg/fixstep_web.js');
await pkg.default();

const $ = (id) => document.getElementById(id);
const status = (text, verdict = '') => {
  $('status').textContent = text;
  $('status').dataset.verdict = verdict;
};
let stopAt = params.has('ticks') ? Number(params.get('ticks')) : Infinity;
$('kernels').textContent = `wasm ${pkg.kernels()}`;

const canvas = $('view');
const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(Math.min(devicePixelRatio, 2));
renderer.shadowMap.enabled = true;
const world = new THREE.Scene();
world.background = new THREE.Color(0x20242c);
world.add(new THREE.HemisphereLight(0xdde6ff, 0x3a3128, 1.1));
const sun = new THREE.DirectionalLight(0xffffff, 2.2);
sun.castShadow = true;
sun.shadow.mapSize.set(2048, 2048);
sun.shadow.bias = -0.0005;
sun.shadow.normalBias = 0.02;
world.add(sun, sun.target);
const camera = new THREE.PerspectiveCamera(50, 1, 0.05, 500);
const controls = new OrbitControls(camera, canvas);
controls.enableDamping = true;

let session = null;
let view = null;
let paused = false;
let started = 0;
let done = 0;

for (const name of pkg.scenes()) {
  const option = new Option(name, name);
  option.title = pkg.sceneDescription(name);
  $('scene').add(option);
}

// Points the camera and the sun's shadow at what moves.
function frame() {
  const box = view.bounds();
  const centre = box.getCenter(new THREE.Vector3());
  const radius = Math.max(box.getSize(new THREE.Vector3()).length() / 2, 1);
  controls.target.copy(centre);
  camera.position.copy(centre).add(new THREE.Vector3(0.9, 0.7, 1.3).multiplyScalar(radius * 1.6));
  camera.near = radius / 100;
  camera.far = radius * 50;
  sun.position.copy(centre).add(new THREE.Vector3(0.5, 1, 0.35).multiplyScalar(radius * 3));
  sun.target.position.copy(centre);
  const s = sun.shadow.camera;
  s.left = s.bottom = -radius * 1.5;
  s.right = s.top = radius * 1.5;
  s.near = radius * 0.5;
  s.far = radius * 6;
  s.updateProjectionMatrix();
  camera.updateProjectionMatrix();
  controls.update();
}

// The replay the page plays instead of a scene: {name, bytes} (null: a scene).
let replay = null;

function load(name) {
  view?.dispose();
  session?.free();
  session = null;
  session = replay ? pkg.Session.fromReplay(replay.bytes, replay.name) : pkg.Session.builtin(name);
  if (replay) {
    stopAt = Math.min(stopAt, session.recordedTicks);
    status(`playing ${replay.name}: ${session.recordedTicks} ticks of ${session.name}`);
  }
  view = new SceneView(session, world);
  $('scene').value = session.name;
  frame();
  started = performance.now();
  done = 0;
  show();
}

function show() {
  $('tick').textContent = session.tick;
  $('checksum').textContent = session.checksum();
  $('commands').textContent = session.commandTicks;
  document.body.dataset.tick = session.tick;
}

function resize() {
  const { clientWidth: w, clientHeight: h } = canvas;
  if (canvas.width !== Math.round(w * renderer.getPixelRatio())) {
    renderer.setSize(w, h, false);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
  }
}

// One animation frame: the ticks due at the scene's tick rate (at most 4 a frame, so a
// slow scene slows down instead of stalling), then the picture.
function animate(now) {
  if (session && !paused && session.tick < stopAt) {
    let due = Math.floor(((now - started) / 1000) * session.tickRate) - done;
    if (due > 4) { done += due - 4; due = 4; } // behind: drop the backlog
    const ticks = Math.max(0, Math.min(due, 4, stopAt - session.tick));
    if (ticks > 0) {
      session.step(ticks);
      done += ticks;
      view.update();
      show();
    }
    if (session.tick >= stopAt && !document.body.dataset.done) {
      document.body.dataset.done = '1';
      if (replay && session.tick === session.recordedTicks) {
        const same = session.checksum() === session.recordedChecksum;
        status(same
          ? `${replay.name}: ${session.tick} ticks, checksum ${session.checksum()} as recorded`
          : `${replay.name}: checksum ${session.checksum()} at tick ${session.tick}, recorded ${session.recordedChecksum}`,
        same ? 'ok' : 'desync');
      }
    }
  } else if (session) {
    done = Math.floor(((now - started) / 1000) * session.tickRate);
  }
  resize();
  controls.update();
  renderer.render(world, camera);
  if (!document.body.dataset.firstFrame) {
    document.body.dataset.firstFrame = String(Math.round(now));
  }
  requestAnimationFrame(animate);
}

// Click (not drag) on a dynamic body: push it 3 m/s along the view ray, at the hit point.
const pointer = new THREE.Vector2();
let down = null;
canvas.addEventListener('pointerdown', (e) => { down = [e.clientX, e.clientY]; });
canvas.addEventListener('pointerup', (e) => {
  if (!down || Math.hypot(e.clientX - down[0], e.clientY - down[1]) > 5 || e.button !== 0) return;
  pointer.set((e.clientX / canvas.clientWidth) * 2 - 1, -(e.clientY / canvas.clientHeight) * 2 + 1);
  const ray = new THREE.Raycaster();
  ray.setFromCamera(pointer, camera);
  const hit = ray.intersectObjects(view.bodies, false).find((h) => h.object.userData.dynamic);
  if (!hit) return;
  const [index, generation] = view.handleOf(hit.object);
  const d = ray.ray.direction;
  const p = hit.point;
  if (session.queueImpulse(index, generation, d.x, d.y, d.z, p.x, p.y, p.z, 3.0)) {
    status(`push on body ${index}v${generation} queued for tick ${session.tick}`);
  }
});

// A dropped replay: verified as `fixstep verify` does.
async function verifyFile(file) {
  const bytes = new Uint8Array(await file.arrayBuffer());
  try {
    const v = pkg.verifyReplay(bytes, file.name);
    if (v.verdict === 'ok') {
      status(`verified: ${v.line}`, 'ok');
    } else {
      status(`first desync at tick ${v.tick}: subsystem ${v.subsystem}, object ${v.object}\n${v.line}`, 'desync');
    }
    v.free();
  } catch (error) {
    status(`error: ${error.message}`, 'error');
  }
}
window.addEventListener('dragover', (e) => { e.preventDefault(); document.body.classList.add('dragging'); });
window.addEventListener('dragleave', () => document.body.classList.remove('dragging'));
window.addEventListener('drop', (e) => {
  e.preventDefault();
  document.body.classList.remove('dragging');
  const file = e.dataTransfer?.files?.[0];
  if (file) window.fixstepPage.verifying = verifyFile(file);
});

$('scene').addEventListener('change', () => {
  replay = null;
  stopAt = Infinity;
  const url = new URL(location.href);
  url.searchParams.set('scene', $('scene').value);
  history.replaceState(null, '', url);
  load($('scene').value);
});
$('pause').addEventListener('click', () => {
  paused = !paused;
  $('pause').textContent = paused ? 'play' : 'pause';
});
$('restart').addEventListener('click', () => {
  delete document.body.dataset.done;
  load(session.name);
});
$('download').addEventListener('click', () => {
  try {
    const bytes = session.replay();
    const link = document.createElement('a');
    link.href = URL.createObjectURL(new Blob([bytes], { type: 'application/octet-stream' }));
    link.download = `${session.name}-${session.tick}.replay`;
    link.click();
    setTimeout(() => URL.revokeObjectURL(link.href), 10000);
    status(`replay of ${session.tick} ticks downloaded: check it with fixstep verify ${link.download}`);
  } catch (error) {
    status(`error: ${error.message}`, 'error');
  }
});

// For scripts (scripts/web-test.mjs) and the console: the session, the view and the
// projection of a body to the canvas.
window.fixstepPage = {
  pkg,
  get session() { return session; },
  get view() { return view; },
  screenPoint(i) {
    const v = view.bodies[i].getWorldPosition(new THREE.Vector3()).project(camera);
    return [(v.x + 1) / 2 * canvas.clientWidth, (1 - v.y) / 2 * canvas.clientHeight];
  },
  verifying: null,
};

try {
  if (window.fixstepReplay) {
    const { name, base64 } = window.fixstepReplay;
    replay = { name, bytes: Uint8Array.from(atob(base64), (c) => c.charCodeAt(0)) };
  } else if (params.has('replay')) {
    const url = new URL(params.get('replay'), location.href);
    const response = await fetch(url);
    if (!response.ok) throw new Error(`${url}: HTTP ${response.status}`);
    replay = { name: url.pathname.split('/').pop(), bytes: new Uint8Array(await response.arrayBuffer()) };
  }
  load(params.get('scene') ?? 'showcase');
} catch (error) {
  status(`error: ${error.message}`, 'error');
}
requestAnimationFrame(animate);
