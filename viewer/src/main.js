// The page `antipode view` writes: scenes (a cloud and the hands found in it) in 3D, a clear-
// the-box run cycle by cycle, and a tree run's trace. The page is one HTML file; this script
// (three.js bundled in) reads the data the command embedded in the <script id="antipode-data">
// element and fetches nothing. The data's schema: docs/viewer.md.

import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';

import { buildPanel, handFacts, NEIGHBOUR_RADIUS_M } from './panel.js';
import { buildLayers } from './scene_layers.js';
import { handsOf, neighbours } from './hand_table.js';
import { buildRunPanel } from './run_panel.js';
import { buildTracePanel } from './trace_panel.js';

const data = JSON.parse(document.getElementById('antipode-data').textContent);
const scenes = data.scenes || [];

const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio);
renderer.setSize(window.innerWidth, window.innerHeight);
document.getElementById('view').appendChild(renderer.domElement);

const world = new THREE.Scene();
world.background = new THREE.Color(0xf4f4f4);
world.add(new THREE.AmbientLight(0xffffff, 1.6));
const sun = new THREE.DirectionalLight(0xffffff, 1.4);
sun.position.set(1, 2, 3);
world.add(sun);

const camera = new THREE.PerspectiveCamera(45, window.innerWidth / window.innerHeight, 0.001, 100);
const controls = new OrbitControls(camera, renderer.domElement);
const render = () => renderer.render(world, camera);
controls.addEventListener('change', render);
window.addEventListener('resize', () => {
  camera.aspect = window.innerWidth / window.innerHeight;
  camera.updateProjectionMatrix();
  renderer.setSize(window.innerWidth, window.innerHeight);
  render();
});

// The "up" of a scene's frame: a sensor frame looks along +z with y down; other frames (a
// robot's base, the world) have z up.
const upOf = (scene) => (scene.frame === 'sensor' ? new THREE.Vector3(0, -1, 0) : new THREE.Vector3(0, 0, 1));

// Around the cloud, looking at its centre, from the side and above.
function fitCamera(layers, up) {
  const sphere = layers.cloud.points.geometry.boundingSphere;
  if (!sphere || !(sphere.radius > 0)) return;
  camera.up.copy(up);
  const side = new THREE.Vector3(1, 0, 0).cross(up).normalize();
  camera.position
    .copy(sphere.center)
    .addScaledVector(side, -2.2 * sphere.radius)
    .addScaledVector(up, 1.2 * sphere.radius);
  controls.target.copy(sphere.center);
  controls.update();
}

// ---- the scene shown ----
let current = -1;
let layers = null;
let hands = [];
let picked = -1; // the hand last clicked, drawn red
let handMode = ['score', []];
let fitted = false;
const decoded = new Map();

const panel = buildPanel(document.getElementById('panel'), data, {
  colourCloud: (mode) => {
    layers?.colourCloud(mode);
    render();
  },
  colourHands: (mode, reasons) => {
    handMode = [mode, reasons];
    layers?.colourHands(mode, reasons, picked);
    render();
  },
  showHands: (visible) => {
    layers?.showHands(visible);
    render();
  },
  armAt: (k) => {
    layers?.armAt(k);
    render();
  },
  showSupport: (shown) => {
    layers?.showSupport(shown);
    render();
  },
});

function showScene(k) {
  if (k === current || k < 0 || k >= scenes.length) return;
  layers?.dispose();
  current = k;
  picked = -1;
  if (!decoded.has(k)) decoded.set(k, handsOf(scenes[k].hands));
  hands = decoded.get(k);
  layers = buildLayers(world, scenes[k], hands, data.gripper, upOf(scenes[k]));
  if (!fitted && layers.cloud.count > 0) {
    fitCamera(layers, upOf(scenes[k]));
    fitted = true;
  }
  panel.setScene(scenes[k], hands);
  render();
}

// ---- picking a hand: the click's ray against the hands' boxes ----
const raycaster = new THREE.Raycaster();
function handAt(clientX, clientY) {
  if (!layers) return -1;
  const rect = renderer.domElement.getBoundingClientRect();
  const ndc = new THREE.Vector2(
    ((clientX - rect.left) / rect.width) * 2 - 1,
    -((clientY - rect.top) / rect.height) * 2 + 1,
  );
  raycaster.setFromCamera(ndc, camera);
  return layers.handAt(raycaster);
}

let pressed = null;
renderer.domElement.addEventListener('pointerdown', (e) => {
  pressed = [e.clientX, e.clientY];
});
renderer.domElement.addEventListener('pointerup', (e) => {
  if (!pressed || Math.hypot(e.clientX - pressed[0], e.clientY - pressed[1]) > 4) return;
  picked = handAt(e.clientX, e.clientY);
  layers?.colourHands(...handMode, picked);
  render();
  panel.showHand(picked);
});

// ---- the run and the trace ----
const side = document.getElementById('side');
const runPanel = data.run ? buildRunPanel(side, data.run, scenes, showScene) : null;
const tracePanel = data.trace ? buildTracePanel(side, data.trace) : null;
if (!runPanel && !tracePanel) side.remove();
if (scenes.length === 0) document.getElementById('panel').remove();

if (runPanel) {
  // The first cycle with a scene to show.
  const first = data.run.runs.flatMap((r, ri) => r.cycles.map((c, ci) => [ri, ci, c])).find(([, , c]) => scenes[c.scene].cloud);
  if (first) runPanel.choose(first[0], first[1]);
} else if (scenes.length > 0) {
  showScene(0);
}
render();

// What the browser test and a script can ask of the page.
window.antipodeView = {
  ready: true,
  loadMs: performance.now(),
  get scene() {
    return current;
  },
  get points() {
    return layers ? layers.cloud.count : 0;
  },
  get hands() {
    return hands.length;
  },
  // The hand drawn at a point of the page (CSS pixels), or -1.
  handAt,
  // The page position of hand i's palm, for a test to click it.
  screenPositionOf(i) {
    const centre = new THREE.Vector3().fromArray(hands[i].position_m);
    const approach = new THREE.Vector3(1, 0, 0).applyQuaternion(new THREE.Quaternion().fromArray(hands[i].quaternion_xyzw));
    centre.addScaledVector(approach, -0.5 * data.gripper.palm_thickness_m);
    const ndc = centre.project(camera);
    const rect = renderer.domElement.getBoundingClientRect();
    return [rect.left + ((ndc.x + 1) / 2) * rect.width, rect.top + ((1 - ndc.y) / 2) * rect.height];
  },
  // What the panel says of hand i, as {key: value}.
  facts: (i) => Object.fromEntries(handFacts(hands, i, scenes[current] || {})),
  // The chosen grasp (rank 1) of the scene shown: {index, rank, score}, or null.
  chosen() {
    const i = hands.findIndex((h) => h.rank === 1);
    return i < 0 ? null : { index: i, rank: hands[i].rank, score: hands[i].score };
  },
  // The hands around hand i, as the panel lists them: [{index, distance_m, rejection}].
  neighbours: (i) => neighbours(hands, i, NEIGHBOUR_RADIUS_M),
  // How many points of the scene shown have each label: {segment id: count}, -1 the support,
  // -2 the rest ({} when the page has no segments).
  segmentCounts() {
    const counts = {};
    for (const label of layers?.cloud.segments || []) counts[label] = (counts[label] || 0) + 1;
    return counts;
  },
  // How many points of the scene shown each view mask has: {mask: count} ({} without views).
  viewCounts() {
    const counts = {};
    for (const mask of layers?.cloud.views || []) counts[mask] = (counts[mask] || 0) + 1;
    return counts;
  },
  // The waypoints of the arm's planned path in the scene shown (0 without one).
  waypoints: () => scenes[current]?.path?.waypoints.length ?? 0,
  // The scene's executed grasp, or -1.
  executed: () => scenes[current]?.executed ?? -1,
  showScene,
  chooseCycle: (run, cycle) => runPanel?.choose(run, cycle),
  traceStep: (k) => tracePanel?.step(k),
};
document.body.dataset.ready = 'true';
