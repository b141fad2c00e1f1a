// What the 3D view draws of one scene: its cloud (coloured by height, by the views that saw
// each point, by object segment or grey), the support's extent, the table and box of its scene file, the arm's planned path, its hands (fingers and palm at the gripper's real size, in one mesh)
// and markers where its objects lie. Built when the scene is shown, disposed when another is.

import * as THREE from 'three';

import { decodeFloat32, decodeInt16, decodeUint32 } from './base64.js';
import { handMatrices } from './hand_geometry.js';
import { categoryColour, scoreColour } from './colours.js';

const EXECUTED = new THREE.Color(0.95, 0.1, 0.75);
const PICKED = new THREE.Color(0.9, 0.1, 0.1);
const UNRANKED = new THREE.Color(0.75, 0.75, 0.75);

function cloudLayer(cloud, up) {
  const positions = cloud ? decodeFloat32(cloud.points) : new Float32Array(0);
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  const colours = new Float32Array(positions.length);
  geometry.setAttribute('color', new THREE.BufferAttribute(colours, 3));
  geometry.computeBoundingSphere();
  const points = new THREE.Points(
    geometry,
    new THREE.PointsMaterial({ size: 2, sizeAttenuation: false, vertexColors: true }),
  );
  const segments = cloud && cloud.segments ? decodeInt16(cloud.segments) : null;
  const views = cloud && cloud.views ? decodeUint32(cloud.views) : null;
  const count = positions.length / 3;
  const height = (i) =>
    positions[3 * i] * up.x + positions[3 * i + 1] * up.y + positions[3 * i + 2] * up.z;
  function colour(mode) {
    let lo = Infinity;
    let hi = -Infinity;
    for (let i = 0; mode === 'height' && i < count; i++) {
      lo = Math.min(lo, height(i));
      hi = Math.max(hi, height(i));
    }
    const c = new THREE.Color();
    for (let i = 0; i < count; i++) {
      if (mode === 'height') c.copy(scoreColour((height(i) - lo) / Math.max(hi - lo, 1e-9)));
      else if (mode === 'view' && views) c.copy(categoryColour(views[i] - 1)); // 1, 2, both: 3
      else if (mode === 'segment' && segments)
        segments[i] >= 0 ? c.copy(categoryColour(segments[i])) : c.setRGB(...(segments[i] === -1 ? [0.8, 0.8, 0.8] : [0.35, 0.35, 0.35]));
      else c.setRGB(0.45, 0.45, 0.45);
      c.toArray(colours, 3 * i);
    }
    geometry.attributes.color.needsUpdate = true;
  }
  return { points, count, colour, segments, views };
}

// One merged geometry, not instances: software renderers (a headless browser's SwiftShader)
// draw a 5,000-hand page in a second this way, and minutes with instancing.
function handLayer(hands, gripper) {
  const box = new THREE.BoxGeometry(1, 1, 1).toNonIndexed();
  const perHand = 3 * box.attributes.position.count; // vertices of a hand's three boxes
  const geometry = new THREE.BufferGeometry();
  const positions = new Float32Array(3 * perHand * hands.length);
  const normals = new Float32Array(3 * perHand * hands.length);
  const colours = new Float32Array(3 * perHand * hands.length);
  const v = new THREE.Vector3();
  const normal = new THREE.Matrix3();
  let at = 0;
  for (const hand of hands) {
    for (const matrix of handMatrices(hand, gripper)) {
      normal.getNormalMatrix(matrix);
      for (let k = 0; k < box.attributes.position.count; k++, at += 3) {
        v.fromBufferAttribute(box.attributes.position, k).applyMatrix4(matrix).toArray(positions, at);
        v.fromBufferAttribute(box.attributes.normal, k).applyMatrix3(normal).normalize().toArray(normals, at);
      }
    }
  }
  geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  geometry.setAttribute('normal', new THREE.BufferAttribute(normals, 3));
  geometry.setAttribute('color', new THREE.BufferAttribute(colours, 3));
  geometry.setIndex(new THREE.BufferAttribute(new Uint32Array(0), 1));
  const mesh = new THREE.Mesh(geometry, new THREE.MeshLambertMaterial({ vertexColors: true }));
  return { mesh, geometry, colours, perHand };
}

// The support's extent, a translucent quad (its four corners in order).
function supportQuad(corners) {
  const group = new THREE.Group();
  if (!corners) return group;
  const geometry = new THREE.BufferGeometry();
  const [a, b, c, d] = corners;
  geometry.setAttribute('position', new THREE.Float32BufferAttribute([...a, ...b, ...c, ...a, ...c, ...d], 3));
  group.add(
    new THREE.Mesh(
      geometry,
      new THREE.MeshBasicMaterial({ color: 0x4a90d9, transparent: true, opacity: 0.15, side: THREE.DoubleSide, depthWrite: false }),
    ),
  );
  const outline = new THREE.BufferGeometry().setFromPoints([a, b, c, d, a].map((p) => new THREE.Vector3(...p)));
  group.add(new THREE.Line(outline, new THREE.LineBasicMaterial({ color: 0x4a90d9 })));
  return group;
}

// A scene file's table top (its outline) and box (the edges of its inside), base frame.
function fixtureLines(fixtures) {
  const group = new THREE.Group();
  if (!fixtures) return group;
  const material = new THREE.LineBasicMaterial({ color: 0x8a6d3b });
  const edges = (size, centre) => {
    const lines = new THREE.LineSegments(new THREE.EdgesGeometry(new THREE.BoxGeometry(...size)), material);
    lines.position.set(...centre);
    return lines;
  };
  const { table, box } = fixtures;
  if (table) group.add(edges([table.size_m[0], table.size_m[1], 0], [table.center_m[0], table.center_m[1], table.top_z_m]));
  if (box)
    group.add(
      edges(
        [box.inner_size_m[0], box.inner_size_m[1], box.wall_height_m],
        [box.center_m[0], box.center_m[1], box.floor_z_m + box.wall_height_m / 2],
      ),
    );
  return group;
}

// The arm along its planned path: the path of its tip, and the arm itself (a line through its
// links' origins) at a chosen waypoint.
function armLayer(path) {
  const group = new THREE.Group();
  if (!path || path.waypoints.length === 0) return { group, at() {} };
  const tip = path.waypoints.map((links) => new THREE.Vector3(...links[links.length - 1]));
  const tipPath = new THREE.Line(
    new THREE.BufferGeometry().setFromPoints(tip),
    new THREE.LineDashedMaterial({ color: 0x555555, dashSize: 0.01, gapSize: 0.01 }),
  );
  tipPath.computeLineDistances(); // dashes are laid out along the line's length
  group.add(tipPath);
  const arm = new THREE.Line(new THREE.BufferGeometry(), new THREE.LineBasicMaterial({ color: 0xd62728, linewidth: 3 }));
  group.add(arm);
  const at = (k) => {
    const links = path.waypoints[Math.min(Math.max(k, 0), path.waypoints.length - 1)];
    arm.geometry.dispose();
    arm.geometry = new THREE.BufferGeometry().setFromPoints(links.map((p) => new THREE.Vector3(...p)));
  };
  at(path.waypoints.length - 1);
  return { group, at };
}

function objectMarkers(objects) {
  const group = new THREE.Group();
  const shape = new THREE.OctahedronGeometry(0.008);
  (objects || []).forEach((object, i) => {
    const marker = new THREE.Mesh(shape, new THREE.MeshLambertMaterial({ color: categoryColour(i) }));
    marker.position.fromArray(object.position_m);
    group.add(marker);
  });
  return group;
}

/**
 * The layers of `scene` (its cloud, `hands` decoded from it, objects), added to `world`.
 * Returns {cloud, colourCloud(mode), colourHands(mode, reasons, picked), showHands(visible),
 * handAt(raycaster), armAt(waypoint), showSupport(shown), dispose()}.
 */
export function buildLayers(world, scene, hands, gripper, up) {
  const cloud = cloudLayer(scene.cloud, up);
  const handsDrawn = handLayer(hands, gripper);
  const markers = objectMarkers(scene.objects);
  const support = supportQuad(scene.support);
  const fixtures = fixtureLines(scene.fixtures);
  const arm = armLayer(scene.path);
  world.add(cloud.points, handsDrawn.mesh, markers, support, fixtures, arm.group);
  const scores = hands.map((h) => (typeof h.score === 'number' ? h.score : 0));
  const scoreLo = Math.min(...scores, 0);
  const scoreHi = Math.max(...scores, 1e-9);
  const ranks = hands.map((h) => h.rank || 0);
  const lastRank = Math.max(...ranks, 1);
  const executed = scene.executed ?? -1;
  return {
    cloud,
    colourCloud: cloud.colour,
    colourHands(mode, reasons, picked) {
      const c = new THREE.Color();
      hands.forEach((hand, i) => {
        if (mode === 'reason') c.copy(categoryColour(reasons.indexOf(hand.rejection || 'accepted')));
        else if (mode === 'rank')
          c.copy(ranks[i] > 0 ? scoreColour(1 - (ranks[i] - 1) / Math.max(lastRank - 1, 1)) : UNRANKED);
        else c.copy(scoreColour((scores[i] - scoreLo) / Math.max(scoreHi - scoreLo, 1e-9)));
        if (i === executed) c.copy(EXECUTED);
        if (i === picked) c.copy(PICKED);
        for (let k = i * handsDrawn.perHand; k < (i + 1) * handsDrawn.perHand; k++)
          c.toArray(handsDrawn.colours, 3 * k);
      });
      handsDrawn.geometry.attributes.color.needsUpdate = true;
    },
    // Draws only the hands `visible` keeps (and always the executed one).
    showHands(visible) {
      const kept = [];
      hands.forEach((hand, i) => {
        if (i === executed || visible(hand, i)) kept.push(i);
      });
      const { perHand } = handsDrawn;
      const index = new Uint32Array(kept.length * perHand);
      kept.forEach((i, n) => {
        for (let k = 0; k < perHand; k++) index[n * perHand + k] = i * perHand + k;
      });
      handsDrawn.geometry.setIndex(new THREE.BufferAttribute(index, 1));
      handsDrawn.geometry.computeBoundingSphere();
    },
    armAt: arm.at,
    showSupport(shown) {
      support.visible = shown;
    },
    handAt(raycaster) {
      const hits = raycaster.intersectObject(handsDrawn.mesh, false);
      if (hits.length === 0) return -1;
      return Math.floor(handsDrawn.geometry.index.array[3 * hits[0].faceIndex] / handsDrawn.perHand);
    },
    dispose() {
      world.remove(cloud.points, handsDrawn.mesh, markers, support, fixtures, arm.group);
      cloud.points.geometry.dispose();
      handsDrawn.geometry.dispose();
    },
  };
}
