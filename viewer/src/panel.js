// The scene panel: what the scene holds, how the cloud and hands are coloured, which hands
// are shown (by rejection reason, object and rank), and the hand last clicked, with the
// hands around it and why each was dropped.

import { categoryColour } from './colours.js';
import { element, factRows, number, recordFacts, vector } from './dom.js';
import { approachOf, neighbours } from './hand_table.js';

/** How far around a clicked hand its neighbours are listed (m). */
export const NEIGHBOUR_RADIUS_M = 0.02;

function select(parent, id, label, options) {
  const row = parent.appendChild(element('label', {}, label + ' '));
  const s = row.appendChild(element('select', { id }));
  for (const [value, text] of options) s.appendChild(element('option', { value }, text));
  return s;
}

// Checkboxes, one per category, each with its count and colour; returns the set of values
// ticked, kept up to date.
function checklist(parent, id, title, values, counts, onChange, ticked = new Set(values)) {
  const box = parent.appendChild(element('fieldset', { id }));
  box.appendChild(element('legend', {}, title));
  values.forEach((value, i) => {
    const row = box.appendChild(element('label', { class: 'check' }));
    const input = row.appendChild(element('input', { type: 'checkbox', 'data-value': value }));
    input.checked = ticked.has(value);
    input.addEventListener('change', () => {
      if (input.checked) ticked.add(value);
      else ticked.delete(value);
      onChange();
    });
    const swatch = row.appendChild(element('span', { class: 'swatch' }));
    swatch.style.background = '#' + categoryColour(i).getHexString();
    row.appendChild(document.createTextNode(` ${value} (${counts.get(value)})`));
  });
  return ticked;
}

function countsOf(values) {
  const counts = new Map();
  for (const v of values) counts.set(v, (counts.get(v) || 0) + 1);
  return counts;
}

export const reasonOf = (hand) => hand.rejection || 'accepted';

/**
 * One [key, value] per fact of hand `index` of `hands` in `scene`: for the grasp the scene's
 * attempt executed, also the attempt's outcome, failure class and the cell's record.
 */
export function handFacts(hands, index, scene) {
  const executed = scene.executed ?? -1;
  const hand = hands[index];
  const facts = [
    ['hand', String(index)],
    ['position_m', vector(hand.position_m)],
    ['quaternion_xyzw', vector(hand.quaternion_xyzw)],
    ['approach', vector(approachOf(hand))],
    ['width_m', number(hand.width_m)],
    ['score', number(hand.score)],
  ];
  if (hand.rank !== undefined) facts.push(['rank', String(hand.rank)]);
  if (hand.object !== undefined) facts.push(['object', String(hand.object)]);
  if (hand.label !== undefined) facts.push(['label', hand.label]);
  facts.push(['rejection', hand.rejection || 'none (accepted)']);
  if (index === executed) {
    facts.push(['executed', 'yes: the grasp the cycle tried']);
    if (scene.attempt) facts.push(['outcome', scene.attempt.outcome], ['failure class', scene.attempt.reason]);
    for (const [key, value] of recordFacts(scene.attempt?.record)) facts.push([key, value]);
  }
  return facts;
}

/**
 * Builds the panel into `root` for the page's title; `draw` holds colourCloud(mode),
 * colourHands(mode, reasons), showHands(visible(hand, i)), showSupport(shown) and
 * armAt(waypoint). Returns {setScene(scene,
 * hands), showHand(i), selectHand(i)}: setScene rebuilds the per-scene part.
 */
export function buildPanel(root, data, draw) {
  root.appendChild(element('h1', {}, data.title || 'antipode view'));
  const summary = root.appendChild(element('p', { id: 'summary' }));
  const cloudMode = select(root, 'cloud-colour', 'cloud colour', [
    ['height', 'height'],
    ['segment', 'object segment'],
    ['view', 'the views that saw it'],
    ['grey', 'grey'],
  ]);
  const supportRow = root.appendChild(element('label', {}, ' the support'));
  const supportShown = supportRow.insertBefore(element('input', { id: 'support', type: 'checkbox' }), supportRow.firstChild);
  supportShown.checked = true;
  const armRow = root.appendChild(element('label', {}, 'arm along its planned path '));
  const armAt = armRow.appendChild(element('input', { id: 'arm-waypoint', type: 'range', min: 0, value: 0 }));
  armAt.addEventListener('input', () => draw.armAt(Number(armAt.value)));
  const handMode = select(root, 'hand-colour', 'hand colour', [
    ['score', 'score'],
    ['reason', 'rejection reason'],
    ['rank', 'selection rank'],
  ]);
  const rankRow = root.appendChild(element('label', {}, 'best hands shown '));
  const best = rankRow.appendChild(element('input', { id: 'best', type: 'number', min: 0 }));
  const filters = root.appendChild(element('div', { id: 'filters' }));
  const handControls = [handMode.parentElement, rankRow, filters];
  const info = root.appendChild(element('table', { id: 'hand-info' }));
  const near = root.appendChild(element('div', { id: 'neighbours' }));
  root.appendChild(element('p', { class: 'hint' }, 'Drag to turn, scroll to zoom, click a hand.'));

  let hands = [];
  let shownScene = {};
  let reasons = [];
  let shownReasons = new Set();
  let shownObjects = null;
  const apply = () => {
    draw.colourHands(handMode.value, reasons);
    const limit = Number(best.value);
    draw.showHands(
      (hand, i) =>
        i < limit &&
        shownReasons.has(reasonOf(hand)) &&
        (!shownObjects || shownObjects.has(String(hand.object ?? 'none'))),
    );
  };
  cloudMode.addEventListener('change', () => draw.colourCloud(cloudMode.value));
  supportShown.addEventListener('change', () => draw.showSupport(supportShown.checked));
  handMode.addEventListener('change', apply);
  best.addEventListener('change', apply);

  function showHand(index) {
    info.replaceChildren();
    near.replaceChildren();
    if (index < 0) return;
    factRows(info, handFacts(hands, index, shownScene));
    const around = neighbours(hands, index, NEIGHBOUR_RADIUS_M);
    near.appendChild(
      element('p', {}, `${around.length} hands within ${NEIGHBOUR_RADIUS_M * 100} cm` + (around.length ? ':' : '')),
    );
    const list = near.appendChild(element('ul'));
    for (const n of around.slice(0, 12))
      list.appendChild(
        element('li', { 'data-hand': n.index }, `hand ${n.index}, ${(n.distance_m * 1000).toFixed(0)} mm: ${n.rejection}`),
      );
  }

  return {
    setScene(scene, sceneHands) {
      hands = sceneHands;
      shownScene = scene;
      const points = scene.cloud ? scene.cloud.count : 0;
      const segments = scene.cloud && scene.cloud.objects !== undefined ? `, ${scene.cloud.objects} object segments` : '';
      summary.textContent =
        `${scene.name}: ${points} points${segments}, ${hands.length} hands, frame ${scene.frame}` +
        (data.gripper.name ? `, ${data.gripper.name}` : '') +
        (scene.objects ? `, ${scene.objects.length} objects` : '');
      best.value = hands.length;
      best.max = hands.length;
      filters.replaceChildren();
      const waypoints = scene.path ? scene.path.waypoints.length : 0;
      armRow.hidden = waypoints === 0;
      armAt.max = Math.max(waypoints - 1, 0);
      armAt.value = armAt.max;
      handControls.forEach((e) => (e.hidden = hands.length === 0));
      const reasonCounts = countsOf(hands.map(reasonOf));
      reasons = [...reasonCounts.keys()];
      // The accepted hands first; the dropped ones a tick away.
      const first = new Set(reasonCounts.has('accepted') ? ['accepted'] : reasons);
      shownReasons = checklist(filters, 'reasons', 'hands by rejection reason', reasons, reasonCounts, apply, first);
      shownObjects = null;
      if (hands.some((h) => h.object !== undefined)) {
        const objectCounts = countsOf(hands.map((h) => String(h.object ?? 'none')));
        shownObjects = checklist(filters, 'objects', 'hands by object', [...objectCounts.keys()], objectCounts, apply);
      }
      showHand(-1);
      cloudMode.querySelector('option[value="view"]').disabled = !(scene.cloud && scene.cloud.views);
      if (cloudMode.value === 'view' && !(scene.cloud && scene.cloud.views)) cloudMode.value = 'height';
      draw.colourCloud(cloudMode.value);
      draw.showSupport(supportShown.checked);
      apply();
    },
    showHand,
    recolour: apply,
  };
}
