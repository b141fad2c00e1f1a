// The page `antipode view` writes: a cloud and the hands found in it, in 3D. The page is one
// HTML file; this script (three.js bundled in) reads the data the command embedded in the
// <script id="antipode-data"> element and fetches nothing. The data's schema: docs/view.md.

import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';

import { decodeFloat32 } from './base64.js';
import { buildPanel } from './panel.js';
import { handMatrices } from './hand_geometry.js';
import { categoryColour, scoreColour } from './colours.js';

const data = JSON.parse(document.getElementById('antipode-data').textContent);
const hands = data.hands || [];

const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio);
renderer.setSize(window.innerWidth, window.innerHeight);
document.getElementById('view').appendChild(renderer.domElement);

const scene = new THREE.Scene();
scene.background = new THREE.Color(0xf4f4f4);
scene.add(new THREE.AmbientLight(0xffffff, 1.6));
const sun = new THREE.DirectionalLight(0xffffff, 1.4);
sun.position.set(1, 2, 3);
scene.add(sun);

// ---- the cloud ----
const cloud = data.cloud;
const positions = decodeFloat32(cloud.points);
const cloudGeometry = new THREE.BufferGeometry();
cloudGeometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
const cloudColours = new Float32Array(positions.length);
cloudGeometry.setAttribute('color', new THREE.BufferAttribute(cloudColours, 3));
cloudGeometry.computeBoundingSphere();
const points = new THREE.Points(
  cloudGeometry,
  new THREE.PointsMaterial({ size: 2, sizeAttenuation: false, vertexColors: true }),
);
scene.add(points);

// The "up" of the data's frame: a sensor frame looks along +z with y down; other frames
// (a robot's base, the world) have z up.
const up = data.frame === 'sensor' ? new THREE.Vector3(0, -1, 0) : new THREE.Vector3(0, 0, 1);

function colourCloud(mode) {
  const count = positions.length / 3;
  let lo = Infinity;
  let hi = -Infinity;
  const height = (i) =>
    positions[3 * i] * up.x + positions[3 * i + 1] * up.y + positions[3 * i + 2] * up.z;
  if (mode === 'height') {
    for (let i = 0; i < count; i++) {
      const h = height(i);
      lo = Math.min(lo, h);
      hi = Math.max(hi, h);
    }
  }
  const c = new THREE.Color();
  for (let i = 0; i < count; i++) {
    if (mode === 'height') c.copy(scoreColour((height(i) - lo) / Math.max(hi - lo, 1e-9)));
    else c.setRGB(0.45, 0.45, 0.45);
    cloudColours[3 * i] = c.r;
    cloudColours[3 * i + 1] = c.g;
    cloudColours[3 * i + 2] = c.b;
  }
  cloudGeometry.attributes.color.needsUpdate = true;
}

// ---- the hands: fingers and palm as boxes of the gripper's real size, all in one mesh ----
// One merged geometry, not instances: software renderers (a headless browser's SwiftShader)
// draw a 5,000-hand page in a second this way, and minutes with instancing.
const box = new THREE.BoxGeometry(1, 1, 1).toNonIndexed();
const perHand = 3 * box.attributes.position.count; // vertices of a hand's three boxes
const handGeometry = new THREE.BufferGeometry();
const handPositions = new Float32Array(3 * perHand * hands.length);
const handNormals = new Float32Array(3 * perHand * hands.length);
const handColours = new Float32Array(3 * perHand * hands.length);
{
  const v = new THREE.Vector3();
  const normal = new THREE.Matrix3();
  let at = 0;
  hands.forEach((hand) => {
    for (const matrix of handMatrices(hand, data.gripper)) {
      normal.getNormalMatrix(matrix);
      for (let k = 0; k < box.attributes.position.count; k++, at += 3) {
        v.fromBufferAttribute(box.attributes.position, k).applyMatrix4(matrix).toArray(handPositions, at);
        v.fromBufferAttribute(box.attributes.normal, k).applyMatrix3(normal).normalize().toArray(handNormals, at);
      }
    }
  });
}
handGeometry.setAttribute('position', new THREE.BufferAttribute(handPositions, 3));
handGeometry.setAttribute('normal', new THREE.BufferAttribute(handNormals, 3));
handGeometry.setAttribute('color', new THREE.BufferAttribute(handColours, 3));
const handMesh = new THREE.Mesh(handGeometry, new THREE.MeshLambertMaterial({ vertexColors: true }));
scene.add(handMesh);

const scores = hands.map((h) => (typeof h.score === 'number' ? h.score : 0));
const scoreLo = Math.min(...scores, 0);
const scoreHi = Math.max(...scores, 1e-9);
const reasonOf = (hand) => hand.rejection || 'accepted';

let picked = -1; // the hand last clicked, drawn red
let handMode = ['score', []];

function colourHands(mode, reasons) {
  handMode = [mode, reasons];
  const c = new THREE.Color();
  hands.forEach((hand, i) => {
    if (mode === 'reason') c.copy(categoryColour(reasons.indexOf(reasonOf(hand))));
    else c.copy(scoreColour((scores[i] - scoreLo) / Math.max(scoreHi - scoreLo, 1e-9)));
    if (i === picked) c.setRGB(0.9, 0.1, 0.1);
    for (let k = i * perHand; k < (i + 1) * perHand; k++) c.toArray(handColours, 3 * k);
  });
  handGeometry.attributes.color.needsUpdate = true;
}

// Draws only the hands `visible` keeps: the mesh's index lists their vertices.
function showHands(visible) {
  const kept = [];
  hands.forEach((hand, i) => {
    if (visible(hand, i)) kept.push(i);
  });
  const index = new Uint32Array(kept.length * perHand);
  kept.forEach((i, n) => {
    for (let k = 0; k < perHand; k++) index[n * perHand + k] = i * perHand + k;
  });
  handGeometry.setIndex(new THREE.BufferAttribute(index, 1));
  handGeometry.computeBoundingSphere();
}

// ---- camera: around the cloud, looking at its centre ----
const sphere = cloudGeometry.boundingSphere;
const camera = new THREE.PerspectiveCamera(45, window.innerWidth / window.innerHeight, 0.001, 100);
camera.up.copy(up);
const side = new THREE.Vector3(1, 0, 0).cross(up).normalize();
camera.position
  .copy(sphere.center)
  .addScaledVector(side, -2.2 * sphere.radius)
  .addScaledVector(up, 1.2 * sphere.radius);
const controls = new OrbitControls(camera, renderer.domElement);
controls.target.copy(sphere.center);
controls.update();

function render() {
  renderer.render(scene, camera);
}
controls.addEventListener('change', render);
window.addEventListener('resize', () => {
  camera.aspect = window.innerWidth / window.innerHeight;
  camera.updateProjectionMatrix();
  renderer.setSize(window.innerWidth, window.innerHeight);
  render();
});

// ---- picking a hand: the click's ray against the hands' boxes ----
const raycaster = new THREE.Raycaster();
function handAt(clientX, clientY) {
  const rect = renderer.domElement.getBoundingClientRect();
  const ndc = new THREE.Vector2(
    ((clientX - rect.left) / rect.width) * 2 - 1,
    -((clientY - rect.top) / rect.height) * 2 + 1,
  );
  raycaster.setFromCamera(ndc, camera);
  const hits = raycaster.intersectObject(handMesh, false);
  if (hits.length === 0) return -1;
  return Math.floor(handGeometry.index.array[3 * hits[0].faceIndex] / perHand);
}

const panel = buildPanel(document.getElementById('panel'), data, hands, reasonOf, {
  colourCloud: (mode) => {
    colourCloud(mode);
    render();
  },
  colourHands: (mode, reasons) => {
    colourHands(mode, reasons);
    render();
  },
  showHands: (visible) => {
    showHands(visible);
    render();
  },
});

let pressed = null;
renderer.domElement.addEventListener('pointerdown', (e) => {
  pressed = [e.clientX, e.clientY];
});
renderer.domElement.addEventListener('pointerup', (e) => {
  if (!pressed || Math.hypot(e.clientX - pressed[0], e.clientY - pressed[1]) > 4) return;
  picked = handAt(e.clientX, e.clientY);
  colourHands(...handMode);
  render();
  panel.showHand(picked);
});

panel.apply();
render();

// What the browser test and a script can ask of the page.
window.antipodeView = {
  ready: true,
  loadMs: performance.now(),
  points: positions.length / 3,
  hands: hands.length,
  // The hand drawn at a point of the page (CSS pixels), or -1.
  handAt,
  // The page position of hand i's centre, for a test to click it.
  screenPositionOf(i) {
    const centre = new THREE.Vector3().fromArray(hands[i].position_m);
    const approach = new THREE.Vector3(1, 0, 0).applyQuaternion(
      new THREE.Quaternion().fromArray(hands[i].quaternion_xyzw),
    );
    centre.addScaledVector(approach, -0.5 * data.gripper.palm_thickness_m);
    const ndc = centre.project(camera);
    const rect = renderer.domElement.getBoundingClientRect();
    return [rect.left + ((ndc.x + 1) / 2) * rect.width, rect.top + ((1 - ndc.y) / 2) * rect.height];
  },
};
document.body.dataset.ready = 'true';
