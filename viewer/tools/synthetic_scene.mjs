// A seeded synthetic scene for the viewer's test and benchmark: a binary PLY cloud of a table
// with five spheres, and a grasps file of hands on a grid above it.
import { writeFileSync } from 'node:fs';

// A seeded stream (mulberry32), so the scene is the same every run.
let seed = 12345;
function random() {
  seed = (seed + 0x6d2b79f5) | 0;
  let t = Math.imul(seed ^ (seed >>> 15), 1 | seed);
  t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
  return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
}

// A binary PLY of `count` points on a 1 m table (z = 0) and five spheres on it.
export function writeCloud(path, count) {
  const header = `ply\nformat binary_little_endian 1.0\nelement vertex ${count}\nproperty float x\nproperty float y\nproperty float z\nend_header\n`;
  const body = Buffer.alloc(12 * count);
  for (let i = 0; i < count; i++) {
    let p;
    if (i % 2 === 0) {
      p = [random() - 0.5, random() - 0.5, 0];
    } else {
      const k = i % 5;
      const [u, v] = [2 * Math.PI * random(), Math.acos(2 * random() - 1)];
      p = [-0.3 + 0.15 * k + 0.04 * Math.cos(u) * Math.sin(v), 0.04 * Math.sin(u) * Math.sin(v), 0.04 + 0.04 * Math.cos(v)];
    }
    p.forEach((x, j) => body.writeFloatLE(x, 12 * i + 4 * j));
  }
  writeFileSync(path, Buffer.concat([Buffer.from(header), body]));
}

// `count` hands over the table on a grid 1 cm apart, approaching from above at random angles
// about the vertical; object k is the grid's column modulo 5.
export function writeGrasps(path, count) {
  const reasons = [undefined, 'in collision', 'not antipodal', 'empty closing region'];
  const hands = [];
  for (let i = 0; i < count; i++) {
    const [row, column] = [Math.floor(i / 100), i % 100];
    const k = column % 5;
    const angle = 2 * Math.PI * random();
    // Approach -z (x axis of the hand) and closing along (cos, sin, 0): q rotates x to -z.
    const half = angle / 2;
    const qz = [0, 0, Math.sin(half), Math.cos(half)]; // about z
    const qy = [0, Math.sin(Math.PI / 4), 0, Math.cos(Math.PI / 4)]; // x -> -z
    const q = [
      qz[3] * qy[0] + qz[0] * qy[3] + qz[1] * qy[2] - qz[2] * qy[1],
      qz[3] * qy[1] - qz[0] * qy[2] + qz[1] * qy[3] + qz[2] * qy[0],
      qz[3] * qy[2] + qz[0] * qy[1] - qz[1] * qy[0] + qz[2] * qy[3],
      qz[3] * qy[3] - qz[0] * qy[0] - qz[1] * qy[1] - qz[2] * qy[2],
    ];
    const hand = {
      position_m: [-0.5 + 0.01 * column, -0.25 + 0.01 * row, 0.1 + 0.05 * random()],
      quaternion_xyzw: q,
      width_m: 0.03 + 0.04 * random(),
      score: 10 * random(),
      object: k,
      rank: i + 1,
    };
    const reason = reasons[i % reasons.length];
    if (reason) hand.rejection = reason;
    hands.push(hand);
  }
  writeFileSync(path, JSON.stringify({ count, frame: 'base', hands }));
  return hands;
}
