// Colours: a perceptual ramp for scores and heights (low: dark blue, high: yellow) and a
// palette for categories (rejection reasons, objects).

import * as THREE from 'three';

const RAMP = [
  [0.267, 0.005, 0.329],
  [0.229, 0.322, 0.546],
  [0.128, 0.567, 0.551],
  [0.369, 0.789, 0.383],
  [0.993, 0.906, 0.144],
];

/** The ramp's colour at t in [0, 1] (clamped). */
export function scoreColour(t) {
  const x = Math.min(Math.max(t, 0), 1) * (RAMP.length - 1);
  const i = Math.min(Math.floor(x), RAMP.length - 2);
  const f = x - i;
  const [a, b] = [RAMP[i], RAMP[i + 1]];
  return new THREE.Color(a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2]));
}

const PALETTE = [
  0x1f77b4, 0xff7f0e, 0x2ca02c, 0xd62728, 0x9467bd, 0x8c564b, 0xe377c2, 0x7f7f7f, 0xbcbd22,
  0x17becf,
];

/** Category i's colour (the palette repeats after ten). */
export function categoryColour(i) {
  return new THREE.Color(PALETTE[((i % PALETTE.length) + PALETTE.length) % PALETTE.length]);
}
